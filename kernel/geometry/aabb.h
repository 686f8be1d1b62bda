#pragma once

#include <Eigen/Core>
#include <limits>

#include "kernel/geometry/rigid_transform.h"

namespace mechanist {

/// An axis-aligned box in some frame (the frame is in the variable's name: box_W, box_P).
/// Default-constructed boxes are empty (min > max); extending an empty box by a point gives
/// the degenerate box at that point.
struct Aabb {
  Eigen::Vector3d min = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d max = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());

  bool empty() const { return (min.array() > max.array()).any(); }
  void Extend(const Eigen::Vector3d& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  void Extend(const Aabb& other) {
    min = min.cwiseMin(other.min);
    max = max.cwiseMax(other.max);
  }
  Eigen::Vector3d size() const {
    return empty() ? Eigen::Vector3d::Zero() : Eigen::Vector3d(max - min);
  }
  Eigen::Vector3d center() const { return 0.5 * (min + max); }
  /// True when the boxes overlap or touch.
  bool Intersects(const Aabb& other) const {
    return !empty() && !other.empty() && (min.array() <= other.max.array()).all() &&
           (other.min.array() <= max.array()).all();
  }
};

/// The world box of a box given in frame P: box_W = bounds of X_WP applied to box_P's eight
/// corners (the seeds' tight box: computed in the part's frame, then transformed).
Aabb TransformBox(const RigidTransform& X_WP, const Aabb& box_P);

/// True when box_A (in frame A) and box_B (in frame B) overlap once B is placed in A by
/// X_AB, each grown by `margin` (mm) on every side: the separating-axis test of two oriented
/// boxes over their 15 candidate axes (Gottschalk, Lin and Manocha, OBBTree, 1996).
bool BoxesOverlap(const Aabb& box_A, const Aabb& box_B, const RigidTransform& X_AB, double margin);

/// The same test for boxes given by half extents (in frames A and B) and the offset t_A of
/// B's centre from A's centre in A's axes, with B's rotation R_AB and its entrywise absolute
/// value absR_AB (plus a small epsilon against near-parallel edges) precomputed: the inner
/// loop of hierarchy traversals, which test many box pairs under one relative pose.
bool OrientedBoxesOverlap(const Eigen::Vector3d& t_A, const Eigen::Vector3d& half_A,
                          const Eigen::Vector3d& half_B, const Eigen::Matrix3d& R_AB,
                          const Eigen::Matrix3d& absR_AB);

}  // namespace mechanist
