// Voxel decomposition: the triangle-box test against polygon clipping, winding numbers of
// closed, inverted and open meshes, the octree's cells against brute force over every voxel
// and against exact inside tests, and the partial voxels' empty fractions against exact ones.
#include "kernel/voxels/occupancy_octree.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "kernel/collision/collision_mesh.h"
#include "kernel/mesh/mesh_builder.h"
#include "kernel/mesh/mesh_check.h"
#include "kernel/mesh/winding_number.h"
#include "kernel/voxels/triangle_box_overlap.h"

namespace mechanist {
namespace {

TriangleMesh BoxMesh(const Eigen::Vector3d& min, const Eigen::Vector3d& max) {
  Region2d r;
  r.outer = {{min.x(), min.y()}, {max.x(), min.y()}, {max.x(), max.y()}, {min.x(), max.y()}};
  return ExtrudeRegion(r, min.z(), max.z());
}

TEST(MakeUvSphere, IsClosedOutwardAndNearTheSpheresVolume) {
  const TriangleMesh sphere = MakeUvSphere(2.0, 32, 64);
  EXPECT_TRUE(CheckMesh(sphere).ok());
  EXPECT_NEAR(sphere.SignedVolume(), 4.0 / 3.0 * std::acos(-1.0) * 8.0, 0.02 * 33.5);
  EXPECT_EQ(sphere.faces.size(), 2u * 64 * 31);
  EXPECT_THROW(MakeUvSphere(1.0, 1, 8), std::invalid_argument);
}

// Sutherland-Hodgman clipping of the triangle by the box's six planes: the exact-arithmetic
// answer up to rounding, which the property test below brackets by shrinking and growing
// the box.
bool ClippedNonEmpty(const std::vector<Eigen::Vector3d>& tri, const Eigen::Vector3d& lo,
                     const Eigen::Vector3d& hi) {
  std::vector<Eigen::Vector3d> poly = tri;
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      std::vector<Eigen::Vector3d> out;
      const auto inside = [&](const Eigen::Vector3d& p) {
        return side == 0 ? p[axis] >= lo[axis] : p[axis] <= hi[axis];
      };
      const double plane = side == 0 ? lo[axis] : hi[axis];
      for (std::size_t i = 0; i < poly.size(); ++i) {
        const Eigen::Vector3d& p = poly[i];
        const Eigen::Vector3d& q = poly[(i + 1) % poly.size()];
        if (inside(p)) out.push_back(p);
        if (inside(p) != inside(q)) {
          const double t = (plane - p[axis]) / (q[axis] - p[axis]);
          out.push_back(p + t * (q - p));
        }
      }
      poly = std::move(out);
      if (poly.empty()) return false;
    }
  }
  return true;
}

// A triangle with corners drawn from u.
std::vector<Eigen::Vector3d> RandomTriangle(std::mt19937& rng,
                                            std::uniform_real_distribution<double>& u) {
  return {{u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}};
}

// Counts of the overlap answers that clipping settles, outside a rounding band of 1e-9.
struct ClippingTally {
  int overlaps = 0, apart = 0;
  // Expects `got` for the triangle and the box when clipping settles it.
  void Check(const std::vector<Eigen::Vector3d>& tri, const Eigen::Vector3d& center,
             const Eigen::Vector3d& half, bool got, const std::string& what) {
    const Eigen::Vector3d band = Eigen::Vector3d::Constant(1e-9);
    if (ClippedNonEmpty(tri, center - half + band, center + half - band)) {
      EXPECT_TRUE(got) << what;
      ++overlaps;
    }
    if (!ClippedNonEmpty(tri, center - half - band, center + half + band)) {
      EXPECT_FALSE(got) << what;
      ++apart;
    }
  }
};

TEST(TriangleOverlapsBox, AgreesWithClippingOutsideARoundingBand) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  ClippingTally tally;
  for (int n = 0; n < 20000; ++n) {
    const std::vector<Eigen::Vector3d> tri = RandomTriangle(rng, u);
    const Eigen::Vector3d center(u(rng) / 2, u(rng) / 2, u(rng) / 2);
    const Eigen::Vector3d half =
        Eigen::Vector3d(std::abs(u(rng)), std::abs(u(rng)), std::abs(u(rng))) / 4 +
        Eigen::Vector3d::Constant(0.01);
    tally.Check(tri, center, half, TriangleOverlapsBox(tri[0], tri[1], tri[2], center, half),
                std::to_string(n));
  }
  EXPECT_GT(tally.overlaps, 2000);
  EXPECT_GT(tally.apart, 2000);
}

TEST(TriangleBoxTester, EachOfACellsEightChildrenAgreesWithClipping) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  ClippingTally tally;
  for (int n = 0; n < 5000; ++n) {
    const std::vector<Eigen::Vector3d> tri = RandomTriangle(rng, u);
    const Eigen::Vector3d mid(u(rng) / 2, u(rng) / 2, u(rng) / 2);
    const Eigen::Vector3d half = Eigen::Vector3d::Constant(std::abs(u(rng)) / 4 + 0.01);
    const TriangleBoxTester tester(tri[0], tri[1], tri[2], mid, half);
    for (int child = 0; child < 8; ++child) {
      const Eigen::Vector3d offset =
          Eigen::Vector3d(child & 1 ? 1 : -1, child & 2 ? 1 : -1, child & 4 ? 1 : -1)
              .cwiseProduct(half);
      tally.Check(tri, mid + offset, half, tester.Overlaps(offset),
                  std::to_string(n) + " child " + std::to_string(child));
    }
  }
  EXPECT_GT(tally.overlaps, 4000);
  EXPECT_GT(tally.apart, 4000);
}

TEST(TriangleOverlapsBox, CountsTouchingAndDegenerateTriangles) {
  const Eigen::Vector3d c(0, 0, 0), h(1, 1, 1);
  // In the plane of a face, and a segment touching a corner.
  EXPECT_TRUE(TriangleOverlapsBox({1, -3, -3}, {1, 3, -3}, {1, 0, 5}, c, h));
  EXPECT_TRUE(TriangleOverlapsBox({1, 1, 1}, {2, 2, 2}, {3, 3, 3}, c, h));
  EXPECT_FALSE(TriangleOverlapsBox({1.001, 1, 1}, {2, 2, 2}, {3, 3, 3}, c, h));
  // Beyond the box's corner: only the triangle's normal separates.
  EXPECT_FALSE(TriangleOverlapsBox({3.5, 0, 0}, {0, 3.5, 0}, {0, 0, 3.5}, c, h));
  EXPECT_TRUE(TriangleOverlapsBox({2.9, 0, 0}, {0, 2.9, 0}, {0, 0, 2.9}, c, h));
}

TEST(WindingNumber, ClosedInvertedAndOpenMeshes) {
  TriangleMesh box = BoxMesh({0, 0, 0}, {2, 3, 4});
  EXPECT_NEAR(WindingNumber(box, {1, 1.5, 2}), 1.0, 1e-12);
  EXPECT_NEAR(WindingNumber(box, {1, 1.5, 4.5}), 0.0, 1e-12);
  EXPECT_NEAR(WindingNumber(box, {-7, 20, 2}), 0.0, 1e-12);
  TriangleMesh inverted = box;
  for (auto& f : inverted.faces) std::swap(f[1], f[2]);
  EXPECT_NEAR(WindingNumber(inverted, {1, 1.5, 2}), -1.0, 1e-12);
  // A cube without its top: the open face subtends a sixth of the sphere from the centre.
  TriangleMesh cube = BoxMesh({-1, -1, -1}, {1, 1, 1});
  TriangleMesh open = cube;
  open.faces.clear();
  for (const auto& f : cube.faces) {
    const bool top = cube.vertices[f[0]].z() > 0.5 && cube.vertices[f[1]].z() > 0.5 &&
                     cube.vertices[f[2]].z() > 0.5;
    if (!top) open.faces.push_back(f);
  }
  ASSERT_EQ(open.faces.size() + 2, cube.faces.size());
  EXPECT_NEAR(WindingNumber(open, {0, 0, 0}), 5.0 / 6.0, 1e-12);
}

// Every voxel of the grid: partial exactly when some triangle touches it, otherwise full
// exactly when its centre is inside (winding number), and the leaves tile the root.
void ExpectMatchesBruteForce(const OccupancyOctree& tree, const std::vector<PosedMesh>& meshes) {
  std::int64_t tiled = 0;
  tree.ForEachLeaf(
      [&](const OccupancyOctree::Cell& c) { tiled += std::int64_t{c.size} * c.size * c.size; });
  const std::int64_t n = tree.resolution();
  EXPECT_EQ(tiled, n * n * n);
  for (std::int32_t k = 0; k < tree.extent()[2]; ++k) {
    for (std::int32_t j = 0; j < tree.extent()[1]; ++j) {
      for (std::int32_t i = 0; i < tree.extent()[0]; ++i) {
        const Eigen::Vector3d lo = tree.origin_W() + tree.voxel() * Eigen::Vector3d(i, j, k);
        const Eigen::Vector3d half = Eigen::Vector3d::Constant(tree.voxel() / 2);
        bool touched = false, inside = false;
        for (const auto& pm : meshes) {
          for (const auto& f : pm.mesh->faces) {
            touched =
                touched || TriangleOverlapsBox(pm.X_WM * pm.mesh->vertices[f[0]],
                                               pm.X_WM * pm.mesh->vertices[f[1]],
                                               pm.X_WM * pm.mesh->vertices[f[2]], lo + half, half);
          }
          inside =
              inside || std::abs(WindingNumber(*pm.mesh, pm.X_WM.inverse() * (lo + half))) >= 0.5;
        }
        const CellState expected =
            touched ? CellState::kPartial : (inside ? CellState::kFull : CellState::kEmpty);
        ASSERT_EQ(tree.state(tree.Locate({i, j, k})), expected) << i << " " << j << " " << k;
      }
    }
  }
}

TEST(OccupancyOctree, CellsMatchBruteForceForRotatedAndOverlappingParts) {
  const TriangleMesh box = BoxMesh({-3, -2, -1}, {3, 2, 1});
  const TriangleMesh sphere = MakeUvSphere(2.2, 8, 12);
  const std::vector<PosedMesh> meshes = {
      {&box, RigidTransform(
                 Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix(),
                 Eigen::Vector3d(0.3, 0.1, -0.2))},
      {&sphere, RigidTransform(Eigen::Matrix3d::Identity(), Eigen::Vector3d(2.5, 0, 1))}};
  for (const double voxel : {0.7, 0.33}) {
    const OccupancyOctree tree = OccupancyOctree::Build(meshes, voxel);
    ExpectMatchesBruteForce(tree, meshes);
  }
}

// STEP tessellations are seldom closed: their inside is decided by CollisionMesh::Contains
// (the winding number summed over the collision hierarchy, or exact ray crossings for a mesh
// closed once coincident vertices are merged), which must give the exact sum's answer at every
// cell. A sphere of 1,500 triangles with a cap 3 mm wide cut off (points near the opening have
// winding numbers near a half) and a crack, a box beside it, and a small sphere as a soup
// (every triangle with vertices of its own): every cell against the brute-force oracle (exact
// winding numbers). The parts are turned off the grid: the oracle does not know the rule for
// faces on voxel faces (FacesOnVoxelFacesMakeOnlyTheVoxelsBehindThemPartial).
TEST(OccupancyOctree, CellsMatchBruteForceForCrackedMeshesAndSoups) {
  TriangleMesh cracked = MakeUvSphere(4.0, 24, 32);
  std::erase_if(cracked.faces, [&](const auto& f) {
    const Eigen::Vector3d c =
        (cracked.vertices[f[0]] + cracked.vertices[f[1]] + cracked.vertices[f[2]]) / 3;
    return c.z() > 3.6 || (std::abs(c.x()) < 0.3 && c.y() > 3.5);
  });
  ASSERT_FALSE(CollisionMesh(std::make_shared<TriangleMesh>(cracked)).closed());
  ASSERT_TRUE(CollisionMesh(std::make_shared<TriangleMesh>(cracked)).solid());
  const TriangleMesh box = BoxMesh({-3, -2, -1}, {3, 2, 1});
  const TriangleMesh welded = MakeUvSphere(1.5, 8, 12);
  TriangleMesh soup;
  for (const auto& f : welded.faces) {
    const auto first = static_cast<std::int32_t>(soup.vertices.size());
    for (const std::int32_t v : f) soup.vertices.push_back(welded.vertices[v]);
    soup.faces.push_back({first, first + 1, first + 2});
  }
  ASSERT_FALSE(CheckMesh(soup).closed());
  ASSERT_TRUE(CollisionMesh(std::make_shared<TriangleMesh>(soup)).closed());
  const std::vector<PosedMesh> meshes = {
      {&cracked,
       RigidTransform(
           Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, -2, 1).normalized()).toRotationMatrix(),
           Eigen::Vector3d(0.2, -0.1, 0.3))},
      {&box, RigidTransform(
                 Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix(),
                 Eigen::Vector3d(3.5, 0, 0))},
      {&soup, RigidTransform(Eigen::Matrix3d::Identity(), Eigen::Vector3d(-3, 3, -2))}};
  for (const double voxel : {1.0, 0.7}) {
    const OccupancyOctree tree = OccupancyOctree::Build(meshes, voxel);
    ExpectMatchesBruteForce(tree, meshes);
  }
}

// Every free octant of a partial voxel: no triangle reaches inside it (clipping against the
// octant shrunk by a rounding band), and its centre and corners are outside the meshes that
// cross its voxel (winding number).
void ExpectFreeOctantsAreFree(const OccupancyOctree& tree, const std::vector<PosedMesh>& meshes,
                              int& free_octants) {
  tree.ForEachLeaf([&](const OccupancyOctree::Cell& cell) {
    const std::uint8_t octants = tree.free_octants(cell);
    if (tree.state(cell) != CellState::kPartial) {
      EXPECT_EQ(octants, 0);
      return;
    }
    const Aabb voxel = tree.Box_W(cell);
    const Eigen::Vector3d half = (voxel.max - voxel.min) / 2;
    const std::vector<std::int32_t> crossing = tree.touching_meshes(cell);
    for (int octant = 0; octant < 8; ++octant) {
      if (!((octants >> octant) & 1)) continue;
      ++free_octants;
      const Eigen::Vector3d lo =
          voxel.min +
          Eigen::Vector3d(octant & 1, (octant >> 1) & 1, (octant >> 2) & 1).cwiseProduct(half);
      const Eigen::Vector3d band = Eigen::Vector3d::Constant(1e-9);
      for (const auto& pm : meshes) {
        for (const auto& f : pm.mesh->faces) {
          const std::vector<Eigen::Vector3d> tri = {pm.X_WM * pm.mesh->vertices[f[0]],
                                                    pm.X_WM * pm.mesh->vertices[f[1]],
                                                    pm.X_WM * pm.mesh->vertices[f[2]]};
          ASSERT_FALSE(ClippedNonEmpty(tri, lo + band, lo + half - band))
              << "octant " << octant << " of voxel " << cell.min[0] << " " << cell.min[1] << " "
              << cell.min[2];
        }
        const auto m = static_cast<std::int32_t>(&pm - meshes.data());
        if (std::find(crossing.begin(), crossing.end(), m) == crossing.end()) continue;
        for (int corner = 0; corner < 9; ++corner) {
          // The corners pulled in by 1% of the octant, then its centre.
          Eigen::Vector3d at = Eigen::Vector3d::Constant(0.5);
          if (corner < 8) {
            at = 0.98 * Eigen::Vector3d(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1) +
                 Eigen::Vector3d::Constant(0.01);
          }
          const Eigen::Vector3d p = lo + at.cwiseProduct(half);
          ASSERT_LT(std::abs(WindingNumber(*pm.mesh, pm.X_WM.inverse() * p)), 0.5)
              << "octant " << octant << " corner " << corner << " at " << p.transpose()
              << " of voxel " << voxel.min.transpose() << " size " << tree.voxel() << " mesh "
              << (&pm - meshes.data());
        }
      }
    }
  });
}

TEST(OccupancyOctree, FreeOctantsHoldNoSurfaceAndNoMaterial) {
  // Rotated and axis-aligned parts that touch and overlap, faces on round coordinates.
  const TriangleMesh box = BoxMesh({-3, -2, -1}, {3, 2, 1});
  const TriangleMesh plate = BoxMesh({-4, -4, 1}, {4, 4, 2});
  const TriangleMesh sphere = MakeUvSphere(2.2, 8, 12);
  const std::vector<PosedMesh> meshes = {
      {&box, RigidTransform(
                 Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix(),
                 Eigen::Vector3d(0.3, 0.1, -0.2))},
      {&plate, RigidTransform()},
      {&box, RigidTransform(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, 3))},
      {&sphere, RigidTransform(Eigen::Matrix3d::Identity(), Eigen::Vector3d(2.5, 0, 1))}};
  int free_octants = 0;
  for (const double voxel : {0.7, 0.5, 0.33}) {
    const OccupancyOctree tree = OccupancyOctree::Build(meshes, voxel);
    ExpectFreeOctantsAreFree(tree, meshes, free_octants);
    for (std::size_t c = 0; c < tree.components().size(); ++c) {
      // A thin component's octants are outside every mesh.
      for (const auto& set : tree.thin_octants(static_cast<std::int32_t>(c))) {
        const Aabb box = tree.Box_W(set.cell);
        for (int octant = 0; octant < 8; ++octant) {
          if (!((set.octants >> octant) & 1)) continue;
          const Eigen::Vector3d p =
              box.min +
              (box.max - box.min)
                  .cwiseProduct(Eigen::Vector3d(octant & 1 ? 0.75 : 0.25, octant & 2 ? 0.75 : 0.25,
                                                octant & 4 ? 0.75 : 0.25));
          for (const auto& pm : meshes) {
            EXPECT_LT(std::abs(WindingNumber(*pm.mesh, pm.X_WM.inverse() * p)), 0.5);
          }
        }
      }
    }
  }
  EXPECT_GT(free_octants, 1000);
}

TEST(OccupancyOctree, FreeOctantsOfAShellWithWallsOnQuarterVoxels) {
  // Inner faces a quarter or three quarters into the voxels: planes between the fill's line
  // prisms, which cut octants.
  int free_octants = 0;
  for (const double wall : {0.5, 1.5}) {
    TriangleMesh shell = BoxMesh({0, 0, 0}, {12, 12, 12});
    TriangleMesh cavity =
        BoxMesh(Eigen::Vector3d::Constant(wall), Eigen::Vector3d::Constant(12 - wall));
    for (auto& f : cavity.faces) std::swap(f[1], f[2]);
    shell.Append(cavity);
    const std::vector<PosedMesh> meshes = {{&shell, RigidTransform()}};
    ExpectFreeOctantsAreFree(OccupancyOctree::Build(meshes, 2.0), meshes, free_octants);
  }
  EXPECT_GT(free_octants, 100);
}

TEST(OccupancyOctree, VolumeOfABoxIsBracketedByFullAndPartialCells) {
  const TriangleMesh box = BoxMesh({0, 0, 0}, {10, 7, 5});
  const std::vector<PosedMesh> meshes = {
      {&box, RigidTransform(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()).toRotationMatrix(),
                            Eigen::Vector3d(1, 2, 3))}};
  for (const double voxel : {1.0, 0.5, 0.25}) {
    const OccupancyOctree tree = OccupancyOctree::Build(meshes, voxel);
    double full = 0, partial = 0;
    tree.ForEachLeaf([&](const OccupancyOctree::Cell& c) {
      const double v = std::pow(c.size * voxel, 3);
      if (tree.state(c) == CellState::kFull) full += v;
      if (tree.state(c) == CellState::kPartial) partial += v;
    });
    EXPECT_LE(full, 350.0) << voxel;
    EXPECT_GE(full + partial, 350.0) << voxel;
    EXPECT_GT(full, 350.0 - partial) << voxel;
  }
}

// The empty volume of the root cube from the cells: empty cells whole, partial voxels by
// their fill, with the sum of the fills' errors.
std::pair<double, double> EmptyVolume(const OccupancyOctree& tree) {
  double empty = 0, error = 0;
  const double h3 = std::pow(tree.voxel(), 3);
  tree.ForEachLeaf([&](const OccupancyOctree::Cell& c) {
    if (tree.state(c) == CellState::kEmpty) empty += std::pow(c.size, 3) * h3;
    empty += tree.fill(c).empty * h3;
    error += tree.fill(c).error * h3;
  });
  return {empty, error};
}

TEST(OccupancyOctree, FillsBracketTheEmptyVolumeAroundARotatedBox) {
  const TriangleMesh box = BoxMesh({0, 0, 0}, {10, 7, 5});
  const std::vector<PosedMesh> meshes = {
      {&box, RigidTransform(
                 Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix(),
                 Eigen::Vector3d(1, 2, 3))}};
  double previous = 1e300;
  for (const double voxel : {1.0, 0.5, 0.25}) {
    const OccupancyOctree tree = OccupancyOctree::Build(meshes, voxel);
    const double root = std::pow(tree.resolution() * voxel, 3);
    const auto [empty, error] = EmptyVolume(tree);
    EXPECT_LE(std::abs(empty - (root - 350.0)), error) << voxel;
    // Sloping faces: well under the half voxel per partial voxel of a count without fills.
    std::int64_t partial = 0;
    tree.ForEachLeaf(
        [&](const OccupancyOctree::Cell& c) { partial += tree.state(c) == CellState::kPartial; });
    EXPECT_LT(error, 0.3 * partial * std::pow(voxel, 3)) << voxel;
    EXPECT_LT(error, previous);
    previous = error;
  }
}

TEST(OccupancyOctree, FacesOnVoxelFacesMakeOnlyTheVoxelsBehindThemPartial) {
  // A box on round coordinates, shifted by fractions of a voxel: the grid starts two voxels
  // below the bounds, so a small cube at (-4, -4, -4) holds it still.
  const TriangleMesh anchor = BoxMesh({-4, -4, -4}, {-3.5, -3.5, -3.5});
  for (const double shift : {0.0, 0.25, 0.37}) {
    const Eigen::Vector3d min = Eigen::Vector3d::Constant(shift),
                          max = min + Eigen::Vector3d(6, 4, 3);
    const TriangleMesh box = BoxMesh(min, max);
    const std::vector<PosedMesh> meshes = {{&box, RigidTransform()}, {&anchor, RigidTransform()}};
    for (const double voxel : {0.5, 1.0}) {
      const OccupancyOctree tree = OccupancyOctree::Build(meshes, voxel);
      tree.ForEachLeaf([&](const OccupancyOctree::Cell& c) {
        const Aabb cell = tree.Box_W(c);
        if ((cell.min.array() >= -3).all() && tree.state(c) == CellState::kPartial) {
          // Exactly the voxels the box's inside reaches, with its empty part exactly.
          double inside = 1;
          for (int i = 0; i < 3; ++i) {
            inside *= std::max(0.0, std::min(cell.max[i], max[i]) - std::max(cell.min[i], min[i]));
          }
          inside /= std::pow(voxel, 3);
          EXPECT_GT(inside, 0) << cell.min.transpose();
          const OccupancyOctree::Fill fill = tree.fill(c);
          EXPECT_LE(std::abs(fill.empty - (1 - inside)), fill.error) << cell.min.transpose();
          // Exact to the 240ths it is stored in, but where two faces cross one voxel off its
          // lines' prisms' sides.
          if (shift != 0.37) {
            EXPECT_NEAR(fill.empty, 1 - inside, 0.5 / 240 + 1e-12) << cell.min.transpose();
          }
        }
      });
      const double root = std::pow(tree.resolution() * voxel, 3);
      const auto [empty, error] = EmptyVolume(tree);
      EXPECT_NEAR(empty, root - 72.0 - 0.125, 1e-3 * root) << shift << " " << voxel;
      EXPECT_LE(std::abs(empty - (root - 72.125)), error) << shift << " " << voxel;
    }
  }
}

TEST(OccupancyOctree, FaceNeighboursAreExactlyTheLeavesSharingAFace) {
  const TriangleMesh sphere = MakeUvSphere(3.0, 6, 8);
  const std::vector<PosedMesh> meshes = {{&sphere, RigidTransform()}};
  const OccupancyOctree tree = OccupancyOctree::Build(meshes, 0.9);
  std::vector<OccupancyOctree::Cell> leaves;
  tree.ForEachLeaf([&](const OccupancyOctree::Cell& c) { leaves.push_back(c); });
  std::set<std::tuple<int, int, int>> expected, got;
  for (const auto& a : leaves) {
    for (const auto& b : leaves) {
      for (int axis = 0; axis < 3; ++axis) {
        if (a.min[axis] + a.size != b.min[axis]) continue;
        bool overlap = true;
        for (int o = 0; o < 3; ++o) {
          if (o == axis) continue;
          overlap = overlap && a.min[o] < b.min[o] + b.size && b.min[o] < a.min[o] + a.size;
        }
        if (overlap) expected.insert({a.node, b.node, axis});
      }
    }
  }
  tree.ForEachFaceNeighbours([&](const auto& a, const auto& b, int axis) {
    EXPECT_TRUE(got.insert({a.node, b.node, axis}).second);
  });
  EXPECT_EQ(got, expected);
  EXPECT_GT(got.size(), 100u);
}

TEST(OccupancyOctree, MemoryGrowsWithSurfaceNotVolume) {
  const TriangleMesh sphere = MakeUvSphere(10.0, 24, 48);
  const std::vector<PosedMesh> meshes = {{&sphere, RigidTransform()}};
  const OccupancyOctree coarse = OccupancyOctree::Build(meshes, 0.4);
  const OccupancyOctree fine = OccupancyOctree::Build(meshes, 0.1);
  // Four times finer: sixteen times the surface cells, 64 times the volume cells.
  const double ratio = static_cast<double>(fine.node_count()) / coarse.node_count();
  EXPECT_GT(ratio, 10.0);
  EXPECT_LT(ratio, 24.0);
  // A 4-byte word, a 2-byte fill and a byte of free octants per node.
  EXPECT_LT(fine.MemoryBytes(), 7 * fine.node_count() + 4096);
}

TEST(OccupancyOctree, AMeshWithAnOpeningWiderThanAVoxelKeepsItsInside) {
  // A 10 mm cube without its top face: the winding number is 5/6 at the centre.
  const TriangleMesh cube = BoxMesh({-5, -5, -5}, {5, 5, 5});
  TriangleMesh open = cube;
  open.faces.clear();
  for (const auto& f : cube.faces) {
    if (cube.vertices[f[0]].z() + cube.vertices[f[1]].z() + cube.vertices[f[2]].z() < 15) {
      open.faces.push_back(f);
    }
  }
  const std::vector<PosedMesh> meshes = {{&open, RigidTransform()}};
  const OccupancyOctree tree = OccupancyOctree::Build(meshes, 0.75);
  int full = 0, empty = 0;
  for (std::int32_t k = 0; k < tree.extent()[2]; ++k) {
    for (std::int32_t j = 0; j < tree.extent()[1]; ++j) {
      for (std::int32_t i = 0; i < tree.extent()[0]; ++i) {
        const Eigen::Vector3d p = tree.origin_W() + tree.voxel() * (Eigen::Vector3d(i, j, k) +
                                                                    Eigen::Vector3d::Constant(0.5));
        if (p.z() > 2) continue;  // near the opening the inside is a matter of definition
        const CellState s = tree.state(tree.Locate({i, j, k}));
        const bool inside = (p.cwiseAbs().array() < 5).all();
        if (s == CellState::kFull) {
          EXPECT_TRUE(inside) << p.transpose();
        }
        if (s == CellState::kEmpty) {
          EXPECT_FALSE(inside) << p.transpose();
        }
        full += s == CellState::kFull;
        empty += s == CellState::kEmpty;
      }
    }
  }
  EXPECT_GT(full, 500);
  EXPECT_GT(empty, 500);
}

TEST(OccupancyOctree, NoMeshesGiveOneEmptyExteriorCell) {
  const OccupancyOctree tree = OccupancyOctree::Build({}, 1.0);
  ASSERT_EQ(tree.components().size(), 1u);
  EXPECT_TRUE(tree.components()[0].exterior);
  EXPECT_EQ(tree.components()[0].state, CellState::kEmpty);
}

TEST(OccupancyOctree, RejectsBadVoxelSizes) {
  const TriangleMesh box = BoxMesh({0, 0, 0}, {1, 1, 1});
  const std::vector<PosedMesh> meshes = {{&box, RigidTransform()}};
  EXPECT_THROW(OccupancyOctree::Build(meshes, 0.0), std::invalid_argument);
  EXPECT_THROW(OccupancyOctree::Build(meshes, std::nan("")), std::invalid_argument);
  EXPECT_THROW(OccupancyOctree::Build(meshes, 1e-7), std::invalid_argument);
}

}  // namespace
}  // namespace mechanist
