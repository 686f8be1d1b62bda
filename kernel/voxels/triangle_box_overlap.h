#pragma once

#include <Eigen/Core>
#include <array>

namespace mechanist {

/// The separating-axis test of one closed triangle abc against closed axis-aligned boxes of
/// one size (half extents `half`) whose centres lie at `origin` + offset with |offset| <= half
/// along each axis (all in one frame): the box's three face normals, the triangle's normal and
/// the nine edge cross products (Akenine-Moller, "Fast 3D triangle-box overlap testing",
/// 2001). The axes and the triangle's projections on them are computed once, so testing the
/// eight children of an octree cell costs little more than testing one. Conservative: the box
/// is grown by a few ulps of the coordinates' magnitude, so rounding may report a triangle that
/// only touches the box from outside as overlapping, never the other way round. Degenerate
/// triangles (segments, points) are handled by the same axes.
class TriangleBoxTester {
 public:
  TriangleBoxTester(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                    const Eigen::Vector3d& origin, const Eigen::Vector3d& half);
  /// True when the triangle and the box centred at origin + offset share a point.
  bool Overlaps(const Eigen::Vector3d& offset) const;

 private:
  struct Axis {
    Eigen::Vector3d direction;
    double min = 0, max = 0;  // of the triangle's corners relative to the origin
    double radius = 0;        // of the grown box
  };
  std::array<Axis, 13> axes_;
};

/// True when the closed triangle abc and the closed axis-aligned box with centre `center` and
/// half extents `half` share a point (TriangleBoxTester for a single box).
bool TriangleOverlapsBox(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                         const Eigen::Vector3d& c, const Eigen::Vector3d& center,
                         const Eigen::Vector3d& half);

}  // namespace mechanist
