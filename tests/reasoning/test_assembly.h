#pragma once

// Builds small assemblies in code for reasoning tests: unit-cube parts carrying features.

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "kernel/assembly/assembly.h"

namespace mechanist::testing {

inline std::shared_ptr<const TriangleMesh> UnitCube() {
  static const auto cube = [] {
    auto mesh = std::make_shared<TriangleMesh>();
    for (int i = 0; i < 8; ++i) mesh->vertices.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    mesh->faces = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                   {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    return std::shared_ptr<const TriangleMesh>(mesh);
  }();
  return cube;
}

/// Boxes given by their corners (min, max), each a closed shell of the one mesh.
inline std::shared_ptr<const TriangleMesh> Boxes(
    const std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>>& boxes) {
  auto mesh = std::make_shared<TriangleMesh>();
  for (const auto& [lo, hi] : boxes) {
    const auto first = static_cast<std::int32_t>(mesh->vertices.size());
    for (const Eigen::Vector3d& v : UnitCube()->vertices) {
      mesh->vertices.push_back(lo + v.cwiseProduct(hi - lo));
    }
    for (const auto& f : UnitCube()->faces) {
      mesh->faces.push_back({first + f[0], first + f[1], first + f[2]});
    }
  }
  return mesh;
}

/// A feature of `kind` at `origin` along `axis` (normalised), parameters set by `set`.
inline Feature MakeFeature(const std::string& id, FeatureKind kind, Eigen::Vector3d origin,
                           Eigen::Vector3d axis, const std::function<void(Feature&)>& set = {}) {
  Feature f;
  f.id = id;
  f.kind = kind;
  f.origin = origin;
  f.axis = axis.normalized();
  if (set) set(f);
  return f;
}

inline Part MakePart(const std::string& id, std::vector<Feature> features,
                     const RigidTransform& X_WP = RigidTransform(), bool ground = false) {
  Part p;
  p.id = id;
  p.mesh = UnitCube();
  p.mesh_source = "test:cube";
  p.X_WP = X_WP;
  p.ground = ground;
  p.features = std::move(features);
  return p;
}

inline Assembly MakeAssembly(std::vector<Part> parts, std::vector<PairOverride> overrides = {},
                             double friction = 0.1) {
  AssemblySpec spec;
  spec.name = "test";
  spec.parts = std::move(parts);
  spec.overrides = std::move(overrides);
  spec.friction = friction;
  return Assembly(std::move(spec));
}

}  // namespace mechanist::testing
