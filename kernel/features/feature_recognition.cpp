#include "kernel/features/feature_recognition.h"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstdint>
#include <numeric>
#include <optional>
#include <tuple>
#include <utility>

#include "kernel/geometry/circle_fit.h"
#include "kernel/solvers/linear_algebra.h"
#include "kernel/support/number_format.h"
#include "kernel/support/union_find.h"

namespace mechanist {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

constexpr double kPi = 3.14159265358979323846;

// The sign that makes a direction's largest component positive: axes come out the same
// whatever the eigen solver's sign.
Vector3d Canonical(Vector3d a) {
  Eigen::Index i = 0;
  a.cwiseAbs().maxCoeff(&i);
  return a[i] < 0 ? Vector3d(-a) : a;
}

// One closed outline of the walls, projected across the axis.
struct Outline {
  double lo = 1e300, hi = -1e300;                      // its extent along the axis
  std::vector<Vector2d> vertices;                      // distinct projected vertices
  std::vector<std::pair<Vector2d, Vector2d>> edges;    // projected wall edges
  std::vector<std::pair<Vector2d, Vector2d>> normals;  // (face centroid, normal), projected
};

// Largest angular gap between the vertices seen from `center`, radians.
double LargestGap(const std::vector<Vector2d>& p, const Vector2d& center) {
  std::vector<double> angles;
  for (const Vector2d& q : p) angles.push_back(std::atan2(q.y() - center.y(), q.x() - center.x()));
  std::sort(angles.begin(), angles.end());
  double gap = angles.front() + 2 * kPi - angles.back();
  for (std::size_t i = 1; i < angles.size(); ++i) gap = std::max(gap, angles[i] - angles[i - 1]);
  return gap;
}

// Samples of a profile over `bins` bins of a parameter: the largest and smallest value of
// `value` over points spread along every edge, empty bins filled from their neighbours.
struct Profile {
  std::vector<double> high, low;
};

template <typename Param, typename Value>
Profile Sample(const Outline& outline, int bins, double lo, double hi, Param param, Value value,
               bool periodic) {
  Profile p{std::vector<double>(bins, -1e300), std::vector<double>(bins, 1e300)};
  const double span = hi - lo;
  for (const auto& [a, b] : outline.edges) {
    const double da = param(a), db = param(b);
    double d = db - da;
    if (periodic) d = std::remainder(d, span);
    const int steps = 2 + static_cast<int>(std::abs(d) / span * bins * 4);
    for (int s = 0; s <= steps; ++s) {
      const Vector2d q = a + (b - a) * (static_cast<double>(s) / steps);
      double t = (param(q) - lo) / span;
      if (periodic) t -= std::floor(t);
      const int bin = std::clamp(static_cast<int>(t * bins), 0, bins - 1);
      const double v = value(q);
      p.high[bin] = std::max(p.high[bin], v);
      p.low[bin] = std::min(p.low[bin], v);
    }
  }
  for (std::vector<double>* series : {&p.high, &p.low}) {
    std::vector<double>& s = *series;
    const bool high = series == &p.high;
    for (int pass = 0; pass < 2; ++pass) {
      for (int i = 0; i < bins; ++i) {
        if (std::abs(s[i]) < 1e299) continue;
        const double left = s[(i + bins - 1) % bins], right = s[(i + 1) % bins];
        const bool l = std::abs(left) < 1e299, r = std::abs(right) < 1e299;
        if (l || r)
          s[i] = l && r ? (high ? std::max(left, right) : std::min(left, right)) : l ? left : right;
      }
    }
    for (double& v : s) {
      if (std::abs(v) >= 1e299) v = 0.0;
    }
  }
  return p;
}

// |F_k| of a series of power-of-two length (mean removed), k = 0 .. n/2, by an iterative
// radix-2 FFT (Cooley-Tukey).
std::vector<double> Spectrum(const std::vector<double>& s) {
  const std::size_t n = s.size();
  const double mean = std::accumulate(s.begin(), s.end(), 0.0) / n;
  std::vector<std::complex<double>> a(n);
  for (std::size_t i = 0, j = 0; i < n; ++i) {
    a[j] = s[i] - mean;  // bit-reversed order
    std::size_t bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
  }
  for (std::size_t len = 2; len <= n; len <<= 1) {
    const std::complex<double> w = std::polar(1.0, -2 * kPi / static_cast<double>(len));
    for (std::size_t i = 0; i < n; i += len) {
      std::complex<double> wk = 1.0;
      for (std::size_t k = 0; k < len / 2; ++k, wk *= w) {
        const std::complex<double> even = a[i + k], odd = wk * a[i + k + len / 2];
        a[i + k] = even + odd;
        a[i + k + len / 2] = even - odd;
      }
    }
  }
  std::vector<double> magnitude(n / 2 + 1);
  for (std::size_t k = 0; k <= n / 2; ++k) magnitude[k] = std::abs(a[k]);
  return magnitude;
}

// The integer frequency in [from, to] with the largest magnitude.
int Dominant(const std::vector<double>& spectrum, int from, int to) {
  int best = from;
  for (int k = from; k <= to; ++k) {
    if (spectrum[k] > spectrum[best] * (1 + 1e-9)) best = k;
  }
  return best;
}

// The standard module nearest `m` within 3%, or nothing.
std::optional<double> Standard(double m) {
  double best = 0.0;
  for (const double s : StandardModules()) {
    if (std::abs(s - m) < std::abs(best - m)) best = s;
  }
  if (std::abs(best - m) > 0.03 * best) return std::nullopt;
  return best;
}

// How far a periodic series differs from itself shifted by `shift` bins, over its range.
double SelfMismatch(const std::vector<double>& s, int shift) {
  const auto [lo, hi] = std::minmax_element(s.begin(), s.end());
  double sum = 0.0;
  const int n = static_cast<int>(s.size());
  for (int i = 0; i < n; ++i) sum += std::abs(s[i] - s[(i + shift) % n]);
  return sum / n / std::max(*hi - *lo, 1e-12);
}

// The radius of a cycloidal disc of `lobes` lobes about its centre, as the largest radius in
// each of `bins` angle bins over [-pi, pi), turned by `turn` (radians; empty bins are -1). The
// disc rolls in a ring of N = lobes + 1 pins of radius r_p on a circle of radius R, on an
// eccentric e; its outline is the pins' circles' envelope (Shin and Kwon, Mech. Mach. Theory
// 41 (2006)): x = R cos t - r_p cos(t + psi) - e cos(N t), y = -R sin t + r_p sin(t + psi)
// + e sin(N t), psi = atan2(sin((1 - N) t), R / (e N) - cos((1 - N) t)). Its radius runs from
// R - r_p - e (at a pin) to R - r_p + e.
std::vector<double> CycloidRadius(int lobes, double R, double r_p, double e, double turn,
                                  int bins) {
  std::vector<double> radius(bins, -1.0);
  const int n = lobes + 1, samples = 4 * bins;
  for (int i = 0; i < samples; ++i) {
    const double t = 2 * kPi * i / samples;
    const double psi = std::atan2(std::sin((1 - n) * t), R / (e * n) - std::cos((1 - n) * t));
    const double x = R * std::cos(t) - r_p * std::cos(t + psi) - e * std::cos(n * t);
    const double y = -R * std::sin(t) + r_p * std::sin(t + psi) + e * std::sin(n * t);
    const double angle = std::remainder(std::atan2(y, x) + turn, 2 * kPi);
    const int bin = std::clamp(static_cast<int>((angle + kPi) / (2 * kPi) * bins), 0, bins - 1);
    radius[bin] = std::max(radius[bin], std::hypot(x, y));
  }
  return radius;
}

// The phase of the `k`-th harmonic of a radius sampled over [-pi, pi) (bins of -1 skipped).
double HarmonicPhase(const std::vector<double>& radius, int k) {
  std::complex<double> sum = 0.0;
  const int bins = static_cast<int>(radius.size());
  for (int i = 0; i < bins; ++i) {
    if (radius[i] < 0) continue;
    const double angle = -kPi + 2 * kPi * (i + 0.5) / bins;
    sum += radius[i] * std::polar(1.0, -k * angle);
  }
  return std::arg(sum);
}

struct CycloidFit {
  double eccentricity = 0.0, rim = 0.0, pin_circle = 0.0, pin_radius = 0.0;
  double rms = 0.0;  // mm: the outline's radius against the fitted disc's
};

// The cycloidal disc of `lobes` lobes that fits a convex outline's radius profile best (over
// [-pi, pi)), or nothing when the profile does not repeat lobe by lobe or even the best disc is
// off by more than 3% of its eccentricity (a rounded polygon, a cam, a knob). Its extremes give
// e and R - r_p (see CycloidRadius); r_p, the one unknown left, is searched over (0, R - r_p)
// and the lobes' phase matched.
// Whether a radius profile may be a cycloidal disc's of `lobes` lobes: an eccentricity (half
// the radius' range) of 1% of the mean radius or more that leaves the pins room (e (lobes + 1)
// below it), and the profile matching itself turned by one lobe (as a gear's teeth do).
bool MayBeCycloid(const std::vector<double>& radius, int lobes) {
  const auto [lo, hi] = std::minmax_element(radius.begin(), radius.end());
  const double e = (*hi - *lo) / 2, rim = (*hi + *lo) / 2;
  if (lobes < 3 || e <= 0.01 * rim || e * (lobes + 1) >= rim) return false;
  const int bins = static_cast<int>(radius.size());
  return SelfMismatch(radius, static_cast<int>(std::lround(bins / double(lobes)))) < 0.05;
}

std::optional<CycloidFit> FitCycloid(const std::vector<double>& radius, int lobes) {
  if (!MayBeCycloid(radius, lobes)) return std::nullopt;
  const auto [lo, hi] = std::minmax_element(radius.begin(), radius.end());
  const double e = (*hi - *lo) / 2, rim = (*hi + *lo) / 2;  // rim = R - r_p
  const int bins = static_cast<int>(radius.size());
  // The search runs on the profile in 512 bins (the largest radius of each group), the best
  // disc is then measured on the whole profile.
  constexpr int kCoarse = 512;
  const int group = std::max(1, bins / kCoarse);
  std::vector<double> coarse(bins / group, -1e300);
  for (int i = 0; i < bins; ++i) {
    const int k = std::min(i / group, static_cast<int>(coarse.size()) - 1);
    coarse[k] = std::max(coarse[k], radius[i]);
  }
  auto fit = [&](double r_p, const std::vector<double>& profile) -> std::optional<CycloidFit> {
    const double R = rim + r_p;
    if (r_p <= 0 || e * (lobes + 1) >= R) return std::nullopt;
    const int n = static_cast<int>(profile.size());
    // Unturned, the disc's radius is even about angle 0, where it is least (a pin): the
    // lobes' harmonic has phase pi. Turned by `turn`, its phase is lowered by lobes x turn.
    const double turn = (kPi - HarmonicPhase(profile, lobes)) / lobes;
    const std::vector<double> model = CycloidRadius(lobes, R, r_p, e, turn, n);
    double sum = 0.0;
    int count = 0;
    for (int i = 0; i < n; ++i) {
      if (model[i] < 0) continue;
      sum += (profile[i] - model[i]) * (profile[i] - model[i]);
      ++count;
    }
    return CycloidFit{e, rim, 2 * R, r_p, std::sqrt(sum / std::max(count, 1))};
  };
  // r_p over (0, rim) in 48 steps, then the best step's neighbourhood in eighths.
  constexpr int kSteps = 48;
  std::optional<CycloidFit> best;
  auto keep = [&](const std::optional<CycloidFit>& f) {
    if (f && (!best || f->rms < best->rms)) best = f;
  };
  for (int step = 1; step < kSteps; ++step) keep(fit(rim * step / kSteps, coarse));
  if (!best) return std::nullopt;
  const double found = best->pin_radius, h = rim / kSteps;
  for (int k = -8; k <= 8; ++k) keep(fit(found + k * h / 8, coarse));
  best = fit(best->pin_radius, radius);
  if (!best || best->rms > 0.03 * e) return std::nullopt;
  return best;
}

// Axes of the mesh's cylindrical patches, whatever their direction: faces joined across
// shared edges whose normals turn by less than 30 degrees make smooth patches; a patch whose
// area-weighted normal matrix sum(a n n^T) has one eigenvalue near zero (every normal across
// one direction) and another well above it (the normals turn: no flat face) is a cylinder, or
// part of one, along that direction. Cones and spheres have no such direction.
std::vector<Vector3d> CylinderPatchAxes(const TriangleMesh& mesh,
                                        const std::vector<Vector3d>& normal,
                                        const std::vector<double>& area) {
  const std::size_t nf = mesh.faces.size();
  std::vector<std::array<std::int32_t, 3>> edges;  // (lower vertex, higher vertex, face)
  edges.reserve(3 * nf);
  for (std::size_t f = 0; f < nf; ++f) {
    for (int k = 0; k < 3; ++k) {
      const std::int32_t a = mesh.faces[f][k], b = mesh.faces[f][(k + 1) % 3];
      edges.push_back({std::min(a, b), std::max(a, b), static_cast<std::int32_t>(f)});
    }
  }
  std::sort(edges.begin(), edges.end());
  const double kSmooth = std::cos(30 * kPi / 180);
  UnionFind patches(nf);
  for (std::size_t i = 0; i + 1 < edges.size(); ++i) {
    for (std::size_t j = i + 1;
         j < edges.size() && edges[j][0] == edges[i][0] && edges[j][1] == edges[i][1]; ++j) {
      if (normal[edges[i][2]].dot(normal[edges[j][2]]) > kSmooth) {
        patches.Join(edges[i][2], edges[j][2]);
      }
    }
  }
  std::vector<int> patch_of(nf, -1);
  std::vector<Eigen::Matrix3d> sums;
  std::vector<int> sizes;
  for (std::size_t f = 0; f < nf; ++f) {
    const int root = patches.Find(static_cast<int>(f));
    if (patch_of[root] < 0) {
      patch_of[root] = static_cast<int>(sums.size());
      sums.push_back(Eigen::Matrix3d::Zero());
      sizes.push_back(0);
    }
    sums[patch_of[root]] += area[f] * normal[f] * normal[f].transpose();
    ++sizes[patch_of[root]];
  }
  std::vector<Vector3d> axes;
  for (std::size_t p = 0; p < sums.size(); ++p) {
    if (sizes[p] < 8) continue;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(sums[p]);
    const Vector3d lambda = eigen.eigenvalues();  // ascending
    const double trace = lambda.sum();
    if (trace <= 0 || lambda[0] > 4e-6 * trace || lambda[1] < 0.05 * trace) continue;
    axes.push_back(Canonical(eigen.eigenvectors().col(0).normalized()));
  }
  return axes;
}

std::string Mm(double x) { return fmt::format("{} mm", FormatNumber(x, 6)); }

// The segments where the plane p . axis = h cuts the mesh's faces, in (u, v) coordinates.
Outline Section(const TriangleMesh& mesh, const Vector3d& axis, const Vector3d& u,
                const Vector3d& v, double h) {
  Outline o;
  for (const auto& t : mesh.faces) {
    std::array<Vector2d, 2> cut;
    int n = 0;
    for (int k = 0; k < 3; ++k) {
      const Vector3d& a = mesh.vertices[t[k]];
      const Vector3d& b = mesh.vertices[t[(k + 1) % 3]];
      const double da = a.dot(axis) - h, db = b.dot(axis) - h;
      if ((da < 0) == (db < 0) || n == 2) continue;
      const Vector3d q = a + da / (da - db) * (b - a);
      cut[n++] = Vector2d(q.dot(u), q.dot(v));
    }
    if (n == 2) o.edges.emplace_back(cut[0], cut[1]);
  }
  return o;
}

// Sections 0 .. n-1 cut by `cut` (true when the section shows teeth), every `stride`-th
// first and the rest only when one of those shows teeth: most parts are no gear, and a run of
// `stride` or more sections that show teeth holds one of the first. Whether any showed teeth.
template <typename Cut>
bool CutEveryNthFirst(int n, int stride, Cut cut) {
  bool teeth = false;
  for (int i = 0; i < n; i += stride) teeth = cut(i) || teeth;
  if (!teeth) return false;
  for (int i = 0; i < n; ++i) {
    if (i % stride != 0) cut(i);
  }
  return true;
}

// Teeth in one section across the axis: the outline's radius about `centre` (its largest for
// external teeth, its smallest for internal ones) repeating z times around with the depth of a
// standard module, as for a spur gear's outline.
struct SectionTeeth {
  int teeth = 0;
  double module = 0.0;      // ISO 54
  double raw_module = 0.0;  // depth / 2.25
  double tip = 0.0;         // mm: tip radius
  double phase = 0.0;       // radians: the z-th harmonic's phase of the radius
  bool internal = false;
};

// Whether a section may show teeth about `centre` (most sections of most parts are no gear):
// with each segment's larger end radius over the angles it spans (external teeth), or its
// smaller (internal), in 1024 angles, the radius spans a tooth depth near a standard module's
// (2.25 m within 6%; with `any_depth`, a bevel gear's, over 2% of the largest radius) and
// repeats around (matching itself turned by one period of its strongest frequency within
// 15%). A cheap look before the full profile.
bool MayShowTeeth(const Outline& o, const Vector2d& centre, bool any_depth = false) {
  constexpr int kBins = 1024;
  std::vector<double> high(kBins, -1e300), low(kBins, 1e300);
  auto bin_of = [&](const Vector2d& q) {
    const double t = (std::atan2(q.y() - centre.y(), q.x() - centre.x()) + kPi) / (2 * kPi);
    return std::clamp(static_cast<int>(t * kBins), 0, kBins - 1);
  };
  for (const auto& [a, b] : o.edges) {
    const double ra = (a - centre).norm(), rb = (b - centre).norm();
    int from = bin_of(a), to = bin_of(b);
    // The short way round from one end's angle to the other's.
    if ((to - from + kBins) % kBins > kBins / 2) std::swap(from, to);
    for (int i = from;; i = (i + 1) % kBins) {
      high[i] = std::max(high[i], std::max(ra, rb));
      low[i] = std::min(low[i], std::min(ra, rb));
      if (i == to) break;
    }
  }
  auto teeth_like = [any_depth](const std::vector<double>& r) {
    const auto [lo, hi] = std::minmax_element(r.begin(), r.end());
    if (*hi >= 1e299 || *lo <= -1e299) return false;  // an angle no segment spans
    const double m = (*hi - *lo) / 2.25;
    const bool standard = std::any_of(StandardModules().begin(), StandardModules().end(),
                                      [m](double s) { return std::abs(s - m) <= 0.06 * s; });
    if (any_depth ? *hi - *lo <= 0.02 * *hi : !standard) return false;
    const int z = Dominant(Spectrum(r), 3, 256);
    return SelfMismatch(r, static_cast<int>(std::lround(kBins / double(z)))) < 0.15;
  };
  return teeth_like(high) || teeth_like(low);
}

std::optional<SectionTeeth> TeethOfSection(const Outline& o, const Vector2d& centre) {
  constexpr int kBins = 2048;
  if (o.edges.size() < 12 || !MayShowTeeth(o, centre)) return std::nullopt;
  const Profile radial = Sample(
      o, kBins, -kPi, kPi,
      [&](const Vector2d& q) { return std::atan2(q.y() - centre.y(), q.x() - centre.x()); },
      [&](const Vector2d& q) { return (q - centre).norm(); }, true);
  for (const bool internal : {false, true}) {
    const std::vector<double>& r = internal ? radial.low : radial.high;
    const auto [lo, hi] = std::minmax_element(r.begin(), r.end());
    const double depth = *hi - *lo;
    if (depth <= 1e-3 * *hi) continue;
    const std::optional<double> m = Standard(depth / 2.25);
    if (!m) continue;
    const int z = Dominant(Spectrum(r), 3, 256);
    if (o.edges.size() < static_cast<std::size_t>(4 * z) ||
        SelfMismatch(r, static_cast<int>(std::lround(kBins / double(z)))) >= 0.05) {
      continue;
    }
    return SectionTeeth{z, *m, depth / 2.25, internal ? *lo : *hi, HarmonicPhase(r, z), internal};
  }
  return std::nullopt;
}

// Directions across `axis` (u, v: with the axis a right-handed frame) and the mesh's extent
// along it.
struct AxisFrame {
  Vector3d u, v;
  double t_min = 1e300, t_max = -1e300;
  double width() const { return t_max - t_min; }
};

// Unit directions u, v across the unit `axis`, with it a right-handed frame.
std::pair<Vector3d, Vector3d> Across(const Vector3d& axis) {
  const Vector3d e = std::abs(axis.x()) < 0.6 ? Vector3d::UnitX() : Vector3d::UnitY();
  const Vector3d u = axis.cross(e).normalized();
  return {u, axis.cross(u)};
}

AxisFrame FrameAbout(const TriangleMesh& mesh, const Vector3d& axis) {
  AxisFrame f;
  std::tie(f.u, f.v) = Across(axis);
  for (const Vector3d& p : mesh.vertices) {
    f.t_min = std::min(f.t_min, p.dot(axis));
    f.t_max = std::max(f.t_max, p.dot(axis));
  }
  return f;
}

// The length-weighted middle of a section's segments (teeth and bore are symmetric about it).
Vector2d CentreOf(const Outline& o) {
  Vector2d sum = Vector2d::Zero();
  double length = 0.0;
  for (const auto& [a, b] : o.edges) {
    sum += (b - a).norm() * (a + b) / 2;
    length += (b - a).norm();
  }
  return length > 0 ? Vector2d(sum / length) : Vector2d::Zero();
}

// A gear whose faces are not all along or across its axis (a helical gear, or a spur gear with
// a hub or chamfers): sections across `axis` that show the same teeth, whose angular position
// theta = -phase / z is fitted as a line in the height h (sections close enough that the teeth
// turn by less than half a tooth between neighbours). At the pitch radius r = m z / (2 cos b)
// the helix rises by dh = r dtheta / tan(b), so sin(b) = m z (dtheta / dh) / 2 with the normal
// module m; theta growing with h about the axis is a right-hand helix.
std::optional<RecognizedFeature> SectionGear(const TriangleMesh& mesh, const Vector3d& axis) {
  const AxisFrame frame = FrameAbout(mesh, axis);
  const Vector3d &u = frame.u, &v = frame.v;
  const double t_min = frame.t_min, t_max = frame.t_max, width = frame.width();
  if (!(width > 0)) return std::nullopt;
  // Coarse sections, off any round height (a CAD vertex plane would cut faces edge-on).
  constexpr int kCoarse = 24;
  const double coarse_step = width / kCoarse;
  auto height = [&](double i, double step, double from) { return from + (i + 0.5013) * step; };
  std::optional<Vector2d> centre;
  std::vector<std::optional<SectionTeeth>> coarse(kCoarse);
  auto cut = [&](int i) {
    const Outline o = Section(mesh, axis, u, v, height(i, coarse_step, t_min));
    if (o.edges.empty()) return false;
    if (!centre) centre = CentreOf(Section(mesh, axis, u, v, t_min + 0.5013 * width));
    coarse[i] = TeethOfSection(o, *centre);
    return coarse[i].has_value();
  };
  // A run of three, the fewest that counts, holds every third section.
  if (!CutEveryNthFirst(kCoarse, 3, cut)) return std::nullopt;
  // The longest run of sections with the same teeth.
  auto same = [](const SectionTeeth& a, const SectionTeeth& b) {
    return a.teeth == b.teeth && a.module == b.module && a.internal == b.internal;
  };
  int best_first = -1, best_count = 0;
  for (int i = 0; i < kCoarse;) {
    if (!coarse[i]) {
      ++i;
      continue;
    }
    int j = i + 1;
    while (j < kCoarse && coarse[j] && same(*coarse[j], *coarse[i])) ++j;
    if (j - i > best_count) best_first = i, best_count = j - i;
    i = j;
  }
  if (best_count < 3) return std::nullopt;
  const SectionTeeth teeth = *coarse[best_first];
  const int z = teeth.teeth;
  const double m = teeth.module;
  // The face: from the run's first section to its last, out to the part's end where the run
  // reaches it.
  const int best_last = best_first + best_count - 1;
  const double lo = best_first == 0 ? t_min : t_min + best_first * coarse_step;
  const double hi = best_last == kCoarse - 1 ? t_max : t_min + (best_last + 1) * coarse_step;
  // Fine sections over the face's inner part: at most 0.4 m apart, which a helix of up to 60
  // degrees turns by less than half a tooth.
  const int fine = std::clamp(static_cast<int>(std::ceil((hi - lo) / (0.4 * m))), 8, 256);
  const double fine_step = (hi - lo) / fine;
  std::vector<double> hs, thetas;
  double theta = 0.0;
  std::optional<double> previous;
  for (int i = 0; i < fine; ++i) {
    const double h = height(i, fine_step, lo);
    const std::optional<SectionTeeth> s = TeethOfSection(Section(mesh, axis, u, v, h), *centre);
    if (!s || !same(*s, teeth)) continue;
    const double at = -s->phase / z;
    if (previous) theta += std::remainder(at - *previous, 2 * kPi / z);
    previous = at;
    hs.push_back(h);
    thetas.push_back(theta);
  }
  if (hs.size() < 4) return std::nullopt;
  // Least squares line theta = a + k h.
  const double n = static_cast<double>(hs.size());
  const double h_mean = std::accumulate(hs.begin(), hs.end(), 0.0) / n;
  const double t_mean = std::accumulate(thetas.begin(), thetas.end(), 0.0) / n;
  double shh = 0.0, sht = 0.0;
  for (std::size_t i = 0; i < hs.size(); ++i) {
    shh += (hs[i] - h_mean) * (hs[i] - h_mean);
    sht += (hs[i] - h_mean) * (thetas[i] - t_mean);
  }
  const double k = sht / shh;
  double misfit = 0.0;  // radians, largest
  for (std::size_t i = 0; i < hs.size(); ++i) {
    misfit = std::max(misfit, std::abs(thetas[i] - t_mean - k * (hs[i] - h_mean)));
  }
  const double sin_helix = m * z * k / 2;
  // The teeth must follow one helix (a twisted or stepped part does not) to a tenth of a tooth.
  if (std::abs(sin_helix) >= std::sin(60 * kPi / 180) || misfit > 0.1 * 2 * kPi / z) {
    return std::nullopt;
  }
  double helix = std::asin(sin_helix);
  if (std::abs(helix) < 0.25 * kPi / 180) helix = 0.0;  // a spur gear's sections barely turn
  const double pitch_radius = m * z / (2 * std::cos(helix));
  const double shift = teeth.internal ? pitch_radius / m - 1.0 - teeth.tip / m
                                      : teeth.tip / m - pitch_radius / m - 1.0;
  if (shift <= -1.0 || shift >= 1.2) return std::nullopt;
  RecognizedFeature g;
  Feature& f = g.feature;
  f.kind = FeatureKind::kGear;
  f.id = "teeth";
  f.origin = centre->x() * u + centre->y() * v + lo * axis;
  f.axis = axis;
  f.length = hi - lo;
  f.teeth = z;
  f.module = m;
  f.internal = teeth.internal;
  f.helix_angle = helix;
  g.fit_error = std::abs(teeth.raw_module - m) * z / 2;
  const std::string kind = teeth.internal ? "internal gear" : "gear";
  g.detail = helix == 0.0
                 ? fmt::format(
                       "spur {} from {} sections across the axis, {} teeth, tooth depth {} = "
                       "2.25 x {}, module {} (ISO 54), profile shift about {}",
                       kind, hs.size(), z, Mm(2.25 * teeth.raw_module),
                       FormatNumber(teeth.raw_module, 5), FormatNumber(m), FormatNumber(shift, 2))
                 : fmt::format(
                       "helical {} from {} sections across the axis, {} teeth, normal module {} "
                       "(ISO 54; tooth depth 2.25 x {}), the teeth turning {} deg per mm: helix "
                       "angle {} deg, {} hand, profile shift about {}",
                       kind, hs.size(), z, FormatNumber(m), FormatNumber(teeth.raw_module, 5),
                       FormatNumber(k * 180 / kPi, 4), FormatNumber(helix * 180 / kPi, 4),
                       helix > 0 ? "right" : "left", FormatNumber(shift, 2));
  return g;
}

// Teeth around a section of a bevel gear: the outline's largest radius about `centre` per
// angle repeating z times around (matching itself turned by one tooth within 5%), its depth
// free (a bevel gear's local module shrinks toward the apex).
struct BevelSection {
  int teeth = 0;
  double tip = 0.0, root = 0.0;  // mm: the largest and smallest of the largest radius
  double phase = 0.0;            // of the teeth's harmonic (HarmonicPhase)
};

std::optional<BevelSection> BevelTeethOfSection(const Outline& o, const Vector2d& centre) {
  constexpr int kBins = 2048;
  if (o.edges.size() < 12 || !MayShowTeeth(o, centre, /*any_depth=*/true)) return std::nullopt;
  const Profile radial = Sample(
      o, kBins, -kPi, kPi,
      [&](const Vector2d& q) { return std::atan2(q.y() - centre.y(), q.x() - centre.x()); },
      [&](const Vector2d& q) { return (q - centre).norm(); }, true);
  const std::vector<double>& r = radial.high;
  const auto [lo, hi] = std::minmax_element(r.begin(), r.end());
  if (*hi - *lo <= 0.02 * *hi) return std::nullopt;
  const int z = Dominant(Spectrum(r), 3, 256);
  if (o.edges.size() < static_cast<std::size_t>(4 * z) ||
      SelfMismatch(r, static_cast<int>(std::lround(kBins / double(z)))) >= 0.05) {
    return std::nullopt;
  }
  return BevelSection{z, *hi, *lo, HarmonicPhase(r, z)};
}

// The spiral angle, radians, of a bevel gear's teeth at the middle of its face, from their
// angular position theta = -phase / z in sections at heights `ts` along the axis (neighbours
// turned by less than half a tooth), pitch angle `d`, apex at height `apex`, pitch radius
// r(t) = `slope` |t - apex|. On the pitch cone (r = s sin d at cone distance s, s = |t - apex|
// / cos d) a tooth trace at spiral angle psi turns by dtheta = tan(psi) ds / r, so tan(psi) =
// r cos(d) dtheta/dt, with dtheta/dt the slope at the face's middle of a cubic fitted to
// theta(t) (a constant-angle spiral turns as the logarithm of s, whose third-order term a
// parabola's slope would take in: +0.2 degree at 35 over a face of a third of the cone).
// Positive, a right-hand spiral, when theta grows about the axis away from the apex (either
// way along the axis: turning both ways over, it keeps its sign). Nothing when the teeth
// follow no smooth spiral (off the cubic by a tenth of a tooth).
std::optional<double> SpiralAngle(const std::vector<double>& ts, const std::vector<double>& phases,
                                  int z, double d, double apex, double slope) {
  std::vector<double> thetas;
  for (std::size_t i = 0; i < phases.size(); ++i) {
    const double at = -phases[i] / z;
    thetas.push_back(
        i == 0 ? at : thetas.back() + std::remainder(at - (-phases[i - 1] / z), 2 * kPi / z));
  }
  const double middle = (ts.front() + ts.back()) / 2;
  Eigen::MatrixXd a(ts.size(), 4);
  Eigen::VectorXd b(ts.size());
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const double x = ts[i] - middle;
    a.row(static_cast<Eigen::Index>(i)) << 1.0, x, x * x, x * x * x;
    b[static_cast<Eigen::Index>(i)] = thetas[i];
  }
  const Eigen::Vector4d c = LinearLeastSquares(a, b);
  if ((a * c - b).cwiseAbs().maxCoeff() > 0.1 * 2 * kPi / z) return std::nullopt;
  const double radius = slope * std::abs(middle - apex);
  const double psi = std::atan(radius * std::cos(d) * c[1]);
  return std::abs(psi) < 0.25 * kPi / 180 ? 0.0 : psi;  // a straight gear's sections barely turn
}

// A straight or spiral bevel gear about `axis`: sections across it show the same teeth, whose
// tip and root radii shrink along lines toward one apex (the gear's tip and root cones). As for
// a spur gear, the pitch line lies a 2.25th of the tooth depth below the tip (addendum m,
// dedendum 1.25 m, measured in any section across the axis); it meets the axis at the apex, at
// the pitch angle d = atan(dr / dh). The teeth end at the heel, farthest from the apex, where
// the pitch radius is m z / 2: the module there, rounded to ISO 54 (within 3%), with a tooth
// depth there of 2.25 m (radial) down to 2.25 m cos(pitch angle) (teeth on the back cone),
// within 15%. The spiral angle (SpiralAngle) from the teeth's turn along the axis.
std::optional<RecognizedFeature> SectionBevelGear(const TriangleMesh& mesh, const Vector3d& axis) {
  const AxisFrame frame = FrameAbout(mesh, axis);
  const Vector3d &u = frame.u, &v = frame.v;
  const double t_min = frame.t_min, width = frame.width();
  if (!(width > 0)) return std::nullopt;
  // The axis' point: the middle of a middle section.
  const Outline middle = Section(mesh, axis, u, v, t_min + 0.5013 * width);
  if (middle.edges.empty()) return std::nullopt;
  const Vector2d centre = CentreOf(middle);
  constexpr int kSections = 24;
  const double step = width / kSections;
  std::vector<std::optional<BevelSection>> sections(kSections);
  auto cut = [&](int i) {
    sections[i] =
        BevelTeethOfSection(Section(mesh, axis, u, v, t_min + (i + 0.5013) * step), centre);
    return sections[i].has_value();
  };
  // A run of five, the fewest that counts, holds every fourth section.
  if (!CutEveryNthFirst(kSections, 4, cut)) return std::nullopt;
  // The longest run of sections with the same tooth count.
  int first = -1, count = 0;
  for (int i = 0; i < kSections;) {
    if (!sections[i]) {
      ++i;
      continue;
    }
    int j = i + 1;
    while (j < kSections && sections[j] && sections[j]->teeth == sections[i]->teeth) ++j;
    if (j - i > count) first = i, count = j - i;
    i = j;
  }
  if (count < 5) return std::nullopt;
  const int z = sections[first]->teeth;
  // Tip and root radius as lines in the height: r = a + b t, by least squares.
  std::vector<double> ts, tips, roots, phases;
  for (int i = first; i < first + count; ++i) {
    ts.push_back(t_min + (i + 0.5013) * step);
    tips.push_back(sections[i]->tip);
    roots.push_back(sections[i]->root);
    phases.push_back(sections[i]->phase);
  }
  const auto line = [&](const std::vector<double>& r) {
    const double n = static_cast<double>(ts.size());
    const double tm = std::accumulate(ts.begin(), ts.end(), 0.0) / n;
    const double rm = std::accumulate(r.begin(), r.end(), 0.0) / n;
    double stt = 0.0, str = 0.0;
    for (std::size_t k = 0; k < ts.size(); ++k) {
      stt += (ts[k] - tm) * (ts[k] - tm);
      str += (ts[k] - tm) * (r[k] - rm);
    }
    const double b = str / stt;
    double misfit = 0.0;
    for (std::size_t k = 0; k < ts.size(); ++k) {
      misfit = std::max(misfit, std::abs(r[k] - rm - b * (ts[k] - tm)));
    }
    return std::array<double, 3>{rm - b * tm, b, misfit};
  };
  const auto [tip_a, tip_b, tip_misfit] = line(tips);
  const auto [root_a, root_b, root_misfit] = line(roots);
  // Cones, not a cylinder (a spur gear) or a disc (a crown gear, teeth on a face): the pitch
  // angle between 5 and 80 degrees, both lines straight to 2% of the tip and sloping alike.
  const double pitch_a = tip_a - (tip_a - root_a) / 2.25;
  const double pitch_b = tip_b - (tip_b - root_b) / 2.25;
  const double angle = std::atan(std::abs(pitch_b));
  const double tip_max = *std::max_element(tips.begin(), tips.end());
  if (angle < 5 * kPi / 180 || angle > 80 * kPi / 180 || tip_b * root_b <= 0 ||
      std::max(tip_misfit, root_misfit) > 0.02 * tip_max) {
    return std::nullopt;
  }
  // The apex: where the pitch line meets the axis; the tip and root lines must meet it there
  // too (within a tenth of the cone distance), as the cones of one gear do.
  const double apex = -pitch_a / pitch_b;
  const double heel = pitch_b > 0 ? t_min + (first + count) * step : t_min + first * step;
  const double reach = std::abs(heel - apex);
  if (std::abs(-tip_a / tip_b - apex) > 0.1 * reach ||
      std::abs(-root_a / root_b - apex) > 0.1 * reach) {
    return std::nullopt;
  }
  const double heel_radius = std::abs(pitch_b) * reach;
  const double raw_module = 2 * heel_radius / z;
  const std::optional<double> m = Standard(raw_module);
  if (!m) return std::nullopt;
  // A tooth's depth at the heel, across the axis: 2.25 m, or 2.25 m cos(angle) where the
  // teeth stand on the back cone (within 15%); a tapered polygon or knob is far shallower.
  const double heel_depth = std::abs(tip_b - root_b) * reach;
  if (heel_depth < 0.85 * 2.25 * *m * std::cos(angle) || heel_depth > 1.15 * 2.25 * *m) {
    return std::nullopt;
  }
  RecognizedFeature g;
  Feature& f = g.feature;
  f.kind = FeatureKind::kBevelGear;
  f.id = "teeth";
  const Vector3d into = pitch_b > 0 ? axis : Vector3d(-axis);  // from the apex into the gear
  f.origin = centre.x() * u + centre.y() * v + apex * axis;
  f.axis = into;
  f.teeth = z;
  f.module = *m;
  f.pitch_angle = angle;
  f.length = count * step / std::cos(angle);  // the face width along the pitch line
  const std::optional<double> spiral = SpiralAngle(ts, phases, z, angle, apex, std::abs(pitch_b));
  f.spiral_angle = spiral.value_or(0.0);
  g.fit_error = std::abs(raw_module - *m) * z / 2;
  const std::string kind =
      !spiral ? "bevel gear (its teeth follow no smooth spiral: taken as straight)"
      : *spiral == 0.0
          ? "straight bevel gear"
          : fmt::format("spiral bevel gear (spiral angle {} deg at the face's middle, {} hand)",
                        FormatNumber(std::abs(*spiral) * 180 / kPi, 3),
                        *spiral > 0 ? "right" : "left");
  g.detail = fmt::format(
      "{} from {} sections across the axis, {} teeth, tip and root radii shrinking toward one "
      "apex: pitch angle {} deg, pitch radius {} at the heel, module {} (ISO 54; measured {})",
      kind, count, z, FormatNumber(angle * 180 / kPi, 4), Mm(heel_radius), FormatNumber(*m),
      FormatNumber(raw_module, 5));
  return g;
}

// The mesh's outline in the half-plane through the axis (point c, direction a) toward u, as
// the largest distance from the axis over `bins` bins of the height t in [lo, hi]; -1 where
// no segment passes.
std::vector<double> AxialProfile(const TriangleMesh& mesh, const Vector3d& c, const Vector3d& a,
                                 const Vector3d& u, double lo, double hi, int bins) {
  const Vector3d n = a.cross(u);
  std::vector<double> r(bins, -1.0);
  for (const auto& f : mesh.faces) {
    std::array<Vector2d, 2> cut;
    int count = 0;
    for (int k = 0; k < 3 && count < 2; ++k) {
      const Vector3d p = mesh.vertices[f[k]] - c, q = mesh.vertices[f[(k + 1) % 3]] - c;
      const double dp = p.dot(n), dq = q.dot(n);
      if ((dp < 0) == (dq < 0)) continue;
      const Vector3d x = p + dp / (dp - dq) * (q - p);
      cut[count++] = Vector2d(x.dot(a), x.dot(u));
    }
    if (count < 2 || cut[0].y() <= 0 || cut[1].y() <= 0) continue;  // the other half-plane
    const int steps =
        2 + static_cast<int>(std::abs(cut[1].x() - cut[0].x()) / (hi - lo) * bins * 4);
    for (int k = 0; k <= steps; ++k) {
      const Vector2d x = cut[0] + (cut[1] - cut[0]) * (static_cast<double>(k) / steps);
      const int bin = static_cast<int>(std::floor((x.x() - lo) / (hi - lo) * bins));
      if (bin >= 0 && bin < bins) r[bin] = std::max(r[bin], x.y());
    }
  }
  return r;
}

// How far a series along a line (not round a circle) differs from itself shifted by `shift`
// samples, over its range: only the samples that have a partner `shift` on are compared.
double LineMismatch(const std::vector<double>& s, int shift) {
  const int n = static_cast<int>(s.size());
  if (shift <= 0 || shift >= n) return 1.0;
  const auto [lo, hi] = std::minmax_element(s.begin(), s.end());
  double sum = 0.0;
  for (int i = 0; i + shift < n; ++i) sum += std::abs(s[i] - s[i + shift]);
  return sum / (n - shift) / std::max(*hi - *lo, 1e-12);
}

// The Fourier coefficient of a series, its mean removed, at `q` cycles over its length (q need
// not be whole: the mean would leak into it).
std::complex<double> Coefficient(const std::vector<double>& s, double q) {
  const double n = static_cast<double>(s.size());
  const double mean = std::accumulate(s.begin(), s.end(), 0.0) / n;
  std::complex<double> sum = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    sum += (s[i] - mean) * std::polar(1.0, -2 * kPi * q * i / n);
  }
  return sum;
}

// A worm about `axis` (refined: see below): its outline in a half-plane through the axis
// repeats along it at the axial pitch p (the strongest frequency over the middle 90% of its
// length, refined to a hundredth of a cycle; two cycles or more, matching itself shifted by one
// within 10%), with a tooth depth of 2.25 m for the standard module m = p / pi
// (ISO 54 within 3%; depth within 10%). In 16 half-planes around the axis the thread's phase
// turns by -h S theta for S starts of hand h (r(t, theta) = P(t - h S p theta / 2 pi)): the
// slope, unwrapped, is the starts and the hand. Pitch diameter: the tip's less two addenda m.
std::optional<RecognizedFeature> AxialWorm(const TriangleMesh& mesh, const Vector3d& axis_guess) {
  // The axis: the principal direction leans where the thread ends part-way round. Through the
  // centres of circles (Kasa) fitted to the vertices on the tip (within 2% of the largest
  // radius) in the lower and the upper half, three times.
  Vector3d axis = axis_guess, c = Vector3d::Zero();
  for (const Vector3d& p : mesh.vertices) c += p / static_cast<double>(mesh.vertices.size());
  double tip = 0.0;
  for (int round = 0; round < 3; ++round) {
    const auto [u, v] = Across(axis);
    tip = 0.0;
    for (const Vector3d& p : mesh.vertices) {
      const Vector3d d = p - c;
      tip = std::max(tip, (d - d.dot(axis) * axis).norm());
    }
    std::array<std::vector<Vector2d>, 2> rims;
    std::array<double, 2> heights = {0.0, 0.0};
    for (const Vector3d& p : mesh.vertices) {
      const Vector3d d = p - c;
      if ((d - d.dot(axis) * axis).norm() < 0.98 * tip) continue;
      const int half = d.dot(axis) < 0 ? 0 : 1;
      rims[half].emplace_back(d.dot(u), d.dot(v));
      heights[half] += d.dot(axis);
    }
    if (rims[0].size() < 3 || rims[1].size() < 3) return std::nullopt;
    std::array<Vector3d, 2> centres;
    for (int h = 0; h < 2; ++h) {
      const Vector2d q = FitCircle(rims[h]).center;
      centres[h] = c + q.x() * u + q.y() * v + heights[h] / rims[h].size() * axis;
    }
    if (!((centres[1] - centres[0]).norm() > 0)) return std::nullopt;
    axis = (centres[1] - centres[0]).normalized();
    if (axis.dot(axis_guess) < 0) axis = -axis;
    c = (centres[0] + centres[1]) / 2;
  }
  c -= c.dot(axis) * axis;  // heights are measured from the origin's plane, as elsewhere
  const AxisFrame frame = FrameAbout(mesh, axis);
  const Vector3d &u = frame.u, &v = frame.v;
  const double t_min = frame.t_min, t_max = frame.t_max, width = frame.width();
  if (!(width > 0)) return std::nullopt;
  constexpr int kBins = 1024, kWedges = 16;
  const double lo = t_min + 0.05 * width, hi = t_max - 0.05 * width;
  auto profile = [&](int k) {
    const double angle = 2 * kPi * k / kWedges;
    std::vector<double> r =
        AxialProfile(mesh, c, axis, std::cos(angle) * u + std::sin(angle) * v, lo, hi, kBins);
    return std::count(r.begin(), r.end(), -1.0) > 0 ? std::vector<double>() : r;
  };
  const std::vector<double> first = profile(0);
  if (first.empty()) return std::nullopt;
  const auto [low, high] = std::minmax_element(first.begin(), first.end());
  const double depth = *high - *low;
  if (depth <= 0.05 * *high) return std::nullopt;
  // The strongest frequency (a cheap look first: the outline repeating at a whole number of
  // cycles within 30%), refined to a tenth, then a hundredth of a cycle over the window.
  const int f = Dominant(Spectrum(first), 2, kBins / 8);
  if (LineMismatch(first, static_cast<int>(std::lround(kBins / double(f)))) >= 0.3) {
    return std::nullopt;
  }
  double q = f;
  for (const double step : {0.1, 0.01}) {
    double best = 0.0, from = q;
    for (int k = -10; k <= 10; ++k) {
      const double strength = std::abs(Coefficient(first, from + step * k));
      if (strength > best) best = strength, q = from + step * k;
    }
  }
  // Two turns of the thread at least, repeating along the axis.
  if (q < 2 || LineMismatch(first, static_cast<int>(std::lround(kBins / q))) >= 0.1) {
    return std::nullopt;
  }
  const double pitch = (hi - lo) / q;
  const std::optional<double> m = Standard(pitch / kPi);
  if (!m || std::abs(depth - 2.25 * *m) > 0.1 * 2.25 * *m) return std::nullopt;
  // The phase in each half-plane, unwrapped around the axis.
  std::vector<double> phases;
  for (int k = 0; k < kWedges; ++k) {
    const std::vector<double> r = k == 0 ? first : profile(k);
    if (r.empty()) return std::nullopt;
    const double at = std::arg(Coefficient(r, q));
    phases.push_back(phases.empty() ? at
                                    : phases.back() + std::remainder(at - phases.back(), 2 * kPi));
  }
  // The slope of the phase in the angle, by least squares over the half-planes.
  double sxx = 0.0, sxy = 0.0;
  for (int k = 0; k < kWedges; ++k) {
    const double x = 2 * kPi * (k - (kWedges - 1) / 2.0) / kWedges;
    sxx += x * x;
    sxy += x * phases[k];
  }
  const double slope = sxy / sxx;
  const int starts = static_cast<int>(std::lround(std::abs(slope)));
  if (starts < 1 || starts > 6 || std::abs(std::abs(slope) - starts) > 0.2) return std::nullopt;
  RecognizedFeature w;
  Feature& feature = w.feature;
  feature.kind = FeatureKind::kWorm;
  feature.id = "worm";
  feature.origin = c + t_min * axis;
  feature.axis = axis;
  feature.length = width;
  feature.starts = starts;
  feature.module = *m;
  feature.pitch_diameter = 2 * (tip - *m);
  feature.hand = slope < 0 ? Hand::kRight : Hand::kLeft;
  w.fit_error = std::abs(pitch / kPi - *m) * kPi;
  w.detail = fmt::format(
      "worm from 16 outlines through its axis: axial pitch {} = pi x {}, tooth depth {} "
      "(2.25 x {}), module {} (ISO 54), the thread turning {} starts around, {} hand; tip "
      "diameter {}, pitch diameter {}",
      Mm(pitch), FormatNumber(pitch / kPi, 5), Mm(depth), FormatNumber(depth / 2.25, 5),
      FormatNumber(*m), starts, feature.hand == Hand::kRight ? "right" : "left", Mm(2 * tip),
      Mm(feature.pitch_diameter));
  return w;
}

}  // namespace

const std::vector<double>& StandardModules() {
  static const std::vector<double> modules = {
      0.05, 0.06, 0.08, 0.1,  0.12, 0.15, 0.2,  0.25,  0.3,  0.35,  0.4,  0.45, 0.5,  0.55,
      0.6,  0.65, 0.7,  0.75, 0.8,  0.9,  1.0,  1.125, 1.25, 1.375, 1.5,  1.75, 2.0,  2.25,
      2.5,  2.75, 3.0,  3.5,  4.0,  4.5,  5.0,  5.5,   6.0,  7.0,   8.0,  9.0,  10.0, 11.0,
      12.0, 14.0, 16.0, 18.0, 20.0, 22.0, 25.0, 28.0,  32.0, 36.0,  40.0, 45.0, 50.0};
  return modules;
}

MeshFeatures RecognizeFeatures(const TriangleMesh& mesh, MeshRecognition what) {
  MeshFeatures out;
  if (mesh.faces.empty()) {
    out.notes.push_back("no faces");
    return out;
  }
  // Face normals and areas.
  const std::size_t nf = mesh.faces.size();
  std::vector<Vector3d> normal(nf);
  std::vector<double> area(nf);
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  double total = 0.0;
  for (std::size_t f = 0; f < nf; ++f) {
    const auto& t = mesh.faces[f];
    const Vector3d c = (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                           .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
    area[f] = 0.5 * c.norm();
    normal[f] = c.norm() > 0 ? Vector3d(c.normalized()) : Vector3d::Zero();
    M += area[f] * normal[f] * normal[f].transpose();
    total += area[f];
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(M);
  // The extrusion axis: the candidate along or across which the most area faces (ties: the
  // most area along it, the caps).
  Vector3d axis = Vector3d::UnitZ();
  double best_score = -1.0, best_caps = -1.0;
  for (int i = 0; i < 3; ++i) {
    const Vector3d a = Canonical(eigen.eigenvectors().col(i).normalized());
    double caps = 0.0, walls = 0.0;
    for (std::size_t f = 0; f < nf; ++f) {
      const double d = std::abs(normal[f].dot(a));
      if (d > 1 - 1e-4) caps += area[f];
      if (d < 2e-3) walls += area[f];
    }
    const double score = (caps + walls) / total;
    if (score > best_score + 1e-9 || (std::abs(score - best_score) <= 1e-9 && caps > best_caps)) {
      best_score = score, best_caps = caps, axis = a;
    }
  }
  // Cylinders may also lie across other directions (an L-bracket's holes in its two legs, a
  // prism's cross holes): the walls across each principal direction and coordinate axis are
  // searched for circles too. The extrusion axis, when there is one, comes first and alone gets
  // the full analysis (gears, racks, polygons).
  const bool prismatic = best_score >= 0.95;
  if (prismatic) {
    out.axis = axis;
  } else {
    out.notes.push_back(
        fmt::format("not prismatic: no axis along or across which 95% of the area faces (best "
                    "{}%); only cylinders are looked for",
                    FormatNumber(100 * best_score, 3)));
  }
  std::vector<Vector3d> candidates;
  if (prismatic) candidates.push_back(axis);
  std::vector<Vector3d> directions;
  if (what == MeshRecognition::kAll) {
    directions = {Vector3d(eigen.eigenvectors().col(0)), Vector3d(eigen.eigenvectors().col(1)),
                  Vector3d(eigen.eigenvectors().col(2)), Vector3d(Vector3d::UnitX()),
                  Vector3d(Vector3d::UnitY()),           Vector3d(Vector3d::UnitZ())};
    for (const Vector3d& a : CylinderPatchAxes(mesh, normal, area)) directions.push_back(a);
  }
  for (const Vector3d& c : directions) {
    const Vector3d a = Canonical(c.normalized());
    const bool known = std::any_of(candidates.begin(), candidates.end(), [&](const Vector3d& b) {
      return std::abs(a.dot(b)) > 1 - 1e-6;
    });
    if (!known) candidates.push_back(a);
  }
  int holes = 0, shafts = 0;
  bool has_teeth = false;
  for (std::size_t candidate = 0; candidate < candidates.size(); ++candidate) {
    const Vector3d& axis = candidates[candidate];
    const bool full = prismatic && candidate == 0;
    Vector3d u, v;
    std::tie(u, v) = Across(axis);
    auto project = [&](const Vector3d& p) { return Vector2d(p.dot(u), p.dot(v)); };
    double t_min = 1e300, t_max = -1e300;
    for (const Vector3d& p : mesh.vertices) {
      t_min = std::min(t_min, p.dot(axis));
      t_max = std::max(t_max, p.dot(axis));
    }
    const double width = t_max - t_min;
    auto lift = [&](const Vector2d& q, double t) {
      return Vector3d(q.x() * u + q.y() * v + t * axis);
    };
    // A feature of the whole extrusion (teeth, lobes) about the centre `q` of an outline.
    auto through_part = [&](FeatureKind kind, const char* id, const Vector2d& q) {
      RecognizedFeature r;
      r.feature.kind = kind;
      r.feature.id = id;
      r.feature.origin = lift(q, t_min);
      r.feature.axis = axis;
      r.feature.length = width;
      return r;
    };

    // Walls grouped into outlines by shared vertices.
    UnionFind groups(mesh.vertices.size());
    std::vector<std::size_t> walls;
    for (std::size_t f = 0; f < nf; ++f) {
      if (std::abs(normal[f].dot(axis)) >= 2e-3 || area[f] == 0.0) continue;
      walls.push_back(f);
      groups.Join(mesh.faces[f][0], mesh.faces[f][1]);
      groups.Join(mesh.faces[f][0], mesh.faces[f][2]);
    }
    std::vector<int> outline_of(mesh.vertices.size(), -1);
    std::vector<Outline> outlines;
    for (const std::size_t f : walls) {
      const int root = groups.Find(mesh.faces[f][0]);
      if (outline_of[root] < 0) {
        outline_of[root] = static_cast<int>(outlines.size());
        outlines.emplace_back();
      }
      Outline& o = outlines[outline_of[root]];
      const auto& t = mesh.faces[f];
      for (int k = 0; k < 3; ++k) {
        o.lo = std::min(o.lo, mesh.vertices[t[k]].dot(axis));
        o.hi = std::max(o.hi, mesh.vertices[t[k]].dot(axis));
      }
      Vector2d centroid = Vector2d::Zero();
      for (int k = 0; k < 3; ++k) {
        const Vector2d a = project(mesh.vertices[t[k]]), b = project(mesh.vertices[t[(k + 1) % 3]]);
        centroid += a / 3;
        if ((a - b).norm() > 1e-9) o.edges.emplace_back(a, b);
      }
      o.normals.emplace_back(centroid, project(normal[f]));
    }
    // Each outline's distinct projected vertices (a wall's top and bottom edges project onto
    // each other): merged on a 1e-7 mm grid.
    for (Outline& o : outlines) {
      std::vector<std::pair<std::pair<std::int64_t, std::int64_t>, Vector2d>> points;
      for (const auto& [a, b] : o.edges) {
        for (const Vector2d& p : {a, b}) {
          points.push_back({{std::llround(p.x() * 1e7), std::llround(p.y() * 1e7)}, p});
        }
      }
      std::sort(points.begin(), points.end(),
                [](const auto& a, const auto& b) { return a.first < b.first; });
      for (std::size_t i = 0; i < points.size(); ++i) {
        if (i == 0 || points[i].first != points[i - 1].first)
          o.vertices.push_back(points[i].second);
      }
    }
    // Largest outline first (by extent), so that a gear's teeth come before its bore.
    auto extent = [](const Outline& o) {
      Eigen::AlignedBox2d box;
      for (const Vector2d& p : o.vertices) box.extend(p);
      return box.diagonal().norm();
    };
    std::stable_sort(outlines.begin(), outlines.end(),
                     [&](const Outline& a, const Outline& b) { return extent(a) > extent(b); });

    auto id = [&](const std::string& base, int n) {
      return n == 0 ? base : fmt::format("{}_{}", base, n + 1);
    };
    for (const Outline& o : outlines) {
      if (o.vertices.size() < 3) continue;
      const FittedCircle circle = FitCircle(o.vertices);
      // Convex when the walls face away from the centre.
      double facing = 0.0;
      for (const auto& [c, n] : o.normals) facing += n.dot((c - circle.center).normalized());
      const bool convex = facing > 0;
      if (o.vertices.size() >= 12 && circle.rms <= 0.01 * circle.radius &&
          LargestGap(o.vertices, circle.center) <= 40 * kPi / 180) {
        RecognizedFeature r;
        Feature& f = r.feature;
        f.kind = convex ? FeatureKind::kShaft : FeatureKind::kHole;
        if (convex) {
          f.id = id("shaft", shafts++);
        } else {
          f.id = has_teeth && holes == 0 ? "bore" : id("hole", holes);
          ++holes;
        }
        f.origin = lift(circle.center, o.lo);
        f.axis = axis;
        f.length = o.hi - o.lo;
        f.diameter = 2 * circle.radius;
        f.through = !convex;
        r.fit_error = circle.rms;
        r.detail = fmt::format("{} cylinder, diameter {} from {} outline vertices (rms {})",
                               convex ? "convex" : "concave", Mm(f.diameter), o.vertices.size(),
                               Mm(circle.rms));
        out.features.push_back(r);
        continue;
      }
      if (!full) continue;
      // Teeth around a centre: the radius about the outline's centre, over 4096 angles.
      constexpr int kBins = 4096;
      const Vector2d c = circle.center;
      const Profile radial = Sample(
          o, kBins, -kPi, kPi,
          [&](const Vector2d& q) { return std::atan2(q.y() - c.y(), q.x() - c.x()); },
          [&](const Vector2d& q) { return (q - c).norm(); }, true);
      const std::vector<double>& r = convex ? radial.high : radial.low;
      const auto [r_lo, r_hi] = std::minmax_element(r.begin(), r.end());
      const double depth = *r_hi - *r_lo;
      bool gear = false;
      if (depth > 1e-3 * *r_hi) {
        const int z = Dominant(Spectrum(r), 3, 512);
        const double m_raw = depth / 2.25;
        const std::optional<double> m = Standard(m_raw);
        const double tip = convex ? *r_hi : *r_lo;
        const double shift = convex ? tip / m_raw - z / 2.0 - 1.0 : z / 2.0 - 1.0 - tip / m_raw;
        const double mismatch = SelfMismatch(r, static_cast<int>(std::lround(kBins / double(z))));
        if (m && o.vertices.size() >= static_cast<std::size_t>(4 * z) && shift > -1.0 &&
            shift < 1.2 && mismatch < 0.05) {
          gear = true;
          has_teeth = true;
          RecognizedFeature g = through_part(FeatureKind::kGear, "teeth", c);
          Feature& f = g.feature;
          f.teeth = z;
          f.module = *m;
          f.internal = !convex;
          g.fit_error = std::abs(m_raw - *m) * z / 2;
          g.detail = fmt::format(
              "{}, {} teeth (the radius repeats {} times around), tooth depth {} = 2.25 x {}, "
              "module {} (ISO 54), profile shift about {}",
              convex ? "spur gear" : "internal gear", z, z, Mm(depth), FormatNumber(m_raw, 5),
              FormatNumber(*m), FormatNumber(shift, 2));
          out.features.push_back(g);
        }
      }
      if (gear || !convex) continue;
      // A cycloidal disc: lobes that follow the envelope of a ring of one pin more. Its centre
      // is that of the outline's vertices, corrected by the radius' first harmonic (a centre
      // off by d adds d cos(angle - direction) to the radius): the outline is sampled again
      // about it when it may be one.
      const auto disc = [&]() -> std::optional<RecognizedFeature> {
        if (!MayBeCycloid(r, Dominant(Spectrum(r), 3, 512))) return std::nullopt;
        std::complex<double> first = 0.0;
        for (int i = 0; i < kBins; ++i) {
          first += r[i] * std::polar(2.0 / kBins, -kPi + 2 * kPi * (i + 0.5) / kBins);
        }
        const Vector2d centre = c + Vector2d(first.real(), first.imag());
        const std::vector<double> about_centre =
            Sample(
                o, kBins, -kPi, kPi,
                [&](const Vector2d& q) {
                  return std::atan2(q.y() - centre.y(), q.x() - centre.x());
                },
                [&](const Vector2d& q) { return (q - centre).norm(); }, true)
                .high;
        const int lobes = Dominant(Spectrum(about_centre), 3, 512);
        const std::optional<CycloidFit> fit = FitCycloid(about_centre, lobes);
        if (!fit) return std::nullopt;
        RecognizedFeature d = through_part(FeatureKind::kCycloidDisc, "lobes", centre);
        Feature& f = d.feature;
        f.teeth = lobes;
        f.eccentricity = fit->eccentricity;
        d.fit_error = fit->rms;
        d.detail = fmt::format(
            "cycloidal disc, {} lobes (the radius repeats {} times around, from {} to {}): "
            "eccentricity {}, for a ring of {} pins of diameter {} on a {} circle (rms {})",
            lobes, lobes, Mm(fit->rim - fit->eccentricity), Mm(fit->rim + fit->eccentricity),
            Mm(fit->eccentricity), lobes + 1, Mm(2 * fit->pin_radius), Mm(fit->pin_circle),
            Mm(fit->rms));
        return d;
      }();
      if (disc) {
        out.features.push_back(*disc);
        continue;
      }
      // A polygon (a nut's outside): 3 to 8 corners, every one turning the same way.
      if (o.vertices.size() >= 3 && o.vertices.size() <= 8) {
        std::vector<Vector2d> corners = o.vertices;
        std::sort(corners.begin(), corners.end(), [&](const Vector2d& a, const Vector2d& b) {
          return std::atan2(a.y() - circle.center.y(), a.x() - circle.center.x()) <
                 std::atan2(b.y() - circle.center.y(), b.x() - circle.center.x());
        });
        bool turning = true;
        for (std::size_t i = 0; i < corners.size(); ++i) {
          const Vector2d a = corners[(i + 1) % corners.size()] - corners[i];
          const Vector2d b = corners[(i + 2) % corners.size()] - corners[(i + 1) % corners.size()];
          turning = turning && a.x() * b.y() - a.y() * b.x() > 0;
        }
        if (turning) {
          out.polygon_sides = static_cast<int>(corners.size());
          continue;
        }
      }
      // A rack: long, repeating along its length on one side.
      Eigen::Matrix2d C = Eigen::Matrix2d::Zero();
      Vector2d mean = Vector2d::Zero();
      for (const Vector2d& p : o.vertices) mean += p / o.vertices.size();
      for (const Vector2d& p : o.vertices) C += (p - mean) * (p - mean).transpose();
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> pca(C);
      // The rack's axis: its long direction, with its largest world component positive.
      Vector2d e1 = pca.eigenvectors().col(1).normalized();
      if (Canonical(lift(e1, 0.0)).dot(lift(e1, 0.0)) < 0) e1 = -e1;
      const Vector2d e2(-e1.y(), e1.x());
      double s_lo = 1e300, s_hi = -1e300;
      for (const Vector2d& p : o.vertices) {
        s_lo = std::min(s_lo, p.dot(e1));
        s_hi = std::max(s_hi, p.dot(e1));
      }
      constexpr int kRackBins = 4096;
      const Profile side = Sample(
          o, kRackBins, s_lo, s_hi, [&](const Vector2d& q) { return q.dot(e1); },
          [&](const Vector2d& q) { return q.dot(e2); }, false);
      // The toothed side varies; the back is straight. Ends excluded.
      auto variation = [&](const std::vector<double>& s) {
        const auto [lo, hi] =
            std::minmax_element(s.begin() + kRackBins / 20, s.end() - kRackBins / 20);
        return *hi - *lo;
      };
      const bool top = variation(side.high) >= variation(side.low);
      std::vector<double> h = top ? side.high : side.low;
      if (!top) {
        for (double& x : h) x = -x;
      }
      const double h_depth = variation(h);
      const double length = s_hi - s_lo;
      if (h_depth < 1e-3 * length || length < 3 * h_depth) {
        out.notes.push_back(
            fmt::format("an outline of {} vertices is neither a circle, nor gear teeth, nor a rack",
                        o.vertices.size()));
        continue;
      }
      const std::vector<double> spectrum = Spectrum(h);
      const int k = Dominant(spectrum, 2, kRackBins / 8);
      // Refine the frequency between integers by a parabola through the magnitudes.
      const double a0 = spectrum[k - 1], a1 = spectrum[k], a2 = spectrum[k + 1];
      const double denominator = a0 - 2 * a1 + a2;
      const double k_fine = k + (denominator != 0.0 ? 0.5 * (a0 - a2) / denominator : 0.0);
      const double pitch = length / k_fine;
      const double m_pitch = pitch / kPi, m_depth = h_depth / 2.25;
      const std::optional<double> m = Standard(m_pitch);
      if (!m || std::abs(m_depth - *m) > 0.05 * *m) {
        out.notes.push_back(fmt::format(
            "an outline repeats along its length every {} but its pitch and depth give no one "
            "standard module",
            Mm(pitch)));
        continue;
      }
      const double tip = *std::max_element(h.begin() + kRackBins / 20, h.end() - kRackBins / 20);
      RecognizedFeature rack;
      Feature& f = rack.feature;
      f.kind = FeatureKind::kRack;
      f.id = "teeth";
      const Vector2d n2 = top ? e2 : Vector2d(-e2);
      f.origin = lift(s_lo * e1 + (tip - *m) * n2, t_min + width / 2);
      f.axis = lift(e1, 0.0);
      f.normal = lift(n2, 0.0);
      f.length = length;
      f.width = width;
      f.module = *m;
      rack.fit_error = std::abs(m_pitch - *m) * kPi;
      rack.detail = fmt::format(
          "rack, pitch {} = pi x {}, tooth depth {}, module {} (ISO 54), about {} teeth", Mm(pitch),
          FormatNumber(m_pitch, 5), Mm(h_depth), FormatNumber(*m), std::lround(length / pitch));
      out.features.push_back(rack);
      has_teeth = true;
    }
  }
  // A part that is no prism may still be a gear: a helical one, or spur teeth beside a hub.
  if (!prismatic && !has_teeth) {
    for (int i = 0; i < 3 && !has_teeth; ++i) {
      const Vector3d a = Canonical(eigen.eigenvectors().col(i).normalized());
      // A bevel gear first: some of its sections show a standard module's depth too.
      std::optional<RecognizedFeature> gear = SectionBevelGear(mesh, a);
      if (!gear) gear = SectionGear(mesh, a);
      if (!gear) gear = AxialWorm(mesh, a);
      if (gear) {
        out.features.insert(out.features.begin(), std::move(*gear));
        has_teeth = true;
      }
    }
  }
  // Below what a mesh's float coordinates resolve: rounded, so that reports read cleanly.
  auto snap = [](double x, double grid) { return std::round(x / grid) * grid + 0.0; };
  for (RecognizedFeature& r : out.features) {
    Feature& f = r.feature;
    for (int i = 0; i < 3; ++i) {
      f.origin[i] = snap(f.origin[i], 1e-6);
      f.axis[i] = snap(f.axis[i], 1e-12);
      f.normal[i] = snap(f.normal[i], 1e-12);
    }
    f.diameter = snap(f.diameter, 1e-6);
    f.length = snap(f.length, 1e-6);
    f.eccentricity = snap(f.eccentricity, 1e-6);
  }
  return out;
}

}  // namespace mechanist
