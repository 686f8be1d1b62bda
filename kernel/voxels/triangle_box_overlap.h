#pragma once

#include <Eigen/Core>

namespace mechanist {

/// True when the closed triangle abc and the closed axis-aligned box with centre `center` and
/// half extents `half` (all in one frame) share a point: the separating-axis test over the
/// box's three face normals, the triangle's normal and the nine edge cross products
/// (Akenine-Moller, "Fast 3D triangle-box overlap testing", 2001). Conservative: the box is
/// grown by a few ulps of the coordinates' magnitude, so rounding may report a triangle that
/// only touches the box from outside as overlapping, never the other way round. Degenerate
/// triangles (segments, points) are handled by the same axes.
bool TriangleOverlapsBox(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                         const Eigen::Vector3d& c, const Eigen::Vector3d& center,
                         const Eigen::Vector3d& half);

}  // namespace mechanist
