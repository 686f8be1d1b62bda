#pragma once

// A helical spring's mesh for tests: a round wire swept along a helix, its ends capped.

#include <Eigen/Geometry>
#include <cmath>

#include "kernel/mesh/triangle_mesh.h"

namespace mechanist::testing {

// A round wire of diameter d swept along the helix of radius R and pitch p (t = p angle / 2 pi,
// negated for a left hand) for `turns` turns from z = d / 2, its ends capped.
inline TriangleMesh SpringMesh(double R, double d, double p, double turns, bool right = true) {
  constexpr double kPi = 3.14159265358979323846;
  TriangleMesh mesh;
  constexpr int kAround = 12, kPerTurn = 48;
  const int rings = static_cast<int>(std::lround(turns * kPerTurn)) + 1;
  const double hand = right ? 1 : -1;
  for (int j = 0; j < rings; ++j) {
    const double a = 2 * kPi * j / kPerTurn;
    const Eigen::Vector3d centre(R * std::cos(a), hand * R * std::sin(a),
                                 d / 2 + p * a / (2 * kPi));
    const Eigen::Vector3d radial(std::cos(a), hand * std::sin(a), 0);
    const Eigen::Vector3d tangent =
        Eigen::Vector3d(-R * std::sin(a), hand * R * std::cos(a), p / (2 * kPi)).normalized();
    const Eigen::Vector3d binormal = tangent.cross(radial).normalized();
    for (int k = 0; k < kAround; ++k) {
      const double phi = 2 * kPi * k / kAround;
      mesh.vertices.push_back(centre + d / 2 * (std::cos(phi) * radial + std::sin(phi) * binormal));
    }
  }
  auto at = [&](int j, int k) { return static_cast<std::int32_t>(j * kAround + (k % kAround)); };
  for (int j = 0; j + 1 < rings; ++j) {
    for (int k = 0; k < kAround; ++k) {
      mesh.faces.push_back({at(j, k), at(j + 1, k), at(j + 1, k + 1)});
      mesh.faces.push_back({at(j, k), at(j + 1, k + 1), at(j, k + 1)});
    }
  }
  for (const int j : {0, rings - 1}) {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int k = 0; k < kAround; ++k) centre += mesh.vertices[at(j, k)] / kAround;
    mesh.vertices.push_back(centre);
    const auto middle = static_cast<std::int32_t>(mesh.vertices.size() - 1);
    for (int k = 0; k < kAround; ++k) {
      if (j == 0) {
        mesh.faces.push_back({middle, at(j, k + 1), at(j, k)});
      } else {
        mesh.faces.push_back({middle, at(j, k), at(j, k + 1)});
      }
    }
  }
  return mesh;
}

}  // namespace mechanist::testing
