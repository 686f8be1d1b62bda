#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "kernel/assembly/assembly.h"
#include "kernel/assembly/diagnostic.h"
#include "kernel/support/compressed_rows.h"
#include "kernel/support/index_range.h"
#include "reasoning/exact_real.h"
#include "reasoning/linear_system.h"
#include "reasoning/pair.h"
#include "reasoning/pair_graph.h"

namespace mechanist {

/// One velocity unknown: the rate of a joint's freedom (world frame, at the file poses).
/// Rotation and screw rates are revolutions per second, translation rates length units per
/// second; a screw also advances `lead` length units along its axis per revolution.
struct Freedom {
  enum class Kind { kRotation, kTranslation, kScrew };
  Kind kind = Kind::kRotation;
  Eigen::Vector3d point_W = Eigen::Vector3d::Zero();  ///< on the axis (rotation, screw)
  Eigen::Vector3d direction_W = Eigen::Vector3d::UnitZ();
  ExactReal lead;
  std::size_t joint = 0;
};

/// A lower pair between two bodies: twist(body_a) - twist(body_b) is a combination of its
/// freedoms. A floating joint (no pair) lets a body that no pair holds move freely.
struct Joint {
  std::optional<std::size_t> pair;  ///< index into the analysis pairs; empty: floating
  PairType type = PairType::kRevolute;
  std::size_t body_a = 0, body_b = 0;
  /// Unknown indices, when the joint is in the tree: consecutive, so a range rather than a
  /// list (no allocation per joint).
  IndexRange freedoms;
  bool in_tree = false;
  std::size_t child = 0;  ///< in the tree: the body it holds to its parent
  Eigen::Vector3d point_W = Eigen::Vector3d::Zero();  ///< on its axis (or the ball's centre)
  Eigen::Vector3d axis_W = Eigen::Vector3d::UnitZ();  ///< rotation axis, slide or face normal
  Eigen::Vector3d slide_W = Eigen::Vector3d::Zero();  ///< pin_slot: the slot's direction
  ExactReal lead;                                     ///< screw: per revolution of a about axis_W
};

/// A constraint on the unknowns: sum of terms = 0, and the pair it comes from.
struct ConstraintRow {
  LinearSystem::Row terms;
  std::size_t pair = 0;
};

/// The velocity model of an assembly at its file poses: bodies are subassemblies (plus a
/// virtual ground when no part is ground), lower pairs are joints, and the unknowns are the
/// rates of the joints of a breadth-first spanning forest from the ground (joint space, as in
/// Featherstone's and Pinocchio's formulations). Joints off the tree and couplings (gear,
/// worm gear, rack and pinion) are constraint rows; gear and worm rows use Willis' form,
/// relative to a body that carries both axes, so that they are exact in tooth counts.
///
/// Geometry is idealised at the file's tolerance, as recognition does: directions within the
/// angular tolerance of parallel or perpendicular have dot products exactly 1 or 0, and lever
/// arms shorter than the length tolerance are exactly 0. Remaining geometry enters as
/// approximate numbers, so rates are exact exactly when the mechanism's ratios are rational.
class KinematicModel {
 public:
  /// `axes_W`: every feature's world axis at the file's poses, per Assembly::FeatureIndex, as
  /// recognition gives them (Recognition::axes_W); empty: computed here. Throws
  /// std::invalid_argument when given for another number of features.
  KinematicModel(const Assembly& assembly, const std::vector<Pair>& pairs,
                 const std::vector<Subassembly>& subassemblies,
                 const std::vector<std::size_t>& subassembly_of,
                 std::vector<AxisSegment> axes_W = {});

  std::size_t body_count() const { return parent_joint_.size(); }
  std::size_t ground() const { return ground_; }
  /// The body of a part.
  std::size_t body_of_part(std::size_t part) const { return body_of_part_[part]; }
  const std::vector<Freedom>& freedoms() const { return freedoms_; }
  /// The tree joint that holds `body` to its parent; empty for the ground.
  const std::optional<std::size_t>& parent_joint(std::size_t body) const {
    return parent_joint_[body];
  }
  /// Bodies in breadth-first order from the ground: parents before children.
  const std::vector<std::size_t>& order() const { return order_; }
  const std::vector<Joint>& joints() const { return joints_; }
  /// Loop-closure rows of the joints off the tree and coupling rows, ordered by pair.
  const std::vector<ConstraintRow>& rows() const { return rows_; }
  /// Couplings left out of the rows, and why (a worm gear whose axes no body carries).
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }

  /// (twist(a) - twist(b)) as its angular rate (rev/s) about `direction_W`.
  LinearSystem::Row Angular(std::size_t a, std::size_t b, const Eigen::Vector3d& direction_W) const;
  /// (twist(a) - twist(b)) as the velocity of point p_W along `direction_W`.
  LinearSystem::Row Linear(std::size_t a, std::size_t b, const Eigen::Vector3d& p_W,
                           const Eigen::Vector3d& direction_W) const;
  /// The rows that hold body a to body b as joint `j` does (its constraint components).
  std::vector<LinearSystem::Row> JointConstraints(const Joint& j, std::size_t a,
                                                  std::size_t b) const;
  /// A body that carries the feature's axis (rotation axis, or a rack's direction) fixed in
  /// it, common to both features; empty when none does.
  std::optional<std::size_t> CommonCarrier(FeatureRef f, FeatureRef g) const;

  /// The numeric twist of each body for unknown rates `x`: angular velocity (rev/s) and the
  /// velocity of the world origin (length/s).
  void Twists(const std::vector<ExactReal>& x, std::vector<Eigen::Vector3d>& omega_W,
              std::vector<Eigen::Vector3d>& v_WO) const;
  /// The numeric twist of one body, (angular velocity in rev/s; velocity of the world origin),
  /// for the unknown rates `rate(k)`.
  Eigen::Matrix<double, 6, 1> BodyTwist(std::size_t body,
                                        const std::function<double(std::size_t)>& rate) const;
  /// The twist of `body` relative to its parent in the tree (through its parent joint) for
  /// the rates `x`, in world coordinates at the file pose: (rev/s; velocity of the world
  /// origin, mm/s). Zero for the ground.
  Eigen::Matrix<double, 6, 1> RelativeTwist(std::size_t body,
                                            const std::vector<ExactReal>& x) const;
  /// The parent of `body` in the tree, or nothing for the ground.
  std::optional<std::size_t> ParentBody(std::size_t body) const;
  /// The rate of Angular(a, b, direction_W) at the freedoms' rates `x` (the row's terms
  /// summed), without building the row.
  ExactReal AngularRate(std::size_t a, std::size_t b, const Eigen::Vector3d& direction_W,
                        const std::vector<ExactReal>& x) const;
  /// The rate of Linear(a, b, p_W, direction_W) at `x`, without building the row.
  ExactReal LinearRate(std::size_t a, std::size_t b, const Eigen::Vector3d& p_W,
                       const Eigen::Vector3d& direction_W, const std::vector<ExactReal>& x) const;

  /// World axis of a feature at the file pose.
  const AxisSegment& WorldAxis(FeatureRef f) const;
  /// Idealised dot product of unit vectors.
  ExactReal Dot(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;

 private:
  /// Calls sink(freedom, sign * measure of the freedom) for each freedom on the path of body
  /// to the ground.
  template <typename Measure, typename Sink>
  void ForPath(std::size_t body, double sign, const Measure& measure, Sink&& sink) const;
  ExactReal AngularOf(const Freedom& f, const Eigen::Vector3d& d) const;
  /// Appends `scale` times the terms of Angular(a, b, d) to `row`.
  void AppendAngular(LinearSystem::Row& row, std::size_t a, std::size_t b, const Eigen::Vector3d& d,
                     const ExactReal& scale) const;
  ExactReal LinearOf(const Freedom& f, const Eigen::Vector3d& p, const Eigen::Vector3d& d) const;
  void BuildJoints(const std::vector<Pair>& pairs);
  void BuildTree();
  void AddFreedoms(std::size_t joint);
  void BuildRows(const std::vector<Pair>& pairs);
  bool Carries(std::size_t body, FeatureRef f) const;

  const Assembly& assembly_;
  double cos_tol_, sin_tol_, length_tol_;
  std::size_t ground_ = 0;
  std::vector<std::size_t> body_of_part_;
  std::vector<AxisSegment> axes_;  // per Assembly::FeatureIndex
  std::vector<Joint> joints_;
  std::vector<Freedom> freedoms_;
  CompressedRows<std::size_t> joints_of_;                 // per body: its pair joints
  std::vector<std::optional<std::size_t>> parent_joint_;  // per body; empty for roots
  std::vector<std::size_t> order_;                        // bodies, parents first
  std::vector<ConstraintRow> rows_;
  std::vector<Diagnostic> diagnostics_;
};

}  // namespace mechanist
