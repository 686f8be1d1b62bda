#include "reasoning/gap_search.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <tuple>

namespace mechanist {

namespace {

// A k-d tree over points, stored implicitly in their order (median splits by nth_element,
// cycling through the axes), with the bounding box of every subtree.
class PointTree {
 public:
  explicit PointTree(std::vector<Eigen::Vector3f> points)
      : points_(std::move(points)), boxes_(points_.size()) {
    Build(0, points_.size(), 0);
  }
  std::size_t size() const { return points_.size(); }
  const Eigen::Vector3f& point(std::size_t i) const { return points_[i]; }
  static std::size_t Mid(std::size_t lo, std::size_t hi) { return lo + (hi - lo) / 2; }
  /// The box of the points [lo, hi), a subtree or a single point (hi = lo + 1).
  const Eigen::AlignedBox3f& Box(std::size_t lo, std::size_t hi) const {
    return boxes_[hi - lo == 1 ? lo : Mid(lo, hi)];
  }

 private:
  void Build(std::size_t lo, std::size_t hi, int axis) {
    if (hi <= lo) return;
    const std::size_t mid = Mid(lo, hi);
    if (hi - lo > 1) {
      std::nth_element(points_.begin() + lo, points_.begin() + mid, points_.begin() + hi,
                       [axis](const Eigen::Vector3f& a, const Eigen::Vector3f& b) {
                         return std::tie(a[axis], a[(axis + 1) % 3], a[(axis + 2) % 3]) <
                                std::tie(b[axis], b[(axis + 1) % 3], b[(axis + 2) % 3]);
                       });
      Build(lo, mid, (axis + 1) % 3);
      Build(mid + 1, hi, (axis + 1) % 3);
    }
    Eigen::AlignedBox3f box(points_[mid]);
    if (mid > lo) box.extend(Box(lo, mid));
    if (hi > mid + 1) box.extend(Box(mid + 1, hi));
    boxes_[mid] = box;
  }

  std::vector<Eigen::Vector3f> points_;
  std::vector<Eigen::AlignedBox3f> boxes_;
};

// A pair of points no farther apart than the closest pair plus `slack` (mm): a dual-tree
// search that skips pairs of subtrees whose boxes cannot bring a pair nearer than the best so
// far by more than the slack (Bentley, 1980).
struct ClosestPair {
  explicit ClosestPair(double slack) : slack(slack) {}
  void Offer(std::size_t i, std::size_t j, double distance2) {
    if (distance2 >= d2) return;
    a = i;
    b = j;
    d2 = distance2;
    const double reach = std::max(0.0, std::sqrt(d2) - slack);
    prune2 = reach * reach;
  }
  double slack = 0;
  std::size_t a = 0, b = 0;
  double d2 = std::numeric_limits<double>::infinity();
  double prune2 = std::numeric_limits<double>::infinity();  // boxes this far apart are skipped
};

void FindClosestPair(const PointTree& ta, std::size_t a_lo, std::size_t a_hi, const PointTree& tb,
                     std::size_t b_lo, std::size_t b_hi, ClosestPair& best) {
  if (a_lo >= a_hi || b_lo >= b_hi) return;
  if (ta.Box(a_lo, a_hi).squaredExteriorDistance(tb.Box(b_lo, b_hi)) >= best.prune2) return;
  if ((a_hi - a_lo) * (b_hi - b_lo) <= 16) {
    for (std::size_t i = a_lo; i < a_hi; ++i) {
      for (std::size_t j = b_lo; j < b_hi; ++j) {
        best.Offer(i, j, (ta.point(i) - tb.point(j)).cast<double>().squaredNorm());
      }
    }
    return;
  }
  // Split the larger side into its point and two subtrees, nearer subtree first.
  const bool split_a = a_hi - a_lo >= b_hi - b_lo;
  const std::size_t lo = split_a ? a_lo : b_lo, hi = split_a ? a_hi : b_hi;
  const std::size_t mid = PointTree::Mid(lo, hi);
  std::pair<std::size_t, std::size_t> parts[3] = {{mid, mid + 1}, {lo, mid}, {mid + 1, hi}};
  const auto distance = [&](const std::pair<std::size_t, std::size_t>& r) {
    if (r.first >= r.second) return std::numeric_limits<float>::infinity();
    return split_a ? ta.Box(r.first, r.second).squaredExteriorDistance(tb.Box(b_lo, b_hi))
                   : tb.Box(r.first, r.second).squaredExteriorDistance(ta.Box(a_lo, a_hi));
  };
  if (distance(parts[2]) < distance(parts[1])) std::swap(parts[1], parts[2]);
  for (const auto& r : parts) {
    if (split_a) {
      FindClosestPair(ta, r.first, r.second, tb, b_lo, b_hi, best);
    } else {
      FindClosestPair(ta, a_lo, a_hi, tb, r.first, r.second, best);
    }
  }
}

}  // namespace

GapSearch FindGaps(const Assembly& assembly, const GapSearchOptions& options) {
  std::vector<PosedMesh> meshes;
  for (const Part& part : assembly.parts()) meshes.push_back({part.mesh.get(), part.X_WP});
  auto octree = std::make_shared<OccupancyOctree>(
      OccupancyOctree::Build(meshes, options.voxel, options.progress));
  const OccupancyOctree& tree = *octree;

  GapSearch result;
  result.voxel = options.voxel;
  result.gap_of_component.assign(tree.components().size(), -1);
  for (std::size_t c = 0; c < tree.components().size(); ++c) {
    const auto& component = tree.components()[c];
    if (component.exterior || component.state != CellState::kEmpty) continue;
    result.gap_of_component[c] = static_cast<std::int32_t>(result.gaps.size());
    Gap gap;
    gap.component = static_cast<std::int32_t>(c);
    gap.voxels = component.voxels;
    result.gaps.push_back(gap);
  }
  if (result.gaps.empty()) {
    result.octree = std::move(octree);
    return result;
  }

  const auto gap_index = [&](const OccupancyOctree::Cell& cell) {
    const std::int32_t c = tree.component(cell);
    return c < 0 ? -1 : result.gap_of_component[c];
  };
  const auto outside = [&](const OccupancyOctree::Cell& cell) {
    const std::int32_t c = tree.component(cell);
    return c >= 0 && tree.components()[c].exterior;
  };

  // From the leaves' face adjacency: the partial voxels next to the outside and to each gap
  // (their centres, each once), the gap leaves next to a wall, and the enclosing parts.
  std::vector<Eigen::Vector3f> outside_walls;
  std::vector<bool> next_to_outside(tree.node_count(), false);
  std::vector<std::vector<Eigen::Vector3f>> gap_walls(result.gaps.size());
  std::vector<std::vector<std::size_t>> parts(result.gaps.size());
  std::vector<std::pair<std::int32_t, OccupancyOctree::Cell>> rim;
  tree.ForEachFaceNeighbours(
      [&](const OccupancyOctree::Cell& a, const OccupancyOctree::Cell& b, int) {
        const bool a_partial = tree.state(a) == CellState::kPartial;
        const bool b_partial = tree.state(b) == CellState::kPartial;
        if (a_partial == b_partial) return;
        const OccupancyOctree::Cell& air = a_partial ? b : a;
        const OccupancyOctree::Cell& wall = a_partial ? a : b;
        const Eigen::Vector3f p = tree.Box_W(wall).center().cast<float>();
        if (outside(air)) {
          if (!next_to_outside[wall.node]) outside_walls.push_back(p);
          next_to_outside[wall.node] = true;
          return;
        }
        const std::int32_t g = gap_index(air);
        if (g < 0) return;
        gap_walls[g].push_back(p);
        rim.emplace_back(g, air);
        for (const std::int32_t m : tree.touching_meshes(wall)) {
          parts[g].push_back(static_cast<std::size_t>(m));
        }
      });
  tree.ForEachLeaf([&](const OccupancyOctree::Cell& cell) {
    const std::int32_t g = gap_index(cell);
    if (g >= 0) result.gaps[g].box_W.Extend(tree.Box_W(cell));
  });
  // The partial voxels among the 26 neighbours of the gap's voxels: it suffices to look
  // around the gap leaves that touch a wall, since a partial voxel diagonal to a gap voxel
  // is face-adjacent to it or to a gap voxel that touches a wall.
  std::sort(rim.begin(), rim.end(), [](const auto& x, const auto& y) {
    return std::tie(x.first, x.second.node) < std::tie(y.first, y.second.node);
  });
  rim.erase(std::unique(rim.begin(), rim.end(),
                        [](const auto& x, const auto& y) {
                          return x.first == y.first && x.second.node == y.second.node;
                        }),
            rim.end());
  std::vector<std::pair<std::int32_t, std::int32_t>> walls;  // (gap, partial node)
  for (const auto& [g, cell] : rim) {
    std::array<std::int32_t, 3> lo, hi;
    for (int i = 0; i < 3; ++i) {
      lo[i] = cell.min[i] - 1;
      hi[i] = cell.min[i] + cell.size + 1;
    }
    tree.ForEachLeafIn(lo, hi, [&, g = g](const OccupancyOctree::Cell& near) {
      if (tree.state(near) == CellState::kPartial) walls.emplace_back(g, near.node);
    });
  }
  // A thin gap (free octants only): its octants stand in for the empty cells, their centres
  // for the faces, and the partial voxels that touch an octant (its own and those around its
  // outer corner) are its walls.
  for (std::size_t g = 0; g < result.gaps.size(); ++g) {
    for (const OccupancyOctree::OctantSet& set : tree.thin_octants(result.gaps[g].component)) {
      for (int octant = 0; octant < 8; ++octant) {
        if (!((set.octants >> octant) & 1)) continue;
        const Aabb box = tree.OctantBox_W(set.cell, octant);
        result.gaps[g].box_W.Extend(box);
        gap_walls[g].push_back(box.center().cast<float>());
        for (const auto& v : OccupancyOctree::VoxelsAroundOctant(set.cell, octant)) {
          const OccupancyOctree::Cell near = tree.Locate(v);
          if (tree.state(near) != CellState::kPartial) continue;
          walls.emplace_back(static_cast<std::int32_t>(g), near.node);
          for (const std::int32_t m : tree.touching_meshes(near)) {
            parts[g].push_back(static_cast<std::size_t>(m));
          }
        }
      }
    }
  }
  std::sort(walls.begin(), walls.end());
  walls.erase(std::unique(walls.begin(), walls.end()), walls.end());
  std::vector<OccupancyOctree::Fill> wall_fill(result.gaps.size());  // summed, in voxels
  for (const auto& [g, node] : walls) {
    ++result.gaps[g].boundary_voxels;
    OccupancyOctree::Cell wall;  // the node is all a partial voxel's fill needs
    wall.node = node;
    const OccupancyOctree::Fill fill = tree.fill(wall);
    wall_fill[g].empty += fill.empty;
    wall_fill[g].error += fill.error;
  }

  // Closest approach: the nearest pair of a partial voxel next to the gap (or a thin gap's
  // octant) and one next to the outside.
  const PointTree outside_tree(std::move(outside_walls));
  for (std::size_t g = 0; g < result.gaps.size(); ++g) {
    Gap& gap = result.gaps[g];
    std::vector<Eigen::Vector3f>& points = gap_walls[g];
    std::sort(points.begin(), points.end(), [](const Eigen::Vector3f& x, const Eigen::Vector3f& y) {
      return std::tie(x[0], x[1], x[2]) < std::tie(y[0], y[1], y[2]);
    });
    points.erase(std::unique(points.begin(), points.end()), points.end());
    const PointTree gap_tree(std::move(points));
    // Half a voxel of slack: the centres stand for the surfaces only to within that anyway.
    ClosestPair best(options.voxel / 2);
    FindClosestPair(gap_tree, 0, gap_tree.size(), outside_tree, 0, outside_tree.size(), best);
    if (std::isfinite(best.d2)) {
      gap.p_gap_W = gap_tree.point(best.a).cast<double>();
      gap.p_outside_W = outside_tree.point(best.b).cast<double>();
      gap.wall = std::sqrt(best.d2);
    }
  }

  const double h3 = options.voxel * options.voxel * options.voxel;
  for (std::size_t g = 0; g < result.gaps.size(); ++g) {
    Gap& gap = result.gaps[g];
    std::sort(parts[g].begin(), parts[g].end());
    parts[g].erase(std::unique(parts[g].begin(), parts[g].end()), parts[g].end());
    gap.parts = std::move(parts[g]);
    gap.volume = (static_cast<double>(gap.voxels) + wall_fill[g].empty) * h3;
    gap.volume_error = wall_fill[g].error * h3;
  }

  // Number the gaps largest first; the mapping from components follows.
  std::vector<std::size_t> order(result.gaps.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    const Gap& a = result.gaps[x];
    const Gap& b = result.gaps[y];
    if (a.volume != b.volume) return a.volume > b.volume;
    const auto key = [](const Gap& g) {
      return std::make_tuple(g.box_W.min.z(), g.box_W.min.y(), g.box_W.min.x(), g.component);
    };
    return key(a) < key(b);
  });
  std::vector<Gap> sorted;
  for (const std::size_t i : order) {
    result.gap_of_component[result.gaps[i].component] = static_cast<std::int32_t>(sorted.size());
    sorted.push_back(std::move(result.gaps[i]));
  }
  result.gaps = std::move(sorted);
  result.octree = std::move(octree);
  return result;
}

TriangleMesh GapSurface(const GapSearch& search, std::vector<std::int32_t>* gap_of_face) {
  TriangleMesh mesh;
  if (gap_of_face) gap_of_face->clear();
  if (!search.octree) return mesh;
  const OccupancyOctree& tree = *search.octree;
  auto gap = [&](const OccupancyOctree::Cell& cell) {
    const std::int32_t c = tree.component(cell);
    return c < 0 ? -1 : search.gap_of_component[c];
  };
  tree.ForEachFaceNeighbours([&](const OccupancyOctree::Cell& a, const OccupancyOctree::Cell& b,
                                 int axis) {
    const std::int32_t ga = gap(a), gb = gap(b);
    if ((ga >= 0) == (gb >= 0)) return;  // neighbouring cells of one gap, or no gap
    // The shared face is the smaller cell's, at b's low side along `axis`.
    const OccupancyOctree::Cell& small = a.size < b.size ? a : b;
    const int v = (axis + 1) % 3, w = (axis + 2) % 3;
    auto corner = [&](std::int32_t dv, std::int32_t dw) {
      std::array<std::int32_t, 3> c = small.min;
      c[axis] = b.min[axis];
      c[v] += dv;
      c[w] += dw;
      return Eigen::Vector3d(tree.origin_W() + tree.voxel() * Eigen::Vector3d(c[0], c[1], c[2]));
    };
    const auto first = static_cast<std::int32_t>(mesh.vertices.size());
    const std::int32_t n = small.size;
    mesh.vertices.push_back(corner(0, 0));
    mesh.vertices.push_back(corner(n, 0));
    mesh.vertices.push_back(corner(n, n));
    mesh.vertices.push_back(corner(0, n));
    // Counter-clockwise about +axis (e_v x e_w = e_axis) when the gap is on the low side.
    if (ga >= 0) {
      mesh.faces.push_back({first, first + 1, first + 2});
      mesh.faces.push_back({first, first + 2, first + 3});
    } else {
      mesh.faces.push_back({first, first + 2, first + 1});
      mesh.faces.push_back({first, first + 3, first + 2});
    }
    if (gap_of_face) gap_of_face->insert(gap_of_face->end(), 2, ga >= 0 ? ga : gb);
  });

  // Thin gaps: the faces of their free octants that no other octant of the same gap shares.
  for (std::size_t g = 0; g < search.gaps.size(); ++g) {
    const auto& sets = tree.thin_octants(search.gaps[g].component);
    std::map<std::int32_t, std::uint8_t> octants_of;  // by node
    for (const auto& set : sets) octants_of[set.cell.node] = set.octants;
    const auto holds = [&](const std::array<std::int32_t, 3>& voxel, int octant) {
      const auto it = octants_of.find(tree.Locate(voxel).node);
      return it != octants_of.end() && ((it->second >> octant) & 1);
    };
    for (const auto& set : sets) {
      for (int octant = 0; octant < 8; ++octant) {
        if (!((set.octants >> octant) & 1)) continue;
        const Aabb box = tree.OctantBox_W(set.cell, octant);
        for (int axis = 0; axis < 3; ++axis) {
          for (const bool high : {false, true}) {
            const int next = octant ^ (1 << axis);
            const bool within_voxel = ((octant >> axis) & 1) != static_cast<int>(high);
            std::array<std::int32_t, 3> voxel = set.cell.min;
            voxel[axis] += high ? 1 : -1;
            if (within_voxel ? ((set.octants >> next) & 1) != 0 : holds(voxel, next)) continue;
            const int v = (axis + 1) % 3, w = (axis + 2) % 3;
            const auto first = static_cast<std::int32_t>(mesh.vertices.size());
            for (const auto& [dv, dw] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}}) {
              Eigen::Vector3d p;
              p[axis] = high ? box.max[axis] : box.min[axis];
              p[v] = dv ? box.max[v] : box.min[v];
              p[w] = dw ? box.max[w] : box.min[w];
              mesh.vertices.push_back(p);
            }
            // Facing away from the octant: counter-clockwise about +axis on its high side.
            if (high) {
              mesh.faces.push_back({first, first + 1, first + 2});
              mesh.faces.push_back({first, first + 2, first + 3});
            } else {
              mesh.faces.push_back({first, first + 2, first + 1});
              mesh.faces.push_back({first, first + 3, first + 2});
            }
            if (gap_of_face)
              gap_of_face->insert(gap_of_face->end(), 2, static_cast<std::int32_t>(g));
          }
        }
      }
    }
  }
  return mesh;
}

}  // namespace mechanist
