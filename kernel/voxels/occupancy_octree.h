#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "kernel/geometry/aabb.h"
#include "kernel/geometry/rigid_transform.h"
#include "kernel/mesh/triangle_mesh.h"

namespace mechanist {

/// A mesh placed in the world for a decomposition: X_WM maps its vertices to world (mm).
struct PosedMesh {
  const TriangleMesh* mesh = nullptr;
  RigidTransform X_WM;
};

/// What a cell of the decomposition holds.
enum class CellState : std::uint8_t {
  kEmpty,    ///< no material: no surface crosses the cell and it is outside every mesh
  kFull,     ///< material: no surface crosses the cell and it is inside a mesh
  kPartial,  ///< a surface crosses the cell (voxel-sized cells only)
};

/// The decomposition of space around a set of posed meshes into an octree of cubic cells, the
/// finest of them voxels of a given size (mm): a cell that no triangle touches is a leaf, full
/// or empty as a whole; a cell that a triangle touches is split down to voxels, which are
/// partial. The meshes' union is decomposed at once (a cell is full when it is inside any mesh).
/// Memory grows with the surface area over the voxel size squared, not with the box's volume.
///
/// Grid: voxel (i, j, k) is the world box origin_W() + voxel() * [i, i+1) x [j, j+1) x
/// [k, k+1), for 0 <= i, j, k < resolution(); the root cube leaves at least one voxel of empty
/// space around the meshes, so every cell that touches the root's boundary is empty.
///
/// Classification. Cells touched by a triangle are found by a separating-axis test grown by a
/// few ulps (TriangleOverlapsBox), so that a surface can never slip between cells. A triangle
/// that lies in the plane of a voxel's face (to within those ulps: CAD faces on round
/// coordinates) meets neither voxel beside it inside; it makes partial only the voxel behind it
/// (against its normal, in the material), and only when it covers that face's centre: the voxel
/// in front stays untouched, and no two untouched cells meet at a face that surfaces cover whole
/// (a face covered in part still joins one region). Untouched cells that share a face form
/// connected components; no surface passes between two cells of one component, so a component is
/// all full or all empty, and one point of it decides: full when the generalized winding number
/// of some mesh there is at least 1/2 in magnitude. For a closed mesh this is the exact inside
/// test. A mesh with cracks, T-junctions or missing faces (common in CAD exports; CheckMesh finds
/// boundary or misoriented edges) may let its inside and outside join through an opening wider
/// than a voxel, so inside its bounding box every untouched cell is decided by the winding number
/// at its own centre (near 1 inside a part with a hole) and only cells of equal state are joined;
/// components of equal state that touch are merged afterwards. Such a mesh's winding number is
/// summed over its collision hierarchy when it bounds a solid (CollisionMesh::Contains: the
/// exact sum's answer), else exactly.
///
/// Free octants. A partial voxel's octants (half-size cubes) that no surface enters and that
/// lie outside the parts are free (free_octants()); they join each other and the empty
/// untouched cells they share a face with, so that space one to two voxels thick, which holds
/// no whole voxel, still connects. Free octants that reach no untouched cell form thin
/// components (thin_octants()), except for a pocket whose every group of octants touches an
/// empty untouched cell (joined to it: space at a gap's rim that octants are too coarse to
/// join) and one that lies inside a part where parts overlap (dropped; told by the winding
/// number of every part at one of its octants).
class OccupancyOctree {
 public:
  /// A leaf cell: the voxel box [min, min + size) (size a power of two) and its node.
  struct Cell {
    std::int32_t node = 0;
    std::array<std::int32_t, 3> min = {0, 0, 0};
    std::int32_t size = 1;
  };
  /// Octants of a partial voxel: bit x | y << 1 | z << 2 for the octant on the high (1) or
  /// low (0) side of the voxel's middle along each axis.
  struct OctantSet {
    Cell cell;
    std::uint8_t octants = 0;
  };
  /// A connected set of untouched cells and free octants (see the class comment); a thin
  /// component has free octants only (voxels 0).
  struct Component {
    CellState state = CellState::kEmpty;
    /// For a full component, the index (into the meshes given to Build) of a mesh containing it.
    std::int32_t mesh = -1;
    /// True when it touches the root's boundary (it is then the outside, or part of it).
    bool exterior = false;
    std::int64_t voxels = 0;  ///< its volume in voxels
  };
  /// The empty part of a partial voxel: the fraction `empty` in [0, 1] of its volume that lies
  /// outside every mesh, within `error` of the true fraction. Along the axis where the voxel's
  /// triangles face most, 4 x 4 lines through it (2 x 2 when a triangle slopes across the
  /// axes) are cut exactly where they cross the triangles, each crossing's normal telling the
  /// material below it from the air above; a line that crosses none takes the state of a
  /// neighbouring line at a height no triangle reaches between them. The fraction is the mean
  /// empty length. Each line stands for its square prism, which can differ from it only
  /// between the lowest and the highest that the triangles reaching into the prism span there:
  /// a face square to the axis or lying in a prism's side adds no error, a sloping face about
  /// its slope times the lines' spacing per prism. Stored in 240ths of a voxel, the error
  /// rounded up to cover the rounding of both.
  struct Fill {
    double empty = 0.0;
    double error = 0.0;
  };
  /// Reports build progress as a fraction in [0, 1].
  using Progress = std::function<void(double)>;

  /// Decomposes the union of `meshes` at `voxel` mm. Throws std::invalid_argument when voxel is
  /// not positive and finite or when the grid would need more than 2^20 voxels along an axis.
  static OccupancyOctree Build(const std::vector<PosedMesh>& meshes, double voxel,
                               const Progress& progress = {});

  double voxel() const { return voxel_; }
  const Eigen::Vector3d& origin_W() const { return origin_W_; }
  int depth() const { return depth_; }
  /// Voxels along each side of the root cube, 2^depth().
  std::int32_t resolution() const { return std::int32_t{1} << depth_; }
  /// Voxel extent of the meshes' bounding box plus one voxel each side (within resolution()).
  const std::array<std::int32_t, 3>& extent() const { return extent_; }

  CellState state(const Cell& cell) const;
  /// The component of an untouched cell, or -1 for a partial cell.
  std::int32_t component(const Cell& cell) const;
  const std::vector<Component>& components() const { return components_; }
  /// The free octants of a partial voxel: those no surface reaches inside, outside the meshes
  /// that cross the voxel (where meshes overlap, possibly inside another); 0 for other cells.
  /// A sloping face is judged by its plane over the octant, so it may take an octant it passes
  /// by. Where one mesh crosses the voxel, its fill lines tell the state; where several do,
  /// each mesh's state is told by its own crossings of 4 x 4 lines along each axis, and an
  /// octant for which some mesh's state stays unknown is not free.
  std::uint8_t free_octants(const Cell& cell) const;
  /// The free octants that make a thin component, by partial voxel in leaf order; empty for
  /// a component with untouched cells.
  const std::vector<OctantSet>& thin_octants(std::int32_t component) const;
  /// The meshes (indices into Build's argument) whose triangles touch a partial cell; empty
  /// for other cells.
  std::vector<std::int32_t> touching_meshes(const Cell& cell) const;

  /// The empty part of a partial cell (see Fill); {0, 0} for other cells. Reads cell.node only.
  Fill fill(const Cell& cell) const;

  /// The cell's box in the world, mm.
  Aabb Box_W(const Cell& cell) const;
  /// The box of one octant (bits as in OctantSet) of a voxel, world, mm.
  Aabb OctantBox_W(const Cell& voxel, int octant) const;
  /// The voxels an octant (bits as in OctantSet) of `voxel` touches, at a face, an edge or a
  /// corner: the 2 x 2 x 2 voxels around its outer corner, `voxel` itself first.
  static std::array<std::array<std::int32_t, 3>, 8> VoxelsAroundOctant(const Cell& voxel,
                                                                       int octant);
  /// Calls f on every leaf, depth first in child order (x, then y, then z bit).
  void ForEachLeaf(const std::function<void(const Cell&)>& f) const;
  /// Calls f(a, b, axis) once for every pair of leaves that share part of a face, a on the low
  /// side of b along `axis` (0, 1, 2), in O(leaves) (the face procedure of octree dual
  /// traversals).
  /// A template, so that f is called directly: the traversal runs over every leaf near a
  /// surface, several times per decomposition.
  template <typename F>
  void ForEachFaceNeighbours(F&& f) const {
    Cell root;
    root.size = resolution();
    CellProc(root, f);
  }
  /// Calls f on every leaf that overlaps the voxel box [min, max) (clipped to the root).
  void ForEachLeafIn(const std::array<std::int32_t, 3>& min, const std::array<std::int32_t, 3>& max,
                     const std::function<void(const Cell&)>& f) const;
  /// The leaf holding voxel v (inside the root).
  Cell Locate(const std::array<std::int32_t, 3>& v) const;

  std::size_t node_count() const { return nodes_.size(); }
  std::size_t leaf_count() const { return leaves_; }
  /// Bytes held by the structure (nodes, their fills, components, mesh lists).
  std::size_t MemoryBytes() const;

 private:
  friend class OctreeBuilder;

  // A node is one word: an inner node holds the index of the first of its eight consecutive
  // children; a leaf has kLeaf set and holds, for a partial cell, kPartialBit and either a mesh
  // index or (with kListBit) an index into multi_meshes_; for an untouched cell, its component.
  static constexpr std::uint32_t kLeaf = 0x80000000u;
  static constexpr std::uint32_t kPartialBit = 0x40000000u;
  static constexpr std::uint32_t kListBit = 0x20000000u;
  static constexpr std::uint32_t kPayload = 0x1fffffffu;

  static bool IsLeaf(std::uint32_t word) { return (word & kLeaf) != 0; }
  static Cell Child(const Cell& parent, std::uint32_t first, int i) {
    Cell c;
    c.node = static_cast<std::int32_t>(first) + i;
    c.size = parent.size / 2;
    for (int a = 0; a < 3; ++a) c.min[a] = parent.min[a] + ((i >> a) & 1) * c.size;
    return c;
  }
  template <typename F>
  void CellProc(const Cell& c, F& f) const {
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
  template <typename F>
  void FaceProc(const Cell& a, const Cell& b, int axis, F& f) const {
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

  double voxel_ = 1.0;
  Eigen::Vector3d origin_W_ = Eigen::Vector3d::Zero();
  int depth_ = 0;
  std::array<std::int32_t, 3> extent_ = {1, 1, 1};
  std::vector<std::uint32_t> nodes_;
  // Per node: a partial leaf's Fill, empty in the low byte and error in the high byte, in
  // 240ths.
  std::vector<std::uint16_t> fills_;
  // Per node: a partial leaf's free octants (see free_octants()).
  std::vector<std::uint8_t> free_octants_;
  std::size_t leaves_ = 0;
  std::vector<Component> components_;
  // Per component: a thin one's octants (see thin_octants()); may stop short of the last
  // components, which then have none.
  std::vector<std::vector<OctantSet>> thin_octants_;
  std::vector<std::vector<std::int32_t>> multi_meshes_;
};

}  // namespace mechanist
