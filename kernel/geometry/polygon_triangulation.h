#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

namespace mechanist {

/// A closed polygonal ring in a plane: its vertices in order, the closing edge implied.
using Ring2d = std::vector<Eigen::Vector2d>;

/// Signed area of `ring` by the shoelace formula: positive when the ring runs
/// counter-clockwise (x right, y up). Units are those of the coordinates squared.
double SignedArea(const Ring2d& ring);

/// Triangulates the simple polygon `outer` with the holes `holes` by ear clipping, as in the
/// earcut algorithm (Mapbox): holes are processed from left to right, each bridged to the outer
/// ring by a pair of coincident edges from its leftmost vertex to a vertex the ray toward -x
/// sees, then ears are cut off the single resulting ring.
///
/// Either orientation of every ring is accepted. Holes must lie strictly inside the outer ring
/// and apart from each other. Vertices are numbered outer ring first, then each hole in order;
/// every vertex is used and none is added, so a triangulated face stays welded to neighbouring
/// faces that share its boundary vertices. Unlike earcut, collinear vertices are kept (removing
/// one would leave a crack next to a face that uses it); no ear is cut at a corner within
/// 1e-10 rad of straight, so no triangle has zero area.
///
/// Returns n + 2h - 2 triangles for n vertices and h holes, each counter-clockwise.
/// Throws std::invalid_argument when a ring has fewer than three vertices or no area, a hole
/// is outside the outer ring, or no ear can be cut (rings that cross or touch).
std::vector<std::array<std::int32_t, 3>> TriangulatePolygon(const Ring2d& outer,
                                                            const std::vector<Ring2d>& holes = {});

}  // namespace mechanist
