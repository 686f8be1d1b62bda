#include "reasoning/linear_system.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

namespace mechanist {
namespace {

/// Scales so that the largest exact |coefficient| is 1 (the first of equals, in variable
/// order), or, in a row with no exact coefficient, the largest; the rhs with it. Dividing by an
/// approximate coefficient would make the exact ones approximate: a screw's lead row beside a
/// lever arm would lose its exact lead. Returns the largest |coefficient| after scaling.
double Normalise(LinearSystem::Row& terms, ExactReal& rhs) {
  const ExactReal* largest = nullptr;
  for (const LinearSystem::Term& t : terms) {
    const bool better_kind = largest && t.coefficient.is_exact() && !largest->is_exact();
    const bool same_kind = largest && t.coefficient.is_exact() == largest->is_exact();
    if (!largest || better_kind ||
        (same_kind && std::abs(t.coefficient.value()) > std::abs(largest->value()))) {
      largest = &t.coefficient;
    }
  }
  if (!largest) return 0.0;
  const ExactReal scale = largest->value() < 0 ? -*largest : *largest;
  double size = 0.0;
  for (LinearSystem::Term& t : terms) {
    t.coefficient = t.coefficient / scale;
    size = std::max(size, std::abs(t.coefficient.value()));
  }
  rhs = rhs / scale;
  return size;
}

}  // namespace

LinearSystem::LinearSystem(std::size_t variable_count, double tolerance)
    : tolerance_(tolerance),
      parent_(variable_count),
      factor_(variable_count, ExactReal(Rational(1))),
      size_(variable_count, 1),
      in_pivot_(variable_count, false),
      pivot_of_(variable_count, -1) {
  std::iota(parent_.begin(), parent_.end(), std::size_t{0});
}

LinearSystem::Root LinearSystem::Find(std::size_t v) const {
  const std::size_t parent = parent_[v];
  if (parent == v) return {v, ExactReal(Rational(1))};
  // Compressed from the top down (recursion: union by size keeps paths short) so that each
  // factor composes with its parent's final factor.
  const Root top = Find(parent);
  if (parent != top.root) factor_[v] = factor_[v] * factor_[parent];
  parent_[v] = top.root;
  return {top.root, factor_[v]};
}

LinearSystem::Outcome LinearSystem::AddRow(const Row& row, const ExactReal& rhs) {
  // Per root: the sum of its terms, and the largest term summed into it (an approximate sum is
  // zero only relative to what cancelled in it, never for being small: a rate through a long
  // chain of reductions is tiny and exact in its digits). The terms, sorted by root (stably:
  // each root's terms are summed in the row's order), are merged in one pass.
  struct Entry {
    std::size_t root;
    ExactReal sum;
    double largest;
  };
  std::vector<Entry> entries;
  entries.reserve(row.size());
  for (const Term& t : row) {
    const Root r = Find(t.variable);
    ExactReal term = t.coefficient * r.factor;
    const double size = std::abs(term.value());
    entries.push_back({r.root, std::move(term), size});
  }
  std::stable_sort(entries.begin(), entries.end(),
                   [](const Entry& x, const Entry& y) { return x.root < y.root; });
  std::size_t kept = 0;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    if (kept > 0 && entries[kept - 1].root == entries[i].root) {
      entries[kept - 1].sum += entries[i].sum;
      entries[kept - 1].largest = std::max(entries[kept - 1].largest, entries[i].largest);
    } else {
      if (kept != i) entries[kept] = std::move(entries[i]);
      ++kept;
    }
  }
  entries.resize(kept);
  std::erase_if(entries, [&](const Entry& e) { return e.sum.IsZero(tolerance_ * e.largest); });
  Row terms;
  terms.reserve(entries.size());
  for (Entry& e : entries) terms.push_back({e.root, std::move(e.sum)});
  ExactReal b = rhs;
  const double size = Normalise(terms, b);
  if (terms.size() == 2 && b.IsZero(tolerance_ * size)) {
    const Term* x = &terms[0];
    const Term* y = &terms[1];
    if (!in_pivot_[x->variable] && !in_pivot_[y->variable]) {
      // a X + b Y = 0: the smaller group joins the larger one.
      if (size_[x->variable] < size_[y->variable]) std::swap(x, y);
      parent_[y->variable] = x->variable;
      factor_[y->variable] = -(x->coefficient / y->coefficient);
      size_[x->variable] += size_[y->variable];
      ++rank_;
      return Outcome::kIndependent;
    }
  }
  return Eliminate(std::move(terms), b);
}

LinearSystem::Outcome LinearSystem::Eliminate(Row row, ExactReal rhs) {
  std::map<std::size_t, ExactReal> work;
  // Per entry, the largest term summed into it while the row is reduced: what is left of an
  // approximate entry is zero when it is below the tolerance relative to that (cancellation
  // noise grows with the numbers cancelled), never for being small.
  std::map<std::size_t, double> summed;
  for (Term& t : row) {
    work.emplace(t.variable, t.coefficient);
    summed[t.variable] = std::abs(t.coefficient.value());
  }
  double rhs_summed = std::abs(rhs.value());
  for (auto it = work.begin(); it != work.end();) {
    const long p = pivot_of_[it->first];
    if (p < 0) {
      ++it;
      continue;
    }
    const Pivot& pivot = pivots_[static_cast<std::size_t>(p)];
    const ExactReal scale = it->second / pivot.terms.front().coefficient;
    const std::size_t column = it->first;
    for (const Term& t : pivot.terms) {
      const ExactReal change = scale * t.coefficient;
      double& m = summed[t.variable];
      m = std::max(m, std::abs(change.value()));
      work[t.variable] += -change;
    }
    const ExactReal rhs_change = scale * pivot.rhs;
    rhs_summed = std::max(rhs_summed, std::abs(rhs_change.value()));
    rhs += -rhs_change;
    work.erase(column);
    std::erase_if(work,
                  [&](const auto& t) { return t.second.IsZero(tolerance_ * summed[t.first]); });
    it = work.upper_bound(column);
  }
  if (work.empty()) {
    return rhs.IsZero(tolerance_ * rhs_summed) ? Outcome::kRedundant : Outcome::kInconsistent;
  }
  Pivot pivot;
  for (auto& [v, c] : work) {
    pivot.terms.push_back({v, c});
    in_pivot_[v] = true;
  }
  pivot.rhs = rhs;
  pivot_of_[pivot.terms.front().variable] = static_cast<long>(pivots_.size());
  pivots_.push_back(std::move(pivot));
  ++rank_;
  return Outcome::kIndependent;
}

void LinearSystem::BackSubstitute(const std::vector<std::size_t>& columns, bool homogeneous,
                                  std::vector<ExactReal>& x) const {
  for (std::size_t column : columns) {
    const Pivot& pivot = pivots_[static_cast<std::size_t>(pivot_of_[column])];
    ExactReal sum = homogeneous ? ExactReal() : pivot.rhs;
    for (std::size_t i = 1; i < pivot.terms.size(); ++i) {
      sum += -(pivot.terms[i].coefficient * x[pivot.terms[i].variable]);
    }
    x[column] = sum / pivot.terms.front().coefficient;
  }
}

std::vector<ExactReal> LinearSystem::Solve() const {
  std::vector<ExactReal> x(variable_count());
  std::vector<std::size_t> columns;
  for (std::size_t c = variable_count(); c-- > 0;) {
    if (pivot_of_[c] >= 0) columns.push_back(c);
  }
  BackSubstitute(columns, false, x);
  for (std::size_t v = 0; v < x.size(); ++v) {
    const Root r = Find(v);
    if (r.root != v) x[v] = r.factor * x[r.root];
  }
  return x;
}

std::vector<std::size_t> LinearSystem::FreeVariables() const {
  std::vector<std::size_t> free;
  for (std::size_t v = 0; v < variable_count(); ++v) {
    if (parent_[v] == v && pivot_of_[v] < 0) free.push_back(v);
  }
  return free;
}

std::vector<LinearSystem::Row> LinearSystem::NullSpace() const {
  const std::size_t n = variable_count();
  // Components of the eliminated rows, so that each basis vector back-substitutes only the
  // pivots it can reach.
  std::vector<std::size_t> component(n);
  std::iota(component.begin(), component.end(), std::size_t{0});
  auto top = [&](std::size_t v) {
    while (component[v] != v) v = component[v] = component[component[v]];
    return v;
  };
  for (const Pivot& p : pivots_) {
    for (const Term& t : p.terms) component[top(t.variable)] = top(p.terms.front().variable);
  }
  std::map<std::size_t, std::vector<std::size_t>> pivots_in;  // component -> columns, descending
  for (std::size_t c = n; c-- > 0;) {
    if (pivot_of_[c] >= 0) pivots_in[top(c)].push_back(c);
  }
  std::vector<std::vector<std::size_t>> members(n);  // root -> the variables it stands for
  for (std::size_t v = 0; v < n; ++v) members[Find(v).root].push_back(v);

  std::vector<Row> basis;
  std::vector<ExactReal> x(n);
  for (std::size_t f : FreeVariables()) {
    x[f] = ExactReal(Rational(1));
    const auto it = pivots_in.find(top(f));
    static const std::vector<std::size_t> kNone;
    const std::vector<std::size_t>& columns = it == pivots_in.end() ? kNone : it->second;
    for (std::size_t c : columns) x[c] = ExactReal();
    BackSubstitute(columns, true, x);
    Row vector;
    auto emit = [&](std::size_t root) {
      if (x[root].IsZero(tolerance_)) return;
      for (std::size_t v : members[root]) vector.push_back({v, Find(v).factor * x[root]});
    };
    emit(f);
    for (std::size_t c : columns) emit(c);
    std::sort(vector.begin(), vector.end(),
              [](const Term& a, const Term& b) { return a.variable < b.variable; });
    basis.push_back(std::move(vector));
    x[f] = ExactReal();
    for (std::size_t c : columns) x[c] = ExactReal();
  }
  return basis;
}

}  // namespace mechanist
