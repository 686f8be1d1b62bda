#include "kernel/voxels/occupancy_octree.h"

#include <fmt/format.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>

#include "kernel/collision/collision_mesh.h"
#include "kernel/mesh/mesh_check.h"
#include "kernel/mesh/winding_number.h"
#include "kernel/voxels/triangle_box_overlap.h"

namespace mechanist {

namespace {

constexpr int kMaxDepth = 20;

// The groups of a set of octants (bit mask, bits as in OccupancyOctree::OctantSet) that share
// faces: each octant's group (0, 1, ...; -1 for octants not in the set) and their number.
struct OctantGroups {
  std::array<std::int8_t, 8> group;
  int count = 0;
};

const OctantGroups& OctantGroupsOf(std::uint8_t octants) {
  static const std::array<OctantGroups, 256> table = [] {
    std::array<OctantGroups, 256> groups;
    for (int mask = 0; mask < 256; ++mask) {
      OctantGroups& g = groups[mask];
      g.group.fill(-1);
      for (int start = 0; start < 8; ++start) {
        if (!((mask >> start) & 1) || g.group[start] >= 0) continue;
        // Flood the new group over octants that differ in one bit.
        std::array<int, 8> stack;
        int top = 0;
        stack[top++] = start;
        g.group[start] = static_cast<std::int8_t>(g.count);
        while (top > 0) {
          const int o = stack[--top];
          for (int axis = 0; axis < 3; ++axis) {
            const int next = o ^ (1 << axis);
            if (((mask >> next) & 1) && g.group[next] < 0) {
              g.group[next] = static_cast<std::int8_t>(g.count);
              stack[top++] = next;
            }
          }
        }
        ++g.count;
      }
    }
    return groups;
  }();
  return table[octants];
}

// Union-find over node indices with path halving.
std::int32_t FindRoot(std::vector<std::int32_t>& parent, std::int32_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

// A triangle in the world, with its normal (b - a) x (c - a) and its bounds.
struct Triangle {
  std::array<Eigen::Vector3d, 3> p;
  Eigen::Vector3d n, min, max;
  std::int32_t mesh = 0;
};

constexpr int kMaxLines = 4;  // lines per side of a voxel for its Fill, at most
// Crossings of a line this close (in voxels) are at one height when states are sampled: the
// faces where parts meet cross a line at heights rounded differently, most where they slope
// steeply to it.
constexpr double kCoincident = 1e-6;
constexpr int kMaxSamples = kMaxLines * kMaxLines * kMaxLines;
// A Fill's unit, 1/240 of a voxel: 8 bits, and halves to sixteenths are exact.
constexpr int kFillUnit = 240;

// Where a line along an axis crosses a triangle: its coordinate along the axis, and whether
// the triangle faces along the axis (material below the crossing) or against it.
struct Crossing {
  double at = 0.0;
  bool up = false;
  std::int32_t mesh = 0;  // of the triangle
};

// A triangle seen along an axis, for crossing lines along it: each edge's side of a point
// (pu, pv) (u and v the next axes, cyclically) is sign * ((q_u - p_u) (pv - p_v) - (q_v - p_v)
// (pu - p_u)), with the edge's end points p, q in a fixed order so that the two triangles
// sharing an edge compute it alike; a line through an edge is given to one of them (the
// top-left rule of rasterizers), so that a line crosses a closed mesh an even number of times.
struct ProjectedTriangle {
  struct Edge {
    double pu, pv, du, dv, sign;
    bool takes_ties;
  };
  std::array<Edge, 3> edges;

  ProjectedTriangle(const Triangle& t, int axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    const double s = t.n[axis] > 0 ? 1.0 : -1.0;  // counter-clockwise seen from +axis when 1
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d& a = t.p[k];
      const Eigen::Vector3d& b = t.p[(k + 1) % 3];
      const bool swap = a[u] > b[u] || (a[u] == b[u] && a[v] > b[v]);
      const Eigen::Vector3d& p = swap ? b : a;
      const Eigen::Vector3d& q = swap ? a : b;
      const double du = s * (b[u] - a[u]), dv = s * (b[v] - a[v]);
      const bool takes_ties = dv > 0 || (dv == 0 && du < 0);
      edges[k] = {p[u], p[v], q[u] - p[u], q[v] - p[v], swap ? -s : s, takes_ties};
    }
  }

  bool Crosses(double pu, double pv) const {
    for (const Edge& e : edges) {
      const double side = e.sign * (e.du * (pv - e.pv) - e.dv * (pu - e.pu));
      if (side < 0 || (side == 0 && !e.takes_ties)) return false;
    }
    return true;
  }
};

// A voxel's lines along an axis: n x n lines, line (i, j) at lo[u] + (i + 1/2) d,
// lo[v] + (j + 1/2) d (u and v the next axes, cyclically, d = h / n), numbered i + n j.
// The lines in [from, to] along u, as a range of i (empty when first > last).
std::pair<int, int> LinesIn(double from, double to, double lo, double d, int n) {
  const double per_d = 1.0 / d;
  const double first = std::ceil(std::clamp((from - lo) * per_d - 0.5, -1.0, double(n)));
  const double last = std::floor(std::clamp((to - lo) * per_d - 0.5, -1.0, double(n)));
  return {std::max(0, static_cast<int>(first)), std::min(n - 1, static_cast<int>(last))};
}

using LineCrossings = std::array<std::vector<Crossing>, kMaxLines * kMaxLines>;

// The crossings of the voxel [lo, lo + h]^3's lines along `axis` with the triangles, within
// the voxel along it (widened by eps, then clamped to it).
void VoxelLineCrossings(const std::vector<Triangle>& tris, int axis, const Eigen::Vector3d& lo,
                        double h, int n, double eps, LineCrossings& crossings) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const double d = h / n;
  for (auto& c : crossings) c.clear();
  for (const Triangle& t : tris) {
    if (t.n[axis] == 0) continue;  // parallel to the lines
    const auto [i0, i1] = LinesIn(t.min[u], t.max[u], lo[u], d, n);
    const auto [j0, j1] = LinesIn(t.min[v], t.max[v], lo[v], d, n);
    if (i0 > i1 || j0 > j1) continue;
    const ProjectedTriangle projected(t, axis);
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i) {
        const double pu = lo[u] + (i + 0.5) * d, pv = lo[v] + (j + 0.5) * d;
        if (!projected.Crosses(pu, pv)) continue;
        const double at = std::clamp(
            t.p[0][axis] - (t.n[u] * (pu - t.p[0][u]) + t.n[v] * (pv - t.p[0][v])) / t.n[axis],
            t.min[axis], t.max[axis]);
        if (at < lo[axis] - eps || at > lo[axis] + h + eps) continue;
        crossings[i + n * j].push_back(
            {std::clamp(at, lo[axis], lo[axis] + h), t.n[axis] > 0, t.mesh});
      }
    }
  }
}

// Whether a triangle that touches the closed voxel [lo, lo + h]^3 makes it partial: always,
// unless it lies in the plane of one of the voxel's faces (all three corners within eps), where
// only the voxel behind it counts, and only when it covers that face's centre.
bool MakesPartial(const Triangle& t, const Eigen::Vector3d& lo, double h, double eps) {
  for (int a = 0; a < 3; ++a) {
    for (int side = 0; side < 2; ++side) {
      const double plane = lo[a] + side * h;
      if (std::abs(t.p[0][a] - plane) > eps || std::abs(t.p[1][a] - plane) > eps ||
          std::abs(t.p[2][a] - plane) > eps) {
        continue;
      }
      // Behind: the normal points out of the voxel through this face.
      const bool behind = side == 0 ? t.n[a] < 0 : t.n[a] > 0;
      if (!behind) return false;
      Eigen::Vector3d center = lo + Eigen::Vector3d::Constant(h / 2);
      center[a] = plane;
      return TriangleOverlapsBox(t.p[0], t.p[1], t.p[2], center, Eigen::Vector3d::Zero());
    }
  }
  return true;
}

// The empty length of [lo, hi] along a line, from its crossings (sorted here): material lies
// below a crossing that faces up and above one that faces down (several parts may meet at one
// height).
double EmptyLength(std::vector<Crossing>& crossings, double lo, double hi, double eps) {
  std::sort(crossings.begin(), crossings.end(),
            [](const Crossing& x, const Crossing& y) { return x.at < y.at; });
  double empty = 0.0, from = lo;
  bool material_above = false;  // of the previous group of crossings
  for (std::size_t i = 0; i < crossings.size();) {
    bool up = false, down = false;
    const double at = crossings[i].at;
    for (; i < crossings.size() && crossings[i].at <= at + eps; ++i) {
      (crossings[i].up ? up : down) = true;
    }
    if (!material_above && !up) empty += at - from;
    material_above = down;
    from = at;
  }
  if (!material_above) empty += hi - from;
  return empty;
}

// The state (-1 unknown, 0 empty, 1 material) at the voxel's n^3 points at the centres of its
// sub-cubes (index x + n (y + n z)), for the lines that cross no surface: a point takes it from
// the nearest crossing on a line along some axis through it, and shares it with the
// neighbouring points along each axis that no crossing separates from it.
std::array<std::int8_t, kMaxSamples> SampleStates(const std::vector<Triangle>& tris,
                                                  const Eigen::Vector3d& lo, double h, int n,
                                                  double eps, LineCrossings& crossings) {
  const double d = h / n;
  std::array<std::int8_t, kMaxSamples> state;
  state.fill(-1);
  std::array<std::int32_t, kMaxSamples> parent;
  std::iota(parent.begin(), parent.end(), 0);
  const auto find = [&](std::int32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    const std::int32_t step = axis == 0 ? 1 : axis == 1 ? n : n * n;
    VoxelLineCrossings(tris, axis, lo, h, n, eps, crossings);
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const std::vector<Crossing>& line = crossings[i + n * j];
        std::array<int, 3> c;
        c[u] = i;
        c[v] = j;
        for (int k = 0; k < n; ++k) {
          c[axis] = k;
          const std::int32_t at_index = c[0] + n * (c[1] + n * c[2]);
          const double at = lo[axis] + (k + 0.5) * d;
          double nearest = std::numeric_limits<double>::infinity();
          int material = -1;
          bool separated = false;  // from the next point along the line
          for (const Crossing& x : line) {
            const double gap = std::abs(x.at - at);
            // Several at one height (within kCoincident, faces of parts that meet, rounded
            // differently): material.
            if (gap > 0 && gap <= nearest + kCoincident * h) {
              const int m = (x.at > at) == x.up ? 1 : 0;
              material = gap < nearest - kCoincident * h ? m : std::max(material, m);
              nearest = std::min(nearest, gap);
            }
            separated = separated || (x.at >= at && x.at <= at + d);
          }
          state[at_index] = static_cast<std::int8_t>(std::max<int>(state[at_index], material));
          if (k + 1 < n && !separated) {
            const std::int32_t a = find(at_index), b = find(at_index + step);
            parent[std::max(a, b)] = std::min(a, b);
          }
        }
      }
    }
  }
  std::array<std::int8_t, kMaxSamples> shared;
  shared.fill(-1);
  const std::int32_t samples = n * n * n;
  for (std::int32_t x = 0; x < samples; ++x) {
    shared[find(x)] = std::max(shared[find(x)], state[x]);
  }
  for (std::int32_t x = 0; x < samples; ++x) state[x] = shared[find(x)];
  return state;
}

// The state (0 empty, 1 material) at `at` on a line with sorted crossings, off them: as in
// EmptyLength.
int StateAt(const std::vector<Crossing>& crossings, double at, double eps) {
  bool below_down = false, above_up = false;
  double below = -std::numeric_limits<double>::infinity();
  double above = std::numeric_limits<double>::infinity();
  for (const Crossing& c : crossings) {
    if (c.at < at && c.at >= below - eps) {
      below_down = (c.at > below + eps ? false : below_down) || !c.up;
      below = std::max(below, c.at);
    } else if (c.at > at && c.at <= above + eps) {
      above_up = (c.at < above - eps ? false : above_up) || c.up;
      above = std::min(above, c.at);
    }
  }
  return below_down || above_up ? 1 : 0;
}

// A height along `axis` inside the voxel at which no triangle reaches the segment between the
// voxel's lines a and b (neighbours, (i, j) as in LinesIn): below or above all that the
// triangles' heights over the segment, widened by eps, reach; NaN when there is none.
double FreeHeight(const std::vector<Triangle>& tris, int axis, const Eigen::Vector3d& lo, double h,
                  double d, std::pair<int, int> a, std::pair<int, int> b, double eps) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const Eigen::Vector2d pa(lo[u] + (a.first + 0.5) * d, lo[v] + (a.second + 0.5) * d);
  const Eigen::Vector2d pb(lo[u] + (b.first + 0.5) * d, lo[v] + (b.second + 0.5) * d);
  const Eigen::Vector2d min = pa.cwiseMin(pb).array() - eps, max = pa.cwiseMax(pb).array() + eps;
  const double bottom = lo[axis], top = lo[axis] + h;
  double low = top, high = bottom;
  for (const Triangle& t : tris) {
    if (t.max[u] < min[0] || t.min[u] > max[0] || t.max[v] < min[1] || t.min[v] > max[1]) {
      continue;
    }
    double from = t.min[axis], to = t.max[axis];
    if (t.n[axis] != 0) {
      const auto height = [&](const Eigen::Vector2d& q) {
        return t.p[0][axis] -
               (t.n[u] * (q[0] - t.p[0][u]) + t.n[v] * (q[1] - t.p[0][v])) / t.n[axis];
      };
      // The list form: the pair form would return references to the temporaries.
      const auto [lo_h, hi_h] = std::minmax({height(pa), height(pb)});
      from = std::max(from, lo_h);
      to = std::min(to, hi_h);
    }
    low = std::min(low, from - 2 * eps);
    high = std::max(high, to + 2 * eps);
  }
  if (low > bottom) return (bottom + std::min(low, top)) / 2;
  if (high < top) return (std::max(high, bottom) + top) / 2;
  return std::numeric_limits<double>::quiet_NaN();
}

// Buffers reused from voxel to voxel.
struct FillScratch {
  LineCrossings crossings, sample_crossings;
  std::array<LineCrossings, 3> axis_crossings;
  std::vector<Crossing> own_crossings;
};

// Of the voxel [lo, lo + h]^3's `octants`, which no triangle reaches inside, those outside
// each of `meshes` (those that cross the voxel), judged at the 4 x 4 x 4 centres of its
// sub-cubes, each mesh on its own: a centre on a line along an axis takes the mesh's state
// below or above the mesh's nearest crossing of the line, and neighbouring centres on a line
// that the mesh does not cross between them share their state. A line may run inside a mesh
// it does not cross, so an octant with a centre whose state for some mesh stays unknown is
// not taken.
std::uint8_t OutsideEveryMesh(const std::vector<Triangle>& tris,
                              const std::vector<std::int32_t>& meshes, const Eigen::Vector3d& lo,
                              double h, double eps, std::uint8_t octants,
                              std::array<LineCrossings, 3>& crossings, std::vector<Crossing>& own) {
  constexpr int n = kMaxLines;
  const double d = h / n;
  for (int axis = 0; axis < 3; ++axis)
    VoxelLineCrossings(tris, axis, lo, h, n, eps, crossings[axis]);
  std::uint8_t outside = octants;
  for (const std::int32_t mesh : meshes) {
    std::array<std::int8_t, kMaxSamples> state;  // per centre: -1 unknown, 0 outside, 1 inside
    state.fill(-1);
    std::array<int, kMaxSamples> parent;
    std::iota(parent.begin(), parent.end(), 0);
    const auto find = [&](int x) {
      while (parent[x] != x) x = parent[x] = parent[parent[x]];
      return x;
    };
    for (int axis = 0; axis < 3; ++axis) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      const int step = axis == 0 ? 1 : axis == 1 ? n : n * n;
      for (int line = 0; line < n * n; ++line) {
        own.clear();
        for (const Crossing& c : crossings[axis][line]) {
          if (c.mesh == mesh) own.push_back(c);
        }
        std::sort(own.begin(), own.end(),
                  [](const Crossing& x, const Crossing& y) { return x.at < y.at; });
        std::array<int, 3> c;
        c[u] = line % n;
        c[v] = line / n;
        for (int k = 0; k < n; ++k) {
          c[axis] = k;
          const int point = c[0] + n * (c[1] + n * c[2]);
          const double at = lo[axis] + (k + 0.5) * d;
          if (!own.empty()) {
            state[point] = static_cast<std::int8_t>(
                std::max<int>(state[point], StateAt(own, at, kCoincident * h)));
          }
          const bool crossed = std::any_of(own.begin(), own.end(), [&](const Crossing& x) {
            return x.at >= at && x.at <= at + d;
          });
          if (k + 1 < n && !crossed) parent[find(point + step)] = find(point);
        }
      }
    }
    std::array<std::int8_t, kMaxSamples> shared;
    shared.fill(-1);
    for (int x = 0; x < kMaxSamples; ++x) shared[find(x)] = std::max(shared[find(x)], state[x]);
    for (int x = 0; x < kMaxSamples; ++x) {
      if (shared[find(x)] == 0) continue;
      // The octant of centre x: bit a set when its coordinate a is in the high half.
      const int octant =
          (x % n >= n / 2) | ((x / n % n >= n / 2) << 1) | ((x / (n * n) >= n / 2) << 2);
      outside = static_cast<std::uint8_t>(outside & ~(1 << octant));
    }
  }
  return outside;
}

// What the lines through a partial voxel tell: its Fill, and its free octants
// (OccupancyOctree::free_octants): those whose inside no triangle reaches (judged on the
// triangles' planes over the octant's prisms, so a sloping triangle may mark an octant it
// passes by) and that are outside the meshes (for one mesh, the state on a line through the
// octant; for several, OutsideEveryMesh).
struct VoxelContents {
  OccupancyOctree::Fill fill;
  std::uint8_t free_octants = 0;
};

// The contents of the voxel [lo, lo + h]^3 crossed by `tris`, of which those of `meshes`
// (ascending) reach inside it; `one_mesh` when all are of one mesh, whose state its lines
// then tell, else the octants are judged mesh by mesh (OutsideEveryMesh) and the meshes not
// in `meshes` are left to the caller.
VoxelContents VoxelFill(const std::vector<Triangle>& tris, const std::vector<std::int32_t>& meshes,
                        bool one_mesh, const Eigen::Vector3d& lo, double h, double eps,
                        FillScratch& scratch) {
  Eigen::Vector3d facing = Eigen::Vector3d::Zero();
  for (const Triangle& t : tris) facing += t.n.cwiseAbs();
  int axis = 0;
  facing.maxCoeff(&axis);
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  // Lines resolve faces square to the axes exactly but for where they cross; a sloping face
  // costs error in proportion to the lines' spacing anyway, so it gets a quarter of them.
  const bool square = std::all_of(
      tris.begin(), tris.end(), [](const Triangle& t) { return (t.n.array() != 0).count() <= 1; });
  const int n = square ? kMaxLines : kMaxLines / 2;
  const double d = h / n, bottom = lo[axis], top = lo[axis] + h;

  // The heights over which a line's square prism may differ from the line lie between the
  // lowest and the highest that the triangles reaching into the prism span there (a triangle
  // in the prism's side does not reach into it; one square to the axis spans no height).
  std::array<std::pair<double, double>, kMaxLines * kMaxLines> span;
  span.fill({top, bottom});
  // Where the triangles reach into each prism at all, faces square to the axis included.
  std::array<std::pair<double, double>, kMaxLines * kMaxLines> reach;
  reach.fill({top, bottom});
  const double per_d = 1.0 / d;
  const auto prisms = [&](double from, double to, double start) {
    const double first = std::floor(std::clamp((from - start + eps) * per_d, 0.0, double(n)));
    const double last = std::ceil(std::clamp((to - start - eps) * per_d, 0.0, double(n))) - 1;
    return std::make_pair(static_cast<int>(first), std::min(n - 1, static_cast<int>(last)));
  };
  // A triangle in the plane between two prisms reaches into neither, but into the octant that
  // plane cuts (a quarter of the voxel in, when n is 4): both prisms then get its reach.
  const auto reach_prisms = [&](double from, double to, double start) {
    std::pair<int, int> range = prisms(from, to, start);
    if (range.first > range.second && n == 4 && to - from <= 2 * eps) {
      for (const int k : {1, 3}) {
        if (std::abs((from + to) / 2 - start - k * d) <= eps) range = {k - 1, k};
      }
    }
    return range;
  };
  for (const Triangle& t : tris) {
    const auto [i0, i1] = prisms(t.min[u], t.max[u], lo[u]);
    const auto [j0, j1] = prisms(t.min[v], t.max[v], lo[v]);
    const auto [ri0, ri1] = reach_prisms(t.min[u], t.max[u], lo[u]);
    const auto [rj0, rj1] = reach_prisms(t.min[v], t.max[v], lo[v]);
    // The triangle's plane: height = base + gu (u - lo[u]) + gv (v - lo[v]).
    const bool flat = t.n[axis] == 0;
    const double gu = flat ? 0 : -t.n[u] / t.n[axis], gv = flat ? 0 : -t.n[v] / t.n[axis];
    const double base = t.p[0][axis] + gu * (lo[u] - t.p[0][u]) + gv * (lo[v] - t.p[0][v]);
    for (int j = std::min(j0, rj0); j <= std::max(j1, rj1); ++j) {
      for (int i = std::min(i0, ri0); i <= std::max(i1, ri1); ++i) {
        double from = t.min[axis], to = t.max[axis];
        if (!flat) {
          // The plane over the part of the prism the triangle's box covers.
          const double umin = std::max(i * d, t.min[u] - lo[u]);
          const double umax = std::min((i + 1) * d, t.max[u] - lo[u]);
          const double vmin = std::max(j * d, t.min[v] - lo[v]);
          const double vmax = std::min((j + 1) * d, t.max[v] - lo[v]);
          const double low = base + std::min(gu * umin, gu * umax) + std::min(gv * vmin, gv * vmax);
          const double high =
              base + std::max(gu * umin, gu * umax) + std::max(gv * vmin, gv * vmax);
          from = std::max(from, low - eps);
          to = std::min(to, high + eps);
        }
        from = std::max(from, bottom);
        to = std::min(to, top);
        if (to >= from && i >= ri0 && i <= ri1 && j >= rj0 && j <= rj1) {
          auto& [low, high] = reach[i + n * j];
          low = std::min(low, from);
          high = std::max(high, to);
        }
        if (to - from > 2 * eps && i >= i0 && i <= i1 && j >= j0 && j <= j1) {
          auto& [low, high] = span[i + n * j];
          low = std::min(low, from);
          high = std::max(high, to);
        }
      }
    }
  }

  VoxelLineCrossings(tris, axis, lo, h, n, eps, scratch.crossings);
  // Per line: kCrossed, or the state of a line that crosses no surface (-1 while unknown).
  constexpr int kCrossed = 2;
  std::array<int, kMaxLines * kMaxLines> state;
  double empty = 0.0, error = 0.0;  // in line lengths
  for (int line = 0; line < n * n; ++line) {
    std::vector<Crossing>& crossings = scratch.crossings[line];
    state[line] = crossings.empty() ? -1 : kCrossed;
    if (!crossings.empty()) empty += EmptyLength(crossings, bottom, top, eps);
  }
  // A line that crosses no surface has one state, that of its neighbour at a height where no
  // triangle reaches between them; repeated while it decides lines.
  for (bool progress = true; progress;) {
    progress = false;
    for (int line = 0; line < n * n; ++line) {
      if (state[line] >= 0) continue;
      const int i = line % n, j = line / n;
      for (const auto& [di, dj] : {std::pair{-1, 0}, {1, 0}, {0, -1}, {0, 1}}) {
        const int ni = i + di, nj = j + dj, next = ni + n * nj;
        if (ni < 0 || ni >= n || nj < 0 || nj >= n || state[next] < 0) continue;
        const double at = FreeHeight(tris, axis, lo, h, d, {i, j}, {ni, nj}, eps);
        if (std::isnan(at)) continue;
        state[line] =
            state[next] == kCrossed ? StateAt(scratch.crossings[next], at, eps) : state[next];
        progress = true;
        break;
      }
    }
  }
  std::optional<std::array<std::int8_t, kMaxSamples>> samples;
  for (int line = 0; line < n * n; ++line) {
    if (state[line] == kCrossed) continue;
    if (state[line] < 0) {
      // Rare: the points' states shared through the voxel.
      if (!samples) samples = SampleStates(tris, lo, h, n, eps, scratch.sample_crossings);
      std::array<int, 3> c;
      c[u] = line % n;
      c[v] = line / n;
      c[axis] = 0;
      state[line] = (*samples)[c[0] + n * (c[1] + n * c[2])];
    }
    if (state[line] < 0) {
      empty += h / 2;
      error += h / 2;
      span[line] = {top, bottom};
    } else if (state[line] == 0) {
      empty += h;
    }
  }
  for (const auto& [low, high] : span) error += std::max(0.0, high - low);
  const double lines = n * n * h;
  VoxelContents contents;
  contents.fill = {std::clamp(empty / lines, 0.0, 1.0), std::min(error / lines, 1.0)};
  for (int octant = 0; octant < 8; ++octant) {
    const auto high = [&](int a) { return (octant >> a) & 1; };
    // The octant's prisms (one when n is 2, four when 4) and its heights.
    const int i0 = high(u) * (n / 2), j0 = high(v) * (n / 2);
    const double below = bottom + high(axis) * h / 2, above = below + h / 2;
    bool touched = false;
    for (int j = j0; j < j0 + n / 2; ++j) {
      for (int i = i0; i < i0 + n / 2; ++i) {
        const auto [low, high_reach] = reach[i + n * j];
        touched = touched || (low < above - eps && high_reach > below + eps);
      }
    }
    if (touched) continue;
    // Untouched, so one state throughout: for one mesh, that on its first line (the
    // crossings are sorted now, by EmptyLength, as StateAt needs); for several, judged below.
    const double at = (below + above) / 2;
    const int line = i0 + n * j0;
    const int octant_state = state[line] == kCrossed
                                 ? StateAt(scratch.crossings[line], at, kCoincident * h)
                                 : state[line];
    if (!one_mesh || octant_state == 0) {
      contents.free_octants |= static_cast<std::uint8_t>(1 << octant);
    }
  }
  if (!one_mesh && contents.free_octants != 0) {
    contents.free_octants = OutsideEveryMesh(tris, meshes, lo, h, eps, contents.free_octants,
                                             scratch.axis_crossings, scratch.own_crossings);
  }
  return contents;
}

}  // namespace

// Builds the tree top-down: each inner node passes its children the triangles that touch them.
class OctreeBuilder {
 public:
  OctreeBuilder(OccupancyOctree& tree, const std::vector<PosedMesh>& meshes,
                const OccupancyOctree::Progress& progress)
      : tree_(tree), meshes_(meshes), progress_(progress) {}

  void Run(double voxel) {
    if (!(voxel > 0.0) || !std::isfinite(voxel)) {
      throw std::invalid_argument(
          fmt::format("voxel size must be positive and finite, got {}", std::to_string(voxel)));
    }
    tree_.voxel_ = voxel;
    GatherTriangles();
    PrepareInsideTests();
    Aabb bounds;
    for (const auto& v : vertices_) bounds.Extend(v);
    if (bounds.empty()) bounds.Extend(Eigen::Vector3d::Zero());
    // Two voxels of padding on the low side and at least two on the high side: a triangle
    // exactly on a voxel's face touches the voxel on either side, so one voxel is not enough
    // to keep the root's boundary cells untouched.
    tree_.origin_W_ = bounds.min - Eigen::Vector3d::Constant(2 * voxel);
    std::int32_t longest = 1;
    for (int i = 0; i < 3; ++i) {
      const double span = std::floor(bounds.size()[i] / voxel) + 5;
      if (!(span <= double{1 << kMaxDepth})) {
        throw std::invalid_argument(
            fmt::format("voxel size {} mm needs {} voxels along an axis; at most {} are supported",
                        std::to_string(voxel), std::to_string(span), 1 << kMaxDepth));
      }
      tree_.extent_[i] = static_cast<std::int32_t>(span);
      longest = std::max(longest, tree_.extent_[i]);
    }
    while ((std::int32_t{1} << tree_.depth_) < longest) ++tree_.depth_;

    tree_.nodes_.assign(1, 0);
    tree_.fills_.assign(1, 0);
    tree_.free_octants_.assign(1, 0);
    std::vector<std::int32_t> all(triangle_mesh_.size());
    std::iota(all.begin(), all.end(), 0);
    OccupancyOctree::Cell root;
    root.size = tree_.resolution();
    // Sized once: Split holds references into it across its recursion.
    child_tris_.resize(tree_.depth_ + 1);
    Split(root, all, 0);
    child_tris_ = {};
    tree_.nodes_.shrink_to_fit();
    tree_.fills_.shrink_to_fit();
    tree_.free_octants_.shrink_to_fit();
    vertices_ = {};
    triangles_ = {};
    triangle_mesh_ = {};
    Classify();
    if (progress_) progress_(1.0);
  }

 private:
  void GatherTriangles() {
    for (std::size_t m = 0; m < meshes_.size(); ++m) {
      const TriangleMesh* mesh = meshes_[m].mesh;
      const auto offset = static_cast<std::int32_t>(vertices_.size());
      if (mesh == nullptr || mesh->faces.empty()) continue;
      for (const auto& v : mesh->vertices) vertices_.push_back(meshes_[m].X_WM * v);
      for (const auto& f : mesh->faces) {
        triangles_.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
        triangle_mesh_.push_back(static_cast<std::int32_t>(m));
      }
    }
  }

  // Whether each mesh is closed and consistently oriented (closed_), and, for one that is not
  // but bounds a solid (CollisionMesh::solid: cracks, T-junctions; most STEP tessellations), the
  // collision hierarchy that sums its winding number quickly (winding_tree_), once per mesh
  // however many parts share it.
  void PrepareInsideTests() {
    closed_.assign(meshes_.size(), false);
    winding_tree_.assign(meshes_.size(), nullptr);
    std::map<const TriangleMesh*, std::size_t> first_of;  // parts often share one mesh
    for (std::size_t m = 0; m < meshes_.size(); ++m) {
      const TriangleMesh* mesh = meshes_[m].mesh;
      if (mesh == nullptr) continue;
      const auto [it, added] = first_of.try_emplace(mesh, m);
      if (!added) {
        closed_[m] = closed_[it->second];
        winding_tree_[m] = winding_tree_[it->second];
        continue;
      }
      const MeshCheck check = CheckMesh(*mesh);
      closed_[m] = check.closed() && check.consistently_oriented();
      if (closed_[m] || mesh->faces.empty()) continue;
      // Not owning (the aliasing constructor with no owner): the posed meshes outlive the
      // builder.
      const std::shared_ptr<const TriangleMesh> unowned(std::shared_ptr<const TriangleMesh>(),
                                                        mesh);
      auto tree = std::make_unique<CollisionMesh>(unowned);
      if (!tree->solid()) continue;
      winding_tree_[m] = tree.get();
      winding_trees_.push_back(std::move(tree));
    }
  }

  // Whether the generalized winding number of mesh `m` at p_M (its own frame) is at least 1/2
  // in magnitude: by CollisionMesh::Contains where the mesh has a hierarchy, else exactly
  // (WindingNumber). Contains gives the exact sum's answer at the points asked here, which lie
  // off the surface: the hierarchy's sum with the exact sum wherever its error bound could
  // change the answer, or, for a mesh that is closed once coincident vertices are merged (a
  // soup), exact ray crossings, the winding number being an integer off its surface. (Outside
  // the mesh's own box it says outside: the exact sum there stays below 1/2 unless openings in
  // stacked layers of surface line up.)
  bool WindsAround(std::size_t m, const Eigen::Vector3d& p_M) const {
    if (winding_tree_[m] != nullptr) return winding_tree_[m]->Contains(p_M);
    return std::abs(WindingNumber(*meshes_[m].mesh, p_M)) >= 0.5;
  }

  // Fills the subtree of `cell`, whose box the triangles `tris` touch.
  void Split(const OccupancyOctree::Cell& cell, const std::vector<std::int32_t>& tris, int level) {
    auto& word = tree_.nodes_[cell.node];
    if (tris.empty()) {
      word = OccupancyOctree::kLeaf;
      ++tree_.leaves_;
      return;
    }
    if (cell.size == 1) {
      const Eigen::Vector3d lo =
          tree_.origin_W_ + tree_.voxel_ * Eigen::Vector3d(cell.min[0], cell.min[1], cell.min[2]);
      // The same margin as TriangleOverlapsBox's for coordinates of this magnitude.
      const double eps =
          64 * std::numeric_limits<double>::epsilon() * (lo.cwiseAbs().maxCoeff() + tree_.voxel_);
      bool partial = false;
      voxel_tris_.clear();
      for (const std::int32_t t : tris) {
        const auto& f = triangles_[t];
        Triangle tri{
            {vertices_[f[0]], vertices_[f[1]], vertices_[f[2]]}, {}, {}, {}, triangle_mesh_[t]};
        tri.n = (tri.p[1] - tri.p[0]).cross(tri.p[2] - tri.p[0]);
        tri.min = tri.p[0].cwiseMin(tri.p[1]).cwiseMin(tri.p[2]);
        tri.max = tri.p[0].cwiseMax(tri.p[1]).cwiseMax(tri.p[2]);
        partial = partial || MakesPartial(tri, lo, tree_.voxel_, eps);
        voxel_tris_.push_back(tri);
      }
      if (!partial) {
        word = OccupancyOctree::kLeaf;
        ++tree_.leaves_;
        return;
      }
      std::vector<std::int32_t>& touching = touching_;
      touching.clear();
      for (const std::int32_t t : tris) touching.push_back(triangle_mesh_[t]);
      std::sort(touching.begin(), touching.end());
      touching.erase(std::unique(touching.begin(), touching.end()), touching.end());
      // The meshes whose triangles reach inside the voxel, and those that only border it.
      std::vector<std::int32_t>& reaching = reaching_;
      reaching.clear();
      for (const Triangle& t : voxel_tris_) {
        if (((t.min - lo).array() < tree_.voxel_ - eps).all() &&
            ((t.max - lo).array() > eps).all()) {
          reaching.push_back(t.mesh);
        }
      }
      std::sort(reaching.begin(), reaching.end());
      reaching.erase(std::unique(reaching.begin(), reaching.end()), reaching.end());
      VoxelContents contents =
          VoxelFill(voxel_tris_, reaching, touching.size() == 1, lo, tree_.voxel_, eps, scratch_);
      if (contents.free_octants != 0 && reaching.size() < touching.size() &&
          InsideABorderingMesh(touching, reaching, lo, eps)) {
        contents.free_octants = 0;
      }
      const OccupancyOctree::Fill& fill = contents.fill;
      // Rounded to kFillUnit-ths; the error also covers the rounding of the fraction.
      const auto empty = static_cast<std::uint16_t>(std::lround(fill.empty * kFillUnit));
      const auto error = static_cast<std::uint16_t>(
          std::min<double>(kFillUnit, std::ceil(fill.error * kFillUnit + 0.5)));
      tree_.fills_[cell.node] = static_cast<std::uint16_t>(empty | (error << 8));
      tree_.free_octants_[cell.node] = contents.free_octants;
      word = OccupancyOctree::kLeaf | OccupancyOctree::kPartialBit;
      if (touching.size() == 1) {
        word |= static_cast<std::uint32_t>(touching.front());
      } else {
        word |= OccupancyOctree::kListBit | static_cast<std::uint32_t>(tree_.multi_meshes_.size());
        tree_.multi_meshes_.push_back(touching);
      }
      ++tree_.leaves_;
      return;
    }
    const auto first = static_cast<std::uint32_t>(tree_.nodes_.size());
    if (first + 8 > OccupancyOctree::kLeaf) throw std::length_error("octree too large");
    word = first;
    tree_.nodes_.resize(first + 8, 0);
    tree_.fills_.resize(first + 8, 0);
    tree_.free_octants_.resize(first + 8, 0);

    const std::int32_t half = cell.size / 2;
    const double h = tree_.voxel_;
    const Eigen::Vector3d lo =
        tree_.origin_W_ + h * Eigen::Vector3d(cell.min[0], cell.min[1], cell.min[2]);
    const Eigen::Vector3d mid = lo + Eigen::Vector3d::Constant(half * h);
    const Eigen::Vector3d child_half = Eigen::Vector3d::Constant(0.5 * half * h);
    const double margin = 1e-12 * (mid.cwiseAbs().maxCoeff() + cell.size * h);
    // The children's triangle lists, one set per level, reused from node to node.
    auto& child_tris = child_tris_.at(level);
    for (auto& list : child_tris) list.clear();
    for (const std::int32_t t : tris) {
      const auto& f = triangles_[t];
      const Eigen::Vector3d& a = vertices_[f[0]];
      const Eigen::Vector3d& b = vertices_[f[1]];
      const Eigen::Vector3d& c = vertices_[f[2]];
      const Eigen::Vector3d tmin = a.cwiseMin(b).cwiseMin(c);
      const Eigen::Vector3d tmax = a.cwiseMax(b).cwiseMax(c);
      // Which halves the triangle's box reaches along each axis, counting a margin at the
      // mid-plane as both (the separating-axis test then decides, with its own margin); a triangle
      // that reaches one child only touches it for sure.
      int lo_side[3], hi_side[3];
      for (int i = 0; i < 3; ++i) {
        lo_side[i] = tmin[i] <= mid[i] + margin ? 0 : 1;
        hi_side[i] = tmax[i] >= mid[i] - margin ? 1 : 0;
      }
      const bool single =
          lo_side[0] == hi_side[0] && lo_side[1] == hi_side[1] && lo_side[2] == hi_side[2];
      std::optional<TriangleBoxTester> tester;
      if (!single) tester.emplace(a, b, c, mid, child_half);
      for (int z = lo_side[2]; z <= hi_side[2]; ++z) {
        for (int y = lo_side[1]; y <= hi_side[1]; ++y) {
          for (int x = lo_side[0]; x <= hi_side[0]; ++x) {
            const int i = x | (y << 1) | (z << 2);
            const Eigen::Vector3d offset =
                Eigen::Vector3d(2 * x - 1, 2 * y - 1, 2 * z - 1).cwiseProduct(child_half);
            if (tester && !tester->Overlaps(offset)) continue;
            child_tris[i].push_back(t);
          }
        }
      }
    }
    for (int i = 0; i < 8; ++i) {
      const OccupancyOctree::Cell child = OccupancyOctree::Child(cell, first, i);
      Split(child, child_tris[i], level + 1);
      // Progress counts the 64 grandchildren of the root (eight for a root child that is a
      // leaf).
      if (progress_ && level <= 1) {
        if (level == 1) {
          done_ += 1;
        } else if (OccupancyOctree::IsLeaf(tree_.nodes_[child.node])) {
          done_ += 8;
        }
        progress_(0.9 * done_ / 64.0);
      }
    }
  }

  // The state at p_W: full, with the first mesh whose winding number there is at least 1/2
  // in magnitude, or empty (-1).
  std::int32_t StateAt(const Eigen::Vector3d& p_W) const {
    for (std::size_t m = 0; m < meshes_.size(); ++m) {
      if (meshes_[m].mesh == nullptr || !mesh_box_W_[m].Intersects(Aabb{p_W, p_W})) continue;
      const Eigen::Vector3d p_M = meshes_[m].X_WM.inverse() * p_W;
      if (WindsAround(m, p_M)) {
        return static_cast<std::int32_t>(m);
      }
    }
    return -1;
  }

  // Joins untouched leaves that share a face into components and decides each one's state.
  // Leaves near a mesh that is not closed are decided one by one (an opening wider than a
  // voxel joins its inside and outside), joined only to leaves of the same state, and
  // components of equal state that touch are merged afterwards.
  void Classify() {
    auto& nodes = tree_.nodes_;
    mesh_box_W_.resize(meshes_.size());
    std::vector<Aabb> open_box_W;
    for (std::size_t m = 0; m < meshes_.size(); ++m) {
      const TriangleMesh* mesh = meshes_[m].mesh;
      if (mesh == nullptr) continue;
      mesh_box_W_[m] = TransformBox(meshes_[m].X_WM, mesh->Bounds());
      if (!closed_[m]) open_box_W.push_back(mesh_box_W_[m]);
    }
    const auto untouched = [&](std::int32_t node) {
      return OccupancyOctree::IsLeaf(nodes[node]) &&
             (nodes[node] & OccupancyOctree::kPartialBit) == 0;
    };
    // Per leaf: kUnknown, or the state found at its centre (-1 empty, else the mesh).
    constexpr std::int32_t kUnknown = -2;
    std::vector<std::int32_t> known;
    if (!open_box_W.empty()) {
      known.assign(nodes.size(), kUnknown);
      tree_.ForEachLeaf([&](const OccupancyOctree::Cell& cell) {
        if (!untouched(cell.node)) return;
        const Eigen::Vector3d p_W = tree_.Box_W(cell).center();
        for (const Aabb& box : open_box_W) {
          if (box.Intersects(Aabb{p_W, p_W})) {
            known[cell.node] = StateAt(p_W);
            break;
          }
        }
      });
    }
    const auto kind = [&](std::int32_t node) {
      return known.empty() ? kUnknown : std::min<std::int32_t>(known[node], 0);
    };

    std::vector<std::int32_t> parent(nodes.size(), -1);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      if (untouched(static_cast<std::int32_t>(i))) parent[i] = static_cast<std::int32_t>(i);
    }
    // The same pass joins free octants that share a face and lists those that share one with
    // an untouched leaf, to be joined once the leaf's state is known.
    FreeOctants octants = CollectFreeOctants();
    const auto& free = tree_.free_octants_;
    tree_.ForEachFaceNeighbours([&](const auto& a, const auto& b, int axis) {
      const bool a_untouched = untouched(a.node), b_untouched = untouched(b.node);
      if (a_untouched && b_untouched) {
        if (kind(a.node) != kind(b.node)) return;
        const std::int32_t ra = FindRoot(parent, a.node), rb = FindRoot(parent, b.node);
        if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);
        return;
      }
      const std::int32_t ha = octants.holder_of[a.node], hb = octants.holder_of[b.node];
      if (ha < 0 && hb < 0) return;
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      for (int k = 0; k < 4; ++k) {
        // The octants of a on its high side and of b on its low side that meet at the face.
        const int low = ((k & 1) << u) | (((k >> 1) & 1) << v);
        const int high = low | (1 << axis);
        const bool a_free = ha >= 0 && ((free[a.node] >> high) & 1);
        const bool b_free = hb >= 0 && ((free[b.node] >> low) & 1);
        if (a_free && b_free) {
          octants.Join(octants.Element(ha, high), octants.Element(hb, low));
        } else if (a_free && b_untouched) {
          octants.Beside(octants.Element(ha, high), b.node);
        } else if (b_free && a_untouched) {
          octants.Beside(octants.Element(hb, low), a.node);
        }
      }
    });
    octants.holder_of = {};

    // Components in the order of their first leaf, each with its state.
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      if (parent[i] >= 0) parent[i] = FindRoot(parent, static_cast<std::int32_t>(i));
    }
    std::vector<std::int32_t> component_of_root(nodes.size(), -1);
    std::vector<std::int32_t> state;  // -1 empty, else a mesh containing it
    tree_.ForEachLeaf([&](const OccupancyOctree::Cell& cell) {
      if (!untouched(cell.node)) return;
      std::int32_t& id = component_of_root[parent[cell.node]];
      if (id < 0) {
        id = static_cast<std::int32_t>(state.size());
        // The centre of an untouched cell is at least half a voxel from every surface, where
        // the winding number is far from the 1/2 threshold.
        state.push_back(kind(cell.node) == kUnknown ? StateAt(tree_.Box_W(cell).center())
                                                    : known[cell.node]);
      }
    });
    known = {};
    // The first-pass component of each untouched leaf.
    const auto first_pass = [&](std::int32_t node) { return component_of_root[parent[node]]; };

    // Second pass: components of equal state that share a face are one.
    std::vector<std::int32_t> merged(state.size());
    std::iota(merged.begin(), merged.end(), 0);
    if (!open_box_W.empty()) {
      tree_.ForEachFaceNeighbours([&](const auto& a, const auto& b, int) {
        if (!untouched(a.node) || !untouched(b.node)) return;
        const std::int32_t ca = first_pass(a.node), cb = first_pass(b.node);
        if ((state[ca] < 0) != (state[cb] < 0)) return;
        const std::int32_t ra = FindRoot(merged, ca), rb = FindRoot(merged, cb);
        if (ra != rb) merged[std::max(ra, rb)] = std::min(ra, rb);
      });
    }
    JoinFreeOctants(octants, state, first_pass, merged);
    const FreeOctants& free_octants = octants;

    std::vector<std::int32_t> final_id(state.size(), -1);
    const std::int32_t n = tree_.resolution();
    tree_.ForEachLeaf([&](const OccupancyOctree::Cell& cell) {
      if (!untouched(cell.node)) return;
      const std::int32_t first = FindRoot(merged, first_pass(cell.node));
      std::int32_t& id = final_id[first];
      if (id < 0) {
        if (tree_.components_.size() >= OccupancyOctree::kPayload) {
          throw std::length_error("octree has too many components");
        }
        id = static_cast<std::int32_t>(tree_.components_.size());
        OccupancyOctree::Component component;
        component.state = state[first] < 0 ? CellState::kEmpty : CellState::kFull;
        component.mesh = state[first];
        tree_.components_.push_back(component);
      }
      auto& component = tree_.components_[id];
      component.voxels += std::int64_t{cell.size} * cell.size * cell.size;
      for (int i = 0; i < 3; ++i) {
        if (cell.min[i] == 0 || cell.min[i] + cell.size == n) component.exterior = true;
      }
      nodes[cell.node] = OccupancyOctree::kLeaf | static_cast<std::uint32_t>(id);
    });
    // Free octants that reach no untouched cell: thin components, in the order of their first
    // octant.
    const auto first_octant = static_cast<std::int32_t>(state.size());
    constexpr std::int32_t kInside = -2;
    std::vector<std::int32_t> thin_id(merged.size() - state.size(), -1);
    const auto& holders = free_octants.holders;
    for (std::size_t h = 0; h < holders.size(); ++h) {
      for (int octant = 0; octant < 8; ++octant) {
        if (!((holders[h].octants >> octant) & 1)) continue;
        const std::int32_t root = FindRoot(
            merged, first_octant + free_octants.Element(static_cast<std::int32_t>(h), octant));
        if (root < first_octant) continue;  // joined to untouched cells
        std::int32_t& id = thin_id[root - first_octant];
        if (id == kInside) continue;
        if (id < 0 && StateAt(tree_.OctantBox_W(holders[h].cell, octant).center()) >= 0) {
          // Inside another part than the one that crosses its voxels (parts that overlap).
          id = kInside;
          continue;
        }
        if (id < 0) {
          if (tree_.components_.size() >= OccupancyOctree::kPayload) {
            throw std::length_error("octree has too many components");
          }
          id = static_cast<std::int32_t>(tree_.components_.size());
          tree_.components_.emplace_back();
          tree_.thin_octants_.resize(tree_.components_.size());
        }
        auto& sets = tree_.thin_octants_[id];
        if (sets.empty() || sets.back().cell.node != holders[h].cell.node) {
          sets.push_back({holders[h].cell, 0});
        }
        sets.back().octants = static_cast<std::uint8_t>(sets.back().octants | (1 << octant));
      }
    }
    tree_.components_.shrink_to_fit();
  }

  // Whether the voxel at lo (whose triangles are voxel_tris_) lies inside one of the meshes in
  // `touching` but not in `reaching`, which touch it only on its boundary and so are on one
  // side of all of it: told by the normal of one of its triangles in the plane of a face of
  // the voxel (pointing out of the voxel: inside), else by its winding number at the centre.
  bool InsideABorderingMesh(const std::vector<std::int32_t>& touching,
                            const std::vector<std::int32_t>& reaching, const Eigen::Vector3d& lo,
                            double eps) const {
    const double h = tree_.voxel_;
    for (const std::int32_t mesh : touching) {
      if (std::binary_search(reaching.begin(), reaching.end(), mesh)) continue;
      std::optional<bool> inside;
      for (const Triangle& t : voxel_tris_) {
        if (t.mesh != mesh || inside) continue;
        for (int a = 0; a < 3 && !inside; ++a) {
          for (int side = 0; side < 2 && !inside; ++side) {
            const double plane = lo[a] + side * h;
            const int u = (a + 1) % 3, v = (a + 2) % 3;
            // In the plane, over part of the face (not only along its edges).
            if (std::abs(t.min[a] - plane) > eps || std::abs(t.max[a] - plane) > eps ||
                t.n[a] == 0) {
              continue;
            }
            Eigen::Vector3d center = lo + Eigen::Vector3d::Constant(h / 2), half;
            center[a] = plane;
            half[a] = 0;
            half[u] = half[v] = h / 2 - 2 * eps;
            if (!TriangleOverlapsBox(t.p[0], t.p[1], t.p[2], center, half)) continue;
            inside = side == 0 ? t.n[a] < 0 : t.n[a] > 0;
          }
        }
      }
      if (!inside) {
        const Eigen::Vector3d center_M =
            meshes_[mesh].X_WM.inverse() * (lo + Eigen::Vector3d::Constant(h / 2));
        inside = WindsAround(mesh, center_M);
      }
      if (*inside) return true;
    }
    return false;
  }

  // The partial voxels with free octants, in leaf order, and their union-find elements: one
  // per group of free octants that share faces within the voxel (OctantGroupsOf), those of
  // the h-th voxel numbered from first[h] on.
  struct FreeOctants {
    std::vector<OccupancyOctree::OctantSet> holders;
    std::vector<std::int32_t> first;
    std::vector<std::int32_t> holder_of;  // by node, -1 for none
    std::vector<std::int32_t> parent;     // union-find over the elements
    // (element, untouched leaf's node) that share a face, in the order found.
    std::vector<std::pair<std::int32_t, std::int32_t>> beside;

    std::int32_t Element(std::int32_t h, int octant) const {
      return first[h] + OctantGroupsOf(holders[h].octants).group[octant];
    }
    void Join(std::int32_t x, std::int32_t y) {
      const std::int32_t rx = FindRoot(parent, x), ry = FindRoot(parent, y);
      if (rx != ry) parent[std::max(rx, ry)] = std::min(rx, ry);
    }
    void Beside(std::int32_t element, std::int32_t node) {
      if (beside.empty() || beside.back() != std::pair{element, node}) {
        beside.emplace_back(element, node);
      }
    }
  };

  FreeOctants CollectFreeOctants() const {
    const auto& nodes = tree_.nodes_;
    const auto& free = tree_.free_octants_;
    FreeOctants octants;
    octants.holder_of.assign(nodes.size(), -1);
    std::int32_t next = 0;
    tree_.ForEachLeaf([&](const OccupancyOctree::Cell& cell) {
      if ((nodes[cell.node] & OccupancyOctree::kPartialBit) && free[cell.node] != 0) {
        octants.holder_of[cell.node] = static_cast<std::int32_t>(octants.holders.size());
        octants.holders.push_back({cell, free[cell.node]});
        octants.first.push_back(next);
        next += OctantGroupsOf(free[cell.node]).count;
      }
    });
    octants.parent.resize(next);
    std::iota(octants.parent.begin(), octants.parent.end(), 0);
    return octants;
  }

  // Adds the free octants' elements to `merged`, the union-find over the first-pass
  // components (`state`: -1 empty), as state.size() + element, and joins them as the first
  // pass found: to each other, and to the empty untouched leaves they share a face with.
  template <typename FirstPass>
  void JoinFreeOctants(FreeOctants& octants, const std::vector<std::int32_t>& state,
                       const FirstPass& first_pass, std::vector<std::int32_t>& merged) {
    const auto& nodes = tree_.nodes_;
    const auto& holders = octants.holders;
    const auto first_octant = static_cast<std::int32_t>(state.size());
    const auto count = static_cast<std::int32_t>(octants.parent.size());
    if (count == 0) return;
    merged.resize(state.size() + count);
    for (std::int32_t e = 0; e < count; ++e) {
      merged[first_octant + e] = first_octant + FindRoot(octants.parent, e);
    }
    const auto join = [&](std::int32_t x, std::int32_t y) {
      const std::int32_t rx = FindRoot(merged, x), ry = FindRoot(merged, y);
      if (rx != ry) merged[std::max(rx, ry)] = std::min(rx, ry);
    };
    for (const auto& [element, node] : octants.beside) {
      if (state[first_pass(node)] < 0) join(first_octant + element, first_pass(node));
    }
    octants.beside = {};

    // A set of free octants each group of which touches an empty untouched cell (shares a
    // face, an edge or a corner with it) is a pocket of that cell's space that octants are too
    // coarse to join to it (at a gap's rim, in its edges and corners): joined to the first such
    // cell's component.
    const auto beside = [&](const OccupancyOctree::Cell& voxel, std::uint8_t group) {
      for (int octant = 0; octant < 8; ++octant) {
        if (!((group >> octant) & 1)) continue;
        for (const auto& v : OccupancyOctree::VoxelsAroundOctant(voxel, octant)) {
          const OccupancyOctree::Cell near = tree_.Locate(v);
          if (!(nodes[near.node] & OccupancyOctree::kPartialBit) &&
              state[first_pass(near.node)] < 0) {
            return first_pass(near.node);
          }
        }
      }
      return std::int32_t{-1};
    };
    // By root (less first_octant): -2 unseen, -1 not a pocket, else the component to join.
    std::vector<std::int32_t> pocket(count, -2);
    for (std::size_t h = 0; h < holders.size(); ++h) {
      const OctantGroups& groups = OctantGroupsOf(holders[h].octants);
      for (int g = 0; g < groups.count; ++g) {
        const std::int32_t root = FindRoot(merged, first_octant + octants.first[h] + g);
        if (root < first_octant) continue;
        std::int32_t& to = pocket[root - first_octant];
        if (to == -1) continue;
        std::uint8_t group = 0;
        for (int octant = 0; octant < 8; ++octant) {
          if (groups.group[octant] == g) group = static_cast<std::uint8_t>(group | (1 << octant));
        }
        const std::int32_t near = beside(holders[h].cell, group);
        to = near < 0 ? -1 : to == -2 ? near : to;
      }
    }
    for (std::int32_t x = first_octant; x < first_octant + count; ++x) {
      const std::int32_t root = FindRoot(merged, x);
      if (root >= first_octant && pocket[root - first_octant] >= 0) {
        join(x, pocket[root - first_octant]);
      }
    }
  }

  OccupancyOctree& tree_;
  const std::vector<PosedMesh>& meshes_;
  const OccupancyOctree::Progress& progress_;
  std::vector<Eigen::Vector3d> vertices_;
  std::vector<std::array<std::int32_t, 3>> triangles_;
  std::vector<std::int32_t> triangle_mesh_;
  std::vector<Aabb> mesh_box_W_;
  std::vector<bool> closed_;                                   // per mesh (PrepareInsideTests)
  std::vector<const CollisionMesh*> winding_tree_;             // per mesh, or null
  std::vector<std::unique_ptr<CollisionMesh>> winding_trees_;  // owns those
  std::vector<Triangle> voxel_tris_;    // the triangles of the voxel being split, reused
  std::vector<std::int32_t> touching_;  // the meshes touching that voxel, reused
  std::vector<std::int32_t> reaching_;  // those reaching inside it, reused
  std::vector<std::array<std::vector<std::int32_t>, 8>> child_tris_;  // per level, reused
  FillScratch scratch_;
  int done_ = 0;
};

OccupancyOctree OccupancyOctree::Build(const std::vector<PosedMesh>& meshes, double voxel,
                                       const Progress& progress) {
  OccupancyOctree tree;
  OctreeBuilder(tree, meshes, progress).Run(voxel);
  return tree;
}

CellState OccupancyOctree::state(const Cell& cell) const {
  const std::uint32_t word = nodes_[cell.node];
  assert(IsLeaf(word));
  if (word & kPartialBit) return CellState::kPartial;
  return components_[word & kPayload].state;
}

std::int32_t OccupancyOctree::component(const Cell& cell) const {
  const std::uint32_t word = nodes_[cell.node];
  assert(IsLeaf(word));
  if (word & kPartialBit) return -1;
  return static_cast<std::int32_t>(word & kPayload);
}

OccupancyOctree::Fill OccupancyOctree::fill(const Cell& cell) const {
  if (state(cell) != CellState::kPartial) return {};
  const std::uint16_t bits = fills_[cell.node];
  return {(bits & 0xff) / double{kFillUnit}, (bits >> 8) / double{kFillUnit}};
}

std::uint8_t OccupancyOctree::free_octants(const Cell& cell) const {
  return state(cell) == CellState::kPartial ? free_octants_[cell.node] : 0;
}

const std::vector<OccupancyOctree::OctantSet>& OccupancyOctree::thin_octants(
    std::int32_t component) const {
  static const std::vector<OctantSet> kNone;
  const auto c = static_cast<std::size_t>(component);
  return c < thin_octants_.size() ? thin_octants_[c] : kNone;
}

std::vector<std::int32_t> OccupancyOctree::touching_meshes(const Cell& cell) const {
  const std::uint32_t word = nodes_[cell.node];
  if (!IsLeaf(word) || !(word & kPartialBit)) return {};
  if (word & kListBit) return multi_meshes_[word & kPayload];
  return {static_cast<std::int32_t>(word & kPayload)};
}

Aabb OccupancyOctree::OctantBox_W(const Cell& voxel, int octant) const {
  const Eigen::Vector3d lo =
      origin_W_ +
      voxel_ * (Eigen::Vector3d(voxel.min[0], voxel.min[1], voxel.min[2]) +
                0.5 * Eigen::Vector3d(octant & 1, (octant >> 1) & 1, (octant >> 2) & 1));
  return Aabb{lo, lo + Eigen::Vector3d::Constant(voxel_ / 2)};
}

std::array<std::array<std::int32_t, 3>, 8> OccupancyOctree::VoxelsAroundOctant(const Cell& voxel,
                                                                               int octant) {
  std::array<std::array<std::int32_t, 3>, 8> voxels;
  for (int corner = 0; corner < 8; ++corner) {
    voxels[corner] = voxel.min;
    for (int i = 0; i < 3; ++i) {
      if ((corner >> i) & 1) voxels[corner][i] += ((octant >> i) & 1) ? 1 : -1;
    }
  }
  return voxels;
}

Aabb OccupancyOctree::Box_W(const Cell& cell) const {
  const Eigen::Vector3d lo =
      origin_W_ + voxel_ * Eigen::Vector3d(cell.min[0], cell.min[1], cell.min[2]);
  return Aabb{lo, lo + Eigen::Vector3d::Constant(voxel_ * cell.size)};
}

void OccupancyOctree::ForEachLeaf(const std::function<void(const Cell&)>& f) const {
  const std::int32_t n = resolution();
  ForEachLeafIn({0, 0, 0}, {n, n, n}, f);
}

void OccupancyOctree::ForEachLeafIn(const std::array<std::int32_t, 3>& min,
                                    const std::array<std::int32_t, 3>& max,
                                    const std::function<void(const Cell&)>& f) const {
  // Depth first: at most seven siblings wait per level, so the stack never outgrows this.
  std::array<Cell, 7 * kMaxDepth + 1> stack;
  std::size_t top = 0;
  Cell root;
  root.size = resolution();
  stack[top++] = root;
  const auto overlaps = [&](const Cell& c) {
    for (int i = 0; i < 3; ++i) {
      if (c.min[i] >= max[i] || min[i] >= c.min[i] + c.size) return false;
    }
    return true;
  };
  if (!overlaps(root)) return;
  while (top > 0) {
    const Cell c = stack[--top];
    const std::uint32_t word = nodes_[c.node];
    if (IsLeaf(word)) {
      f(c);
      continue;
    }
    for (int i = 7; i >= 0; --i) {
      const Cell child = Child(c, word, i);
      if (overlaps(child)) stack[top++] = child;
    }
  }
}

OccupancyOctree::Cell OccupancyOctree::Locate(const std::array<std::int32_t, 3>& v) const {
  Cell c;
  c.size = resolution();
  while (!IsLeaf(nodes_[c.node])) {
    const std::int32_t half = c.size / 2;
    int i = 0;
    for (int a = 0; a < 3; ++a) {
      if (v[a] >= c.min[a] + half) i |= 1 << a;
    }
    c = Child(c, nodes_[c.node], i);
  }
  return c;
}

std::size_t OccupancyOctree::MemoryBytes() const {
  std::size_t bytes = sizeof(*this) + nodes_.capacity() * sizeof(std::uint32_t) +
                      fills_.capacity() * sizeof(std::uint16_t) + free_octants_.capacity() +
                      components_.capacity() * sizeof(Component) +
                      multi_meshes_.capacity() * sizeof(std::vector<std::int32_t>);
  for (const auto& list : multi_meshes_) bytes += list.capacity() * sizeof(std::int32_t);
  bytes += thin_octants_.capacity() * sizeof(std::vector<OctantSet>);
  for (const auto& sets : thin_octants_) bytes += sets.capacity() * sizeof(OctantSet);
  return bytes;
}

}  // namespace mechanist
