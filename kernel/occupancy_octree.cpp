#include "kernel/occupancy_octree.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>

#include "kernel/mesh_check.h"
#include "kernel/triangle_box_overlap.h"
#include "kernel/winding_number.h"

namespace mechanist {

namespace {

constexpr int kMaxDepth = 20;

// Union-find over node indices with path halving.
std::int32_t FindRoot(std::vector<std::int32_t>& parent, std::int32_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
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
      throw std::invalid_argument("voxel size must be positive and finite, got " +
                                  std::to_string(voxel));
    }
    tree_.voxel_ = voxel;
    GatherTriangles();
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
        throw std::invalid_argument("voxel size " + std::to_string(voxel) + " mm needs " +
                                    std::to_string(span) + " voxels along an axis; at most " +
                                    std::to_string(1 << kMaxDepth) + " are supported");
      }
      tree_.extent_[i] = static_cast<std::int32_t>(span);
      longest = std::max(longest, tree_.extent_[i]);
    }
    while ((std::int32_t{1} << tree_.depth_) < longest) ++tree_.depth_;

    tree_.nodes_.assign(1, 0);
    std::vector<std::int32_t> all(triangle_mesh_.size());
    std::iota(all.begin(), all.end(), 0);
    OccupancyOctree::Cell root;
    root.size = tree_.resolution();
    Split(root, all, 0);
    tree_.nodes_.shrink_to_fit();
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

  // Fills the subtree of `cell`, whose box the triangles `tris` touch.
  void Split(const OccupancyOctree::Cell& cell, const std::vector<std::int32_t>& tris, int level) {
    auto& word = tree_.nodes_[cell.node];
    if (tris.empty()) {
      word = OccupancyOctree::kLeaf;
      ++tree_.leaves_;
      return;
    }
    if (cell.size == 1) {
      std::vector<std::int32_t> touching;
      for (const std::int32_t t : tris) touching.push_back(triangle_mesh_[t]);
      std::sort(touching.begin(), touching.end());
      touching.erase(std::unique(touching.begin(), touching.end()), touching.end());
      word = OccupancyOctree::kLeaf | OccupancyOctree::kPartialBit;
      if (touching.size() == 1) {
        word |= static_cast<std::uint32_t>(touching.front());
      } else {
        word |= OccupancyOctree::kListBit | static_cast<std::uint32_t>(tree_.multi_meshes_.size());
        tree_.multi_meshes_.push_back(std::move(touching));
      }
      ++tree_.leaves_;
      return;
    }
    const auto first = static_cast<std::uint32_t>(tree_.nodes_.size());
    if (first + 8 > OccupancyOctree::kLeaf) throw std::length_error("octree too large");
    word = first;
    tree_.nodes_.resize(first + 8, 0);

    const std::int32_t half = cell.size / 2;
    const double h = tree_.voxel_;
    const Eigen::Vector3d lo =
        tree_.origin_W_ + h * Eigen::Vector3d(cell.min[0], cell.min[1], cell.min[2]);
    const Eigen::Vector3d mid = lo + Eigen::Vector3d::Constant(half * h);
    const Eigen::Vector3d child_half = Eigen::Vector3d::Constant(0.5 * half * h);
    const double margin = 1e-12 * (mid.cwiseAbs().maxCoeff() + cell.size * h);
    std::array<std::vector<std::int32_t>, 8> child_tris;
    for (const std::int32_t t : tris) {
      const auto& f = triangles_[t];
      const Eigen::Vector3d& a = vertices_[f[0]];
      const Eigen::Vector3d& b = vertices_[f[1]];
      const Eigen::Vector3d& c = vertices_[f[2]];
      const Eigen::Vector3d tmin = a.cwiseMin(b).cwiseMin(c);
      const Eigen::Vector3d tmax = a.cwiseMax(b).cwiseMax(c);
      // Which halves the triangle's box reaches along each axis, counting a margin at the
      // mid-plane as both (TriangleOverlapsBox then decides, with its own margin); a triangle
      // that reaches one child only touches it for sure.
      int lo_side[3], hi_side[3];
      for (int i = 0; i < 3; ++i) {
        lo_side[i] = tmin[i] <= mid[i] + margin ? 0 : 1;
        hi_side[i] = tmax[i] >= mid[i] - margin ? 1 : 0;
      }
      const bool single =
          lo_side[0] == hi_side[0] && lo_side[1] == hi_side[1] && lo_side[2] == hi_side[2];
      for (int z = lo_side[2]; z <= hi_side[2]; ++z) {
        for (int y = lo_side[1]; y <= hi_side[1]; ++y) {
          for (int x = lo_side[0]; x <= hi_side[0]; ++x) {
            const int i = x | (y << 1) | (z << 2);
            if (!single) {
              const Eigen::Vector3d center =
                  lo + Eigen::Vector3d(x * half * h, y * half * h, z * half * h) + child_half;
              if (!TriangleOverlapsBox(a, b, c, center, child_half)) continue;
            }
            child_tris[i].push_back(t);
          }
        }
      }
    }
    for (int i = 0; i < 8; ++i) {
      const OccupancyOctree::Cell child = OccupancyOctree::Child(cell, first, i);
      std::vector<std::int32_t> own = std::move(child_tris[i]);
      Split(child, own, level + 1);
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
      if (std::abs(WindingNumber(*meshes_[m].mesh, p_M)) >= 0.5) {
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
    std::map<const TriangleMesh*, bool> closed;  // parts often share one mesh
    for (std::size_t m = 0; m < meshes_.size(); ++m) {
      const TriangleMesh* mesh = meshes_[m].mesh;
      if (mesh == nullptr) continue;
      mesh_box_W_[m] = TransformBox(meshes_[m].X_WM, mesh->Bounds());
      auto [it, inserted] = closed.try_emplace(mesh, false);
      if (inserted) {
        const MeshCheck check = CheckMesh(*mesh);
        it->second = check.closed() && check.consistently_oriented();
      }
      if (!it->second) open_box_W.push_back(mesh_box_W_[m]);
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
    tree_.ForEachFaceNeighbours([&](const auto& a, const auto& b, int) {
      if (!untouched(a.node) || !untouched(b.node) || kind(a.node) != kind(b.node)) return;
      const std::int32_t ra = FindRoot(parent, a.node), rb = FindRoot(parent, b.node);
      if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);
    });

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
    tree_.components_.shrink_to_fit();
  }

  OccupancyOctree& tree_;
  const std::vector<PosedMesh>& meshes_;
  const OccupancyOctree::Progress& progress_;
  std::vector<Eigen::Vector3d> vertices_;
  std::vector<std::array<std::int32_t, 3>> triangles_;
  std::vector<std::int32_t> triangle_mesh_;
  std::vector<Aabb> mesh_box_W_;
  int done_ = 0;
};

OccupancyOctree OccupancyOctree::Build(const std::vector<PosedMesh>& meshes, double voxel,
                                       const Progress& progress) {
  OccupancyOctree tree;
  OctreeBuilder(tree, meshes, progress).Run(voxel);
  return tree;
}

OccupancyOctree::Cell OccupancyOctree::Child(const Cell& parent, std::uint32_t first, int i) {
  Cell c;
  c.node = static_cast<std::int32_t>(first) + i;
  c.size = parent.size / 2;
  for (int a = 0; a < 3; ++a) c.min[a] = parent.min[a] + ((i >> a) & 1) * c.size;
  return c;
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

std::vector<std::int32_t> OccupancyOctree::touching_meshes(const Cell& cell) const {
  const std::uint32_t word = nodes_[cell.node];
  if (!IsLeaf(word) || !(word & kPartialBit)) return {};
  if (word & kListBit) return multi_meshes_[word & kPayload];
  return {static_cast<std::int32_t>(word & kPayload)};
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

void OccupancyOctree::CellProc(const Cell& c,
                               const std::function<void(const Cell&, const Cell&, int)>& f) const {
  const std::uint32_t word = nodes_[c.node];
  if (IsLeaf(word)) return;
  for (int i = 0; i < 8; ++i) CellProc(Child(c, word, i), f);
  for (int axis = 0; axis < 3; ++axis) {
    for (int i = 0; i < 8; ++i) {
      if ((i >> axis) & 1) continue;
      FaceProc(Child(c, word, i), Child(c, word, i | (1 << axis)), axis, f);
    }
  }
}

void OccupancyOctree::FaceProc(const Cell& a, const Cell& b, int axis,
                               const std::function<void(const Cell&, const Cell&, int)>& f) const {
  const std::uint32_t wa = nodes_[a.node], wb = nodes_[b.node];
  if (IsLeaf(wa) && IsLeaf(wb)) {
    f(a, b, axis);
    return;
  }
  // The four children pairs across the shared face: a's children on its high side, b's on
  // its low side, matched by the other two bits.
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  for (int k = 0; k < 4; ++k) {
    const int bits = (((k >> 0) & 1) << u) | (((k >> 1) & 1) << v);
    const Cell ca = IsLeaf(wa) ? a : Child(a, wa, bits | (1 << axis));
    const Cell cb = IsLeaf(wb) ? b : Child(b, wb, bits);
    FaceProc(ca, cb, axis, f);
  }
}

void OccupancyOctree::ForEachFaceNeighbours(
    const std::function<void(const Cell&, const Cell&, int)>& f) const {
  Cell root;
  root.size = resolution();
  CellProc(root, f);
}

void OccupancyOctree::ForEachLeafIn(const std::array<std::int32_t, 3>& min,
                                    const std::array<std::int32_t, 3>& max,
                                    const std::function<void(const Cell&)>& f) const {
  std::vector<Cell> stack;
  Cell root;
  root.size = resolution();
  stack.push_back(root);
  const auto overlaps = [&](const Cell& c) {
    for (int i = 0; i < 3; ++i) {
      if (c.min[i] >= max[i] || min[i] >= c.min[i] + c.size) return false;
    }
    return true;
  };
  if (!overlaps(root)) return;
  while (!stack.empty()) {
    const Cell c = stack.back();
    stack.pop_back();
    const std::uint32_t word = nodes_[c.node];
    if (IsLeaf(word)) {
      f(c);
      continue;
    }
    for (int i = 7; i >= 0; --i) {
      const Cell child = Child(c, word, i);
      if (overlaps(child)) stack.push_back(child);
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
                      components_.capacity() * sizeof(Component) +
                      multi_meshes_.capacity() * sizeof(std::vector<std::int32_t>);
  for (const auto& list : multi_meshes_) bytes += list.capacity() * sizeof(std::int32_t);
  return bytes;
}

}  // namespace mechanist
