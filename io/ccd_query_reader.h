#pragma once

#include <Eigen/Core>
#include <array>
#include <filesystem>
#include <vector>

namespace mechanist {

/// One continuous collision query of the Sample-Queries format (../shared/data/ccd): eight
/// points, positions at t = 0 then t = 1 (vertex-face: v, f0, f1, f2; edge-edge: ea0, ea1, eb0,
/// eb1), and the ground truth.
struct CcdQuery {
  bool vertex_face = true;
  std::array<Eigen::Vector3d, 8> points;
  bool colliding = false;
};

/// Reads a query file: 8 rows per query, 7 integer columns (numerator/denominator of x, y and
/// z, then the answer), each value exactly a double. The kind comes from the path
/// ("vertex-face" or "edge-edge"). Throws InputError naming the file and line for anything
/// else.
std::vector<CcdQuery> ReadCcdQueries(const std::filesystem::path& path);

}  // namespace mechanist
