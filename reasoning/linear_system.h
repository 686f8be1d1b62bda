#pragma once

#include <cstddef>
#include <vector>

#include "reasoning/exact_real.h"

namespace mechanist {

/// A sparse linear system A x = b over ExactReal, for mechanism velocities: exact where the
/// coefficients are exact, with `tolerance` deciding zero for approximate values.
///
/// Rows are added one by one and classified on arrival (independent, redundant, or
/// inconsistent), so the caller learns which constraints are implied by earlier ones. Two
/// stages keep it near linear in the size of gear nets: homogeneous rows of two variables
/// (a gear mesh, a coaxial rotation) merge the variables in a weighted union-find (each
/// variable a multiple of its root) while neither root is in an eliminated row; other rows go
/// through sparse Gaussian elimination over the roots, with the smallest column as pivot, in
/// the order the caller numbered the variables (a breadth-first numbering keeps fill-in low).
class LinearSystem {
 public:
  struct Term {
    std::size_t variable;
    ExactReal coefficient;
  };
  using Row = std::vector<Term>;
  enum class Outcome { kIndependent, kRedundant, kInconsistent };

  /// A system of `variable_count` unknowns and no rows. Approximate values with magnitude at
  /// most `tolerance` relative to the terms summed into them are zero. Each row is scaled so
  /// that its largest exact coefficient is 1 (its largest, when none is exact), which keeps
  /// exact coefficients exact beside approximate ones.
  LinearSystem(std::size_t variable_count, double tolerance);

  std::size_t variable_count() const { return parent_.size(); }
  /// Adds sum(row) = rhs. Terms may repeat a variable (they are summed). A redundant row is
  /// implied by the rows before it; an inconsistent one contradicts them and is not kept.
  Outcome AddRow(const Row& row, const ExactReal& rhs = ExactReal());
  /// Rank of the rows kept so far.
  std::size_t rank() const { return rank_; }
  /// variable_count() - rank(): the dimension of the solution space.
  std::size_t nullity() const { return variable_count() - rank_; }

  /// A solution: every free variable zero. Valid when no row was inconsistent.
  std::vector<ExactReal> Solve() const;
  /// A basis of the homogeneous solutions: one sparse vector per free variable, that variable
  /// at 1 and the other free variables at 0.
  std::vector<Row> NullSpace() const;
  /// The free variables, in the order of NullSpace's basis vectors: the freedom each of them
  /// sets at 1 (the others follow it).
  std::vector<std::size_t> FreeVariables() const;

 private:
  struct Pivot {
    Row terms;  // over roots, ascending variable, terms[0] is the pivot
    ExactReal rhs;
  };
  struct Root {
    std::size_t root;
    ExactReal factor;  // variable = factor * root
  };
  Root Find(std::size_t v) const;
  Outcome Eliminate(Row row, ExactReal rhs);
  /// Back substitution over the pivots in `columns` (descending), free variables from `x`;
  /// `homogeneous` takes every right-hand side as zero.
  void BackSubstitute(const std::vector<std::size_t>& columns, bool homogeneous,
                      std::vector<ExactReal>& x) const;

  double tolerance_;
  mutable std::vector<std::size_t> parent_;
  mutable std::vector<ExactReal> factor_;  // variable = factor * parent
  std::vector<std::size_t> size_;
  std::vector<bool> in_pivot_;  // root appears in a pivot row: no longer merged by union-find
  std::vector<long> pivot_of_;  // column -> index into pivots_, or -1
  std::vector<Pivot> pivots_;
  std::size_t rank_ = 0;
};

}  // namespace mechanist
