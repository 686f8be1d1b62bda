#include "kernel/collision/continuous_collision.h"

#include <fmt/format.h>
#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

namespace mechanist {
namespace {

// Polynomials in t, lowest power first: with integer coefficients (built from the inputs
// scaled to integers) or rational ones (gcds and square-free parts).
using IPoly = std::vector<mpz_class>;
using Poly = std::vector<mpq_class>;
using Vec = std::array<IPoly, 3>;

template <typename T>
std::vector<T> Add(const std::vector<T>& x, const std::vector<T>& y, int sign = 1) {
  std::vector<T> r(std::max(x.size(), y.size()), T(0));
  for (std::size_t i = 0; i < x.size(); ++i) r[i] += x[i];
  for (std::size_t i = 0; i < y.size(); ++i) r[i] += sign * y[i];
  return r;
}

template <typename T>
std::vector<T> Mul(const std::vector<T>& x, const std::vector<T>& y) {
  std::vector<T> r(x.size() + y.size() - 1, T(0));
  for (std::size_t i = 0; i < x.size(); ++i) {
    for (std::size_t j = 0; j < y.size(); ++j) r[i + j] += x[i] * y[j];
  }
  return r;
}

// The power of two that makes every coordinate an integer: each double is an integer
// mantissa times a power of two, and scaling all by one positive factor changes no sign or
// root of the homogeneous conditions below.
int IntegerScale(std::initializer_list<const Eigen::Vector3d*> points) {
  int scale = 0;
  for (const Eigen::Vector3d* q : points) {
    for (int k = 0; k < 3; ++k) {
      if ((*q)[k] == 0.0) continue;
      int exponent = 0;
      std::frexp((*q)[k], &exponent);
      scale = std::max(scale, 53 - exponent);
    }
  }
  return scale;
}

mpz_class Scaled(double x, int scale) {
  if (x == 0.0) return 0;
  int exponent = 0;
  const double mantissa = std::frexp(x, &exponent);  // x = mantissa 2^exponent, |m| in [0.5, 1)
  mpz_class m(std::ldexp(mantissa, 53));             // exact: 53-bit integer
  const int shift = exponent - 53 + scale;
  if (shift < 0) throw std::logic_error("IntegerScale: a coordinate is not an integer");
  return m << shift;
}

// The linear motion from q0 (t = 0) to q1 (t = 1), in integers scaled by 2^scale.
Vec Moving(const Eigen::Vector3d& q0, const Eigen::Vector3d& q1, int scale) {
  Vec v;
  for (int k = 0; k < 3; ++k) {
    const mpz_class x0 = Scaled(q0[k], scale), x1 = Scaled(q1[k], scale);
    v[k] = {x0, x1 - x0};
  }
  return v;
}

Vec Sub(const Vec& x, const Vec& y) {
  return {Add(x[0], y[0], -1), Add(x[1], y[1], -1), Add(x[2], y[2], -1)};
}

Vec Cross(const Vec& x, const Vec& y) {
  return {Add(Mul(x[1], y[2]), Mul(x[2], y[1]), -1), Add(Mul(x[2], y[0]), Mul(x[0], y[2]), -1),
          Add(Mul(x[0], y[1]), Mul(x[1], y[0]), -1)};
}

IPoly Dot(const Vec& x, const Vec& y) {
  return Add(Add(Mul(x[0], y[0]), Mul(x[1], y[1])), Mul(x[2], y[2]));
}

Poly Rational(const IPoly& p) { return Poly(p.begin(), p.end()); }

// Without leading zero coefficients (the zero polynomial becomes empty).
template <typename T>
std::vector<T> Trim(std::vector<T> p) {
  while (!p.empty() && sgn(p.back()) == 0) p.pop_back();
  return p;
}

Poly Derivative(const Poly& p) {
  Poly d;
  for (std::size_t i = 1; i < p.size(); ++i) d.push_back(p[i] * static_cast<long>(i));
  return Trim(d);
}

// Quotient and remainder of x / y (y not zero).
void Divide(Poly x, const Poly& y, Poly* quotient, Poly* remainder) {
  x = Trim(x);
  Poly q(x.size() >= y.size() ? x.size() - y.size() + 1 : 0, mpq_class(0));
  while (x.size() >= y.size() && !x.empty()) {
    const std::size_t shift = x.size() - y.size();
    const mpq_class factor = x.back() / y.back();
    q[shift] = factor;
    for (std::size_t i = 0; i < y.size(); ++i) x[i + shift] -= factor * y[i];
    x.pop_back();
    x = Trim(x);
  }
  *quotient = q;
  *remainder = x;
}

// Monic greatest common divisor (Euclid over the rationals; degrees here are at most 4).
Poly Gcd(Poly x, Poly y) {
  x = Trim(x);
  y = Trim(y);
  while (!y.empty()) {
    Poly q, r;
    Divide(x, y, &q, &r);
    x = y;
    y = r;
  }
  if (!x.empty()) {
    const mpq_class lead = x.back();
    for (mpq_class& a : x) a /= lead;
  }
  return x;
}

// Bernstein coefficients on an interval, as integers times one positive factor that is not
// kept: only their signs and ratios matter, and integers subdivide without any gcd.
using Coeffs = std::vector<mpz_class>;

// Bernstein coefficients of p on [0, 1], b_i = sum_{k <= i} C(i, k) / C(n, k) a_k, scaled to
// integers by the common denominator.
Coeffs Bernstein(Poly p) {
  if (p.empty()) p.push_back(mpq_class(0));
  const std::size_t n = p.size() - 1;
  std::vector<std::vector<mpz_class>> choose(n + 1, std::vector<mpz_class>(n + 1, 0));
  for (std::size_t i = 0; i <= n; ++i) {
    choose[i][0] = 1;
    for (std::size_t k = 1; k <= i; ++k) choose[i][k] = choose[i - 1][k - 1] + choose[i - 1][k];
  }
  Poly b(n + 1, mpq_class(0));
  mpz_class denominator = 1;
  for (std::size_t i = 0; i <= n; ++i) {
    for (std::size_t k = 0; k <= i; ++k) {
      b[i] += mpq_class(choose[i][k], choose[n][k]) * p[k];
    }
    b[i].canonicalize();
    mpz_lcm(denominator.get_mpz_t(), denominator.get_mpz_t(), b[i].get_den_mpz_t());
  }
  Coeffs out(n + 1);
  for (std::size_t i = 0; i <= n; ++i) out[i] = b[i].get_num() * (denominator / b[i].get_den());
  return out;
}

// Bernstein coefficients of an integer polynomial, times lcm_k C(n, k).
Coeffs Bernstein(IPoly p) {
  if (p.empty()) p.push_back(mpz_class(0));
  const std::size_t n = p.size() - 1;
  std::vector<std::vector<mpz_class>> choose(n + 1, std::vector<mpz_class>(n + 1, 0));
  for (std::size_t i = 0; i <= n; ++i) {
    choose[i][0] = 1;
    for (std::size_t k = 1; k <= i; ++k) choose[i][k] = choose[i - 1][k - 1] + choose[i - 1][k];
  }
  mpz_class lcm = 1;
  for (std::size_t k = 0; k <= n; ++k)
    mpz_lcm(lcm.get_mpz_t(), lcm.get_mpz_t(), choose[n][k].get_mpz_t());
  Coeffs b(n + 1, mpz_class(0));
  for (std::size_t i = 0; i <= n; ++i) {
    for (std::size_t k = 0; k <= i; ++k) b[i] += choose[i][k] * (lcm / choose[n][k]) * p[k];
  }
  return b;
}

// de Casteljau at the midpoint without division: at level k the running values are 2^k times
// the true ones, so the halves' coefficient k is scaled by 2^(n - k) to share the factor 2^n.
void Split(const Coeffs& b, Coeffs* left, Coeffs* right) {
  Coeffs work = b;
  const std::size_t n = b.size();
  left->resize(n);
  right->resize(n);
  for (std::size_t level = 0; level < n; ++level) {
    (*left)[level] = work[0] << (n - 1 - level);
    (*right)[n - 1 - level] = work[n - 1 - level] << (n - 1 - level);
    for (std::size_t i = 0; i + 1 < n - level; ++i) work[i] += work[i + 1];
  }
}

bool AllPositive(const Coeffs& b) {
  for (const mpz_class& c : b) {
    if (sgn(c) <= 0) return false;
  }
  return true;
}
bool AllNegative(const Coeffs& b) {
  for (const mpz_class& c : b) {
    if (sgn(c) >= 0) return false;
  }
  return true;
}
bool AllNonNegative(const Coeffs& b) {
  for (const mpz_class& c : b) {
    if (sgn(c) < 0) return false;
  }
  return true;
}

// Sign variations of Bernstein coefficients, zeros skipped: an upper bound on the number of
// roots in the open interval with the same parity (Descartes' rule in Bernstein form).
int Variations(const Coeffs& b) {
  int count = 0, last = 0;
  for (const mpz_class& x : b) {
    const int s = sgn(x);
    if (s == 0) continue;
    if (last != 0 && s != last) ++count;
    last = s;
  }
  return count;
}

// How much deeper than the search's bisection an isolated root is refined (only one branch).
constexpr int kRootDepthFactor = 20;

// The Bernstein forms of everything the search subdivides together.
struct Forms {
  Coeffs f;                    // the contact polynomial, square-free
  std::vector<Coeffs> g;       // the conditions, >= 0 at a contact
  std::vector<Coeffs> common;  // per condition, gcd(f, g): its roots are roots of f where g = 0
};

Forms SplitForms(const Forms& x, bool right) {
  Forms out;
  Coeffs l, r;
  Split(x.f, &l, &r);
  out.f = right ? r : l;
  for (const Coeffs& p : x.g) {
    Split(p, &l, &r);
    out.g.push_back(right ? r : l);
  }
  for (const Coeffs& p : x.common) {
    Split(p, &l, &r);
    out.common.push_back(right ? r : l);
  }
  return out;
}

Poly SquareFree(const Poly& p) {
  const Poly repeated = Gcd(p, Derivative(p));
  if (repeated.size() <= 1) return p;
  Poly quotient, remainder;
  Divide(p, repeated, &quotient, &remainder);
  return quotient;
}

// At the single root t* of the square-free `root` (Bernstein form on the interval, one sign
// change) are all `g` >= 0? `common[j]`: Bernstein form of gcd(root, g_j) (or 1). Refines the
// interval around t* until every condition's sign there is known.
CcdAnswer AtRoot(Coeffs root, std::vector<Coeffs> g, std::vector<Coeffs> common, int depth,
                 int max_depth) {
  for (;; ++depth) {
    bool undecided = false;
    for (std::size_t j = 0; j < g.size(); ++j) {
      if (AllNonNegative(g[j])) continue;
      if (AllNegative(g[j])) return CcdAnswer::kApart;
      // gcd(root, g_j) vanishing in the interval means g_j(t*) = 0.
      if (common[j].size() > 1 && sgn(common[j].front()) * sgn(common[j].back()) <= 0) continue;
      undecided = true;
    }
    if (!undecided) return CcdAnswer::kContact;
    if (depth >= max_depth) return CcdAnswer::kMaybe;
    Coeffs l, r;
    Split(root, &l, &r);
    const bool right = sgn(l.back()) != 0 && sgn(l.front()) * sgn(l.back()) > 0;
    if (sgn(l.back()) == 0) {
      // t* is the midpoint, exactly: the values there decide.
      bool inside = true;
      for (const Coeffs& x : g) {
        Coeffs xl, xr;
        Split(x, &xl, &xr);
        inside = inside && sgn(xl.back()) >= 0;
      }
      return inside ? CcdAnswer::kContact : CcdAnswer::kApart;
    }
    root = right ? r : l;
    for (Coeffs& x : g) {
      Coeffs xl, xr;
      Split(x, &xl, &xr);
      x = right ? xr : xl;
    }
    for (Coeffs& x : common) {
      Coeffs xl, xr;
      Split(x, &xl, &xr);
      x = right ? xr : xl;
    }
  }
}

// Is there a t in the interval with f(t) = 0 and every g(t) >= 0? `coplanar`: f vanishes
// identically. `has_common[i]`: gcd(f, g_i) has positive degree. Bisection stops at
// `max_depth`; an isolated root of f is followed alone down to `root_depth`.
CcdAnswer Search(const Forms& x, const std::vector<bool>& has_common, bool coplanar, int depth,
                 int max_depth, int root_depth) {
  const Coeffs& f = x.f;
  if (!coplanar && (AllPositive(f) || AllNegative(f))) return CcdAnswer::kApart;
  for (const Coeffs& c : x.g) {
    if (AllNegative(c)) return CcdAnswer::kApart;
  }
  // Exact roots at the ends of the interval (the first and last coefficients are the values
  // there): common in data whose contacts happen at t = 0 or 1.
  for (const bool at_end : {false, true}) {
    const auto value = [&](const Coeffs& b) -> const mpz_class& {
      return at_end ? b.back() : b.front();
    };
    if (!coplanar && sgn(value(f)) != 0) continue;
    bool inside = true;
    for (const Coeffs& c : x.g) inside = inside && sgn(value(c)) >= 0;
    if (inside) return CcdAnswer::kContact;
  }
  if (coplanar) {
    bool inside_throughout = true;
    for (const Coeffs& c : x.g) inside_throughout = inside_throughout && AllNonNegative(c);
    if (inside_throughout) return CcdAnswer::kContact;
  } else if (Variations(f) == 1 && sgn(f.front()) * sgn(f.back()) < 0) {
    // Exactly one root t* of f inside: follow it alone, as deep as its conditions need (a
    // condition's root may lie within 1e-12 of t* without being t*).
    return AtRoot(f, x.g, x.common, depth, root_depth);
  }
  if (depth >= max_depth) return CcdAnswer::kMaybe;
  const CcdAnswer left =
      Search(SplitForms(x, false), has_common, coplanar, depth + 1, max_depth, root_depth);
  if (left == CcdAnswer::kContact) return left;
  const CcdAnswer right =
      Search(SplitForms(x, true), has_common, coplanar, depth + 1, max_depth, root_depth);
  if (right == CcdAnswer::kContact) return right;
  return left == CcdAnswer::kMaybe || right == CcdAnswer::kMaybe ? CcdAnswer::kMaybe
                                                                 : CcdAnswer::kApart;
}

// Coplanar throughout: is there a t in [0, 1] with every g(t) >= 0? The set where they all
// hold is a union of closed intervals, each starting at 0 or at a root of some g_k: the ends
// are tested exactly, then every root of every g_k in [0, 1], each isolated by Bernstein
// subdivision (one sign change of its square-free part) and decided by AtRoot.
CcdAnswer Coplanar(const std::vector<Poly>& conditions, const CcdOptions& options) {
  std::vector<Coeffs> g;
  for (const Poly& x : conditions) g.push_back(Bernstein(Trim(x)));
  for (const bool at_end : {false, true}) {
    bool inside = true;
    for (const Coeffs& x : g) inside = inside && sgn(at_end ? x.back() : x.front()) >= 0;
    if (inside) return CcdAnswer::kContact;
  }
  bool maybe = false;
  for (std::size_t k = 0; k < conditions.size(); ++k) {
    const Poly gk = Trim(conditions[k]);
    if (gk.size() <= 1) continue;  // constant: no root
    const Poly sf = SquareFree(gk);
    std::vector<Coeffs> common;
    for (const Poly& x : conditions) {
      const Poly h = Gcd(sf, Trim(x));
      common.push_back(Bernstein(h.size() > 1 ? h : Poly{mpq_class(1)}));
    }
    // Isolate the roots of sf in [0, 1] (the ends are done).
    struct Piece {
      Coeffs root;
      std::vector<Coeffs> g, common;
      int depth;
    };
    std::vector<Piece> stack = {{Bernstein(sf), g, common, 0}};
    while (!stack.empty()) {
      Piece piece = std::move(stack.back());
      stack.pop_back();
      const int variations = Variations(piece.root);
      if (variations == 0) continue;
      if (variations == 1 && sgn(piece.root.front()) * sgn(piece.root.back()) < 0) {
        const CcdAnswer a = AtRoot(piece.root, piece.g, piece.common, piece.depth,
                                   kRootDepthFactor * options.max_depth);
        if (a == CcdAnswer::kContact) return a;
        maybe = maybe || a == CcdAnswer::kMaybe;
        continue;
      }
      if (piece.depth >= options.max_depth) {
        maybe = true;
        continue;
      }
      Piece halves[2];
      for (int side = 0; side < 2; ++side) halves[side].depth = piece.depth + 1;
      Split(piece.root, &halves[0].root, &halves[1].root);
      for (const auto* list : {&piece.g, &piece.common}) {
        for (const Coeffs& x : *list) {
          Coeffs xl, xr;
          Split(x, &xl, &xr);
          (list == &piece.g ? halves[0].g : halves[0].common).push_back(xl);
          (list == &piece.g ? halves[1].g : halves[1].common).push_back(xr);
        }
      }
      // A root exactly at the midpoint: decide it there.
      if (sgn(halves[0].root.back()) == 0) {
        bool inside = true;
        for (const Coeffs& x : halves[0].g) inside = inside && sgn(x.back()) >= 0;
        if (inside) return CcdAnswer::kContact;
      }
      stack.push_back(std::move(halves[1]));
      stack.push_back(std::move(halves[0]));
    }
  }
  return maybe ? CcdAnswer::kMaybe : CcdAnswer::kApart;
}

CcdAnswer Decide(const IPoly& contact, const std::vector<IPoly>& conditions,
                 const CcdOptions& options) {
  const IPoly trimmed = Trim(contact);
  if (trimmed.empty()) {
    std::vector<Poly> rational;
    for (const IPoly& x : conditions) rational.push_back(Rational(x));
    return Coplanar(rational, options);
  }
  // First as given, without gcds: almost every query ends here.
  Forms forms;
  forms.f = Bernstein(trimmed);
  for (const IPoly& x : conditions) {
    forms.g.push_back(Bernstein(x));
    forms.common.push_back(Bernstein(IPoly{mpz_class(1)}));
  }
  const CcdAnswer first = Search(forms, std::vector<bool>(conditions.size(), false), false, 0,
                                 options.max_depth, 2 * options.max_depth);
  if (first != CcdAnswer::kMaybe) return first;
  // Undecided: a repeated root of f (no sign change) or a condition vanishing at the contact.
  // The square-free part has the same roots, all simple; gcd(f, g_i) finds where g_i = 0.
  const Poly square_free = SquareFree(Rational(trimmed));
  forms.f = Bernstein(square_free);
  std::vector<bool> has_common;
  forms.common.clear();
  for (const IPoly& x : conditions) {
    const Poly h = Gcd(square_free, Rational(x));
    has_common.push_back(h.size() > 1);
    forms.common.push_back(Bernstein(h.size() > 1 ? h : Poly{mpq_class(1)}));
  }
  return Search(forms, has_common, false, 0, options.max_depth,
                kRootDepthFactor * options.max_depth);
}

}  // namespace

CcdAnswer VertexFaceCcd(const Eigen::Vector3d& p0, const Eigen::Vector3d& a0,
                        const Eigen::Vector3d& b0, const Eigen::Vector3d& c0,
                        const Eigen::Vector3d& p1, const Eigen::Vector3d& a1,
                        const Eigen::Vector3d& b1, const Eigen::Vector3d& c1,
                        const CcdOptions& options) {
  const int s = IntegerScale({&p0, &a0, &b0, &c0, &p1, &a1, &b1, &c1});
  const Vec p = Moving(p0, p1, s), a = Moving(a0, a1, s), b = Moving(b0, b1, s),
            c = Moving(c0, c1, s);
  const Vec ab = Sub(b, a), bc = Sub(c, b), ca = Sub(a, c);
  const Vec n = Cross(ab, Sub(c, a));
  const IPoly f = Dot(n, Sub(p, a));
  return Decide(
      f, {Dot(Cross(ab, Sub(p, a)), n), Dot(Cross(bc, Sub(p, b)), n), Dot(Cross(ca, Sub(p, c)), n)},
      options);
}

CcdAnswer EdgeEdgeCcd(const Eigen::Vector3d& a0, const Eigen::Vector3d& b0,
                      const Eigen::Vector3d& c0, const Eigen::Vector3d& d0,
                      const Eigen::Vector3d& a1, const Eigen::Vector3d& b1,
                      const Eigen::Vector3d& c1, const Eigen::Vector3d& d1,
                      const CcdOptions& options) {
  const int s = IntegerScale({&a0, &b0, &c0, &d0, &a1, &b1, &c1, &d1});
  const Vec a = Moving(a0, a1, s), b = Moving(b0, b1, s), c = Moving(c0, c1, s),
            d = Moving(d0, d1, s);
  const Vec ab = Sub(b, a), cd = Sub(d, c);
  const Vec x_c = Cross(ab, Sub(c, a)), x_d = Cross(ab, Sub(d, a));
  const Vec y_a = Cross(cd, Sub(a, c)), y_b = Cross(cd, Sub(b, c));
  const IPoly f = Dot(x_c, Sub(d, a));
  IPoly g1 = Dot(x_c, x_d), g2 = Dot(y_a, y_b);
  for (mpz_class& x : g1) x = -x;
  for (mpz_class& x : g2) x = -x;
  return Decide(f, {g1, g2}, options);
}

double ExactRationalToDouble(std::string_view numerator, std::string_view denominator) {
  mpq_class q;
  try {
    q = mpq_class(mpz_class(std::string(numerator)), mpz_class(std::string(denominator)));
  } catch (const std::invalid_argument&) {
    throw std::invalid_argument(
        fmt::format("expected an integer pair, found \"{}/{}\"", numerator, denominator));
  }
  if (sgn(q.get_den()) == 0) throw std::invalid_argument("zero denominator");
  q.canonicalize();
  const double d = q.get_d();
  if (mpq_class(d) != q) {
    throw std::invalid_argument(
        fmt::format("the rational {}/{} is not exactly a double", numerator, denominator));
  }
  return d;
}

}  // namespace mechanist
