#include "kernel/mesh/mesh_builder.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace mechanist {

Ring2d CircleRing(const Eigen::Vector2d& center, double radius, int segments) {
  Ring2d ring;
  ring.reserve(static_cast<std::size_t>(std::max(segments, 0)));
  for (int i = 0; i < segments; ++i) {
    Eigen::Vector2d direction;
    if ((4 * i) % segments == 0) {
      // Exactly on the axes at quarter turns (cos(pi) is not exact), so that the polygon's
      // extent is exact and vertices meant to be collinear with others are.
      constexpr double kQuarterTurns[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
      const int quarter = 4 * i / segments;
      direction = {kQuarterTurns[quarter][0], kQuarterTurns[quarter][1]};
    } else {
      const double angle = 2.0 * std::numbers::pi * i / segments;
      direction = {std::cos(angle), std::sin(angle)};
    }
    ring.push_back(center + radius * direction);
  }
  return ring;
}

Ring2d Oriented(Ring2d ring, bool counter_clockwise) {
  if ((SignedArea(ring) > 0.0) != counter_clockwise) std::reverse(ring.begin(), ring.end());
  return ring;
}

MeshBuilder::Indices MeshBuilder::AddRing(const Ring2d& ring, double z) {
  Indices indices;
  indices.reserve(ring.size());
  for (const Eigen::Vector2d& p : ring) {
    indices.push_back(static_cast<std::int32_t>(mesh_.vertices.size()));
    mesh_.vertices.emplace_back(p.x(), p.y(), z);
  }
  return indices;
}

void MeshBuilder::AddTriangle(std::int32_t a, std::int32_t b, std::int32_t c) {
  mesh_.faces.push_back({a, b, c});
}

void MeshBuilder::AddWall(const Indices& lower, const Indices& upper, Diagonal diagonal) {
  if (lower.size() != upper.size() || lower.size() < 3) {
    throw std::invalid_argument(
        fmt::format("MeshBuilder::AddWall: rings of {} and {} vertices; need equal sizes of at "
                    "least 3",
                    lower.size(), upper.size()));
  }
  const std::size_t n = lower.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t l0 = lower[i], l1 = lower[(i + 1) % n];
    const std::int32_t u0 = upper[i], u1 = upper[(i + 1) % n];
    if (diagonal == Diagonal::kForward) {
      AddTriangle(l0, l1, u1);
      AddTriangle(l0, u1, u0);
    } else {
      AddTriangle(l0, l1, u0);
      AddTriangle(l1, u1, u0);
    }
  }
}

void MeshBuilder::AddCap(const Indices& outer, const std::vector<Indices>& holes, bool facing_up) {
  // The triangulator numbers the outer ring's vertices first, then each hole's.
  Indices numbering = outer;
  auto ring_of = [this](const Indices& indices) {
    Ring2d ring;
    ring.reserve(indices.size());
    for (std::int32_t i : indices) ring.push_back(mesh_.vertices[i].head<2>());
    return ring;
  };
  std::vector<Ring2d> hole_rings;
  hole_rings.reserve(holes.size());
  for (const Indices& hole : holes) {
    hole_rings.push_back(ring_of(hole));
    numbering.insert(numbering.end(), hole.begin(), hole.end());
  }
  for (const auto& t : TriangulatePolygon(ring_of(outer), hole_rings)) {
    if (facing_up) {
      AddTriangle(numbering[t[0]], numbering[t[1]], numbering[t[2]]);
    } else {
      AddTriangle(numbering[t[0]], numbering[t[2]], numbering[t[1]]);
    }
  }
}

TriangleMesh ExtrudeRegion(const Region2d& region, double z0, double z1) {
  return ExtrudeTwistedRegion(region, z0, z1, 0.0, 1);
}

TriangleMesh ExtrudeTwistedRegion(const Region2d& region, double z0, double z1, double twist,
                                  int layers) {
  if (!(z0 < z1)) {
    throw std::invalid_argument(fmt::format("ExtrudeTwistedRegion: z0 {} must be below z1 {}",
                                            std::to_string(z0), std::to_string(z1)));
  }
  if (layers < 1) {
    throw std::invalid_argument(fmt::format("ExtrudeTwistedRegion: {} layers", layers));
  }
  MeshBuilder builder;
  // Counter-clockwise outer ring and clockwise holes make every wall face away from the
  // material. Each ring is added at every height, turned, with walls between neighbours.
  auto add_prism_ring = [&](const Ring2d& ring, bool counter_clockwise) {
    const Ring2d oriented = Oriented(ring, counter_clockwise);
    MeshBuilder::Indices lower, first;
    for (int j = 0; j <= layers; ++j) {
      const double z = j == layers ? z1 : z0 + (z1 - z0) * j / layers;
      const Eigen::Rotation2Dd turn(twist * (z - z0));
      Ring2d turned;
      turned.reserve(oriented.size());
      for (const Eigen::Vector2d& p : oriented) turned.push_back(turn * p);
      MeshBuilder::Indices upper = builder.AddRing(turned, z);
      if (j == 0) {
        first = upper;
      } else {
        builder.AddWall(lower, upper);
      }
      lower = std::move(upper);
    }
    return std::pair(std::move(first), std::move(lower));
  };
  const auto [outer_lower, outer_upper] = add_prism_ring(region.outer, true);
  std::vector<MeshBuilder::Indices> holes_lower, holes_upper;
  for (const Ring2d& hole : region.holes) {
    auto [lower, upper] = add_prism_ring(hole, false);
    holes_lower.push_back(std::move(lower));
    holes_upper.push_back(std::move(upper));
  }
  builder.AddCap(outer_lower, holes_lower, /*facing_up=*/false);
  builder.AddCap(outer_upper, holes_upper, /*facing_up=*/true);
  return builder.Release();
}

TriangleMesh MakeRadialGridSolid(const RadialGrid& grid) {
  const int n = grid.angular_segments, m = grid.axial_segments;
  if (n < 3 || m < 1 || !(grid.z0 < grid.z1)) {
    throw std::invalid_argument(
        fmt::format("MakeRadialGridSolid: need at least 3 angular segments ({}), 1 axial segment "
                    "({}) and z0 < z1",
                    n, m));
  }
  const bool bored = grid.bore_radius > 0.0;
  if (bored && grid.bore_segments < 3) {
    throw std::invalid_argument(fmt::format(
        "MakeRadialGridSolid: a bore needs at least 3 segments, not {}", grid.bore_segments));
  }
  MeshBuilder builder;
  MeshBuilder::Indices below;
  MeshBuilder::Indices first;
  for (int j = 0; j <= m; ++j) {
    // The last level is z1 itself rather than z0 plus m steps, so the cap is exactly at z1.
    const double z = j == m ? grid.z1 : grid.z0 + (grid.z1 - grid.z0) * j / m;
    Ring2d ring;
    ring.reserve(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
      const double theta = 2.0 * std::numbers::pi * i / n;
      ring.push_back(grid.radius(theta, z) * Eigen::Vector2d(std::cos(theta), std::sin(theta)));
    }
    MeshBuilder::Indices level = builder.AddRing(ring, z);
    if (j == 0) {
      first = level;
    } else {
      builder.AddWall(below, level, grid.diagonal);
    }
    below = std::move(level);
  }
  std::vector<MeshBuilder::Indices> bore_bottom, bore_top;
  if (bored) {
    const Ring2d bore = Oriented(CircleRing({0.0, 0.0}, grid.bore_radius, grid.bore_segments),
                                 /*counter_clockwise=*/false);
    bore_bottom.push_back(builder.AddRing(bore, grid.z0));
    bore_top.push_back(builder.AddRing(bore, grid.z1));
    builder.AddWall(bore_bottom.front(), bore_top.front());
  }
  builder.AddCap(first, bore_bottom, /*facing_up=*/false);
  builder.AddCap(below, bore_top, /*facing_up=*/true);
  return builder.Release();
}

TriangleMesh MakeUvSphere(double radius, int rings, int segments) {
  if (rings < 2 || segments < 3) {
    throw std::invalid_argument("a UV sphere needs at least 2 rings and 3 segments");
  }
  TriangleMesh m;
  const double pi = std::numbers::pi;
  m.vertices.emplace_back(0, 0, -radius);
  for (int i = 1; i < rings; ++i) {
    const double t = pi * i / rings - pi / 2;
    for (int j = 0; j < segments; ++j) {
      const double p = 2 * pi * j / segments;
      m.vertices.emplace_back(radius * std::cos(t) * std::cos(p),
                              radius * std::cos(t) * std::sin(p), radius * std::sin(t));
    }
  }
  m.vertices.emplace_back(0, 0, radius);
  const auto ring = [&](int i, int j) { return 1 + (i - 1) * segments + (j % segments); };
  for (int j = 0; j < segments; ++j) m.faces.push_back({0, ring(1, j + 1), ring(1, j)});
  for (int i = 1; i + 1 < rings; ++i) {
    for (int j = 0; j < segments; ++j) {
      m.faces.push_back({ring(i, j), ring(i, j + 1), ring(i + 1, j + 1)});
      m.faces.push_back({ring(i, j), ring(i + 1, j + 1), ring(i + 1, j)});
    }
  }
  const int top = static_cast<int>(m.vertices.size()) - 1;
  for (int j = 0; j < segments; ++j) {
    m.faces.push_back({top, ring(rings - 1, j), ring(rings - 1, j + 1)});
  }
  return m;
}

}  // namespace mechanist
