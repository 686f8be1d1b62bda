// Gap search against analytic cavities: a sealed box of plates, two cavities of different
// sizes, a leak that opens once the voxel is smaller than it, a plate exported with a missing
// triangle, and a rotated copy of the box; the analytic volume must lie within the reported
// error bound, and the bound must shrink with the voxel.
#include "reasoning/gap_search.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <bit>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "kernel/mesh/mesh_builder.h"

namespace mechanist {
namespace {

std::shared_ptr<const TriangleMesh> BoxMesh(const Eigen::Vector3d& min,
                                            const Eigen::Vector3d& max) {
  Region2d r;
  r.outer = {{min.x(), min.y()}, {max.x(), min.y()}, {max.x(), max.y()}, {min.x(), max.y()}};
  return std::make_shared<TriangleMesh>(ExtrudeRegion(r, min.z(), max.z()));
}

Part Slab(const std::string& id, const Eigen::Vector3d& min, const Eigen::Vector3d& max,
          const RigidTransform& X_WA = RigidTransform()) {
  Part p;
  p.id = id;
  p.mesh = BoxMesh(min, max);
  p.mesh_source = "test:box";
  p.X_WP = X_WA;
  return p;
}

// A closed box of six plates, thickness t, around the cavity [0, a] x [0, b] x [0, c]; with
// `partition_x`, a seventh plate at that x splits the cavity in two.
std::vector<Part> SealedBox(double a, double b, double c, double t,
                            const RigidTransform& X_WA = RigidTransform(),
                            double partition_x = -1) {
  std::vector<Part> parts = {Slab("bottom", {-t, -t, -t}, {a + t, b + t, 0}, X_WA),
                             Slab("top", {-t, -t, c}, {a + t, b + t, c + t}, X_WA),
                             Slab("left", {-t, -t, 0}, {0, b + t, c}, X_WA),
                             Slab("right", {a, -t, 0}, {a + t, b + t, c}, X_WA),
                             Slab("front", {0, -t, 0}, {a, 0, c}, X_WA),
                             Slab("back", {0, b, 0}, {a, b + t, c}, X_WA)};
  if (partition_x > 0) {
    parts.push_back(Slab("partition", {partition_x, 0, 0}, {partition_x + t, b, c}, X_WA));
  }
  return parts;
}

Assembly MakeAssembly(std::vector<Part> parts) {
  AssemblySpec spec;
  spec.name = "gaps";
  spec.parts = std::move(parts);
  return Assembly(std::move(spec));
}

GapSearch Search(const Assembly& assembly, double voxel) {
  GapSearchOptions options;
  options.voxel = voxel;
  return FindGaps(assembly, options);
}

void ExpectBracketed(const Gap& gap, double truth, const std::string& what) {
  EXPECT_LE(std::abs(gap.volume - truth), gap.volume_error) << what;
  EXPECT_GT(gap.volume_error, 0.0) << what;
}

TEST(GapSearch, SealedBoxHasOneGapOfTheCavitysVolume) {
  const Assembly assembly = MakeAssembly(SealedBox(40, 30, 20, 3));
  double previous_error = 1e300;
  for (const double voxel : {2.0, 1.0, 0.5}) {
    const GapSearch search = Search(assembly, voxel);
    ASSERT_EQ(search.gaps.size(), 1u) << voxel;
    const Gap& gap = search.gaps[0];
    ExpectBracketed(gap, 40 * 30 * 20, "voxel " + std::to_string(voxel));
    EXPECT_LT(gap.volume_error, previous_error);
    previous_error = gap.volume_error;
    // Every plate bounds the cavity, and its box is the cavity's within a voxel.
    EXPECT_EQ(gap.parts.size(), 6u);
    EXPECT_LE(gap.box_W.min.cwiseAbs().maxCoeff(), voxel);
    EXPECT_LE((gap.box_W.max - Eigen::Vector3d(40, 30, 20)).cwiseAbs().maxCoeff(), voxel);
    // Every wall is 3 mm thick; the centres of the partial voxels that hold its faces lie
    // up to half a voxel off them.
    EXPECT_GE(gap.wall, 3.0 - voxel);
    EXPECT_LE(gap.wall, 3.0 + voxel);
    EXPECT_NEAR((gap.p_gap_W - gap.p_outside_W).norm(), gap.wall, 1e-5);
  }
}

// A part `id` of one closed mesh of two shells: the box [outer_min, outer_max] and, wound inside
// out, the cavity [cavity_min, cavity_max].
Part HollowBlock(const std::string& id, const Eigen::Vector3d& outer_min,
                 const Eigen::Vector3d& outer_max, const Eigen::Vector3d& cavity_min,
                 const Eigen::Vector3d& cavity_max) {
  auto mesh = std::make_shared<TriangleMesh>(*BoxMesh(outer_min, outer_max));
  TriangleMesh cavity = *BoxMesh(cavity_min, cavity_max);
  for (auto& f : cavity.faces) std::swap(f[1], f[2]);
  mesh->Append(cavity);
  Part part;
  part.id = id;
  part.mesh = mesh;
  part.mesh_source = "test:" + id;
  return part;
}

TEST(GapSearch, AOnePieceShellComesClosestToTheOutsideAtItsThinnestWall) {
  const Part part = HollowBlock("shell", {-4, -4, -4}, {22, 14, 9}, {0, 0, 0}, {20, 10, 5});
  for (const double voxel : {1.0, 0.5}) {
    const GapSearch search = Search(MakeAssembly({part}), voxel);
    ASSERT_EQ(search.gaps.size(), 1u);
    const Gap& gap = search.gaps[0];
    ExpectBracketed(gap, 20 * 10 * 5, "shell");
    EXPECT_EQ(gap.parts, std::vector<std::size_t>{0});
    // The walls are 4 mm thick but the one at +x, 2 mm: the closest approach is there.
    EXPECT_GE(gap.wall, 2.0 - voxel);
    EXPECT_LE(gap.wall, 2.0 + voxel);
    EXPECT_NEAR(gap.p_gap_W.x(), 20, voxel);
    EXPECT_NEAR(gap.p_outside_W.x(), 22, voxel);
  }
}

TEST(GapSearch, VolumeDoesNotDependOnTheAssemblysPose) {
  const RigidTransform X_WA(
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix(),
      Eigen::Vector3d(13.1, -7.7, 2.9));
  const GapSearch search = Search(MakeAssembly(SealedBox(25, 18, 12, 2.5, X_WA)), 0.6);
  ASSERT_EQ(search.gaps.size(), 1u);
  ExpectBracketed(search.gaps[0], 25 * 18 * 12, "rotated");
  EXPECT_EQ(search.gaps[0].parts.size(), 6u);
}

TEST(GapSearch, TwoCavitiesComeLargestFirst) {
  // Cavities [0, 30] and [33, 40] along x.
  const GapSearch search =
      Search(MakeAssembly(SealedBox(40, 30, 20, 3, RigidTransform(), 30)), 0.5);
  ASSERT_EQ(search.gaps.size(), 2u);
  ExpectBracketed(search.gaps[0], 30 * 30 * 20, "large");
  ExpectBracketed(search.gaps[1], 7 * 30 * 20, "small");
  EXPECT_LT(search.gaps[0].box_W.max.x(), 31);
  EXPECT_GT(search.gaps[1].box_W.min.x(), 32);
  // The partition bounds both; the right wall only the small one.
  const auto has = [](const Gap& g, std::size_t part) {
    return std::find(g.parts.begin(), g.parts.end(), part) != g.parts.end();
  };
  EXPECT_TRUE(has(search.gaps[0], 6) && has(search.gaps[1], 6));
  EXPECT_FALSE(has(search.gaps[0], 3));
  EXPECT_TRUE(has(search.gaps[1], 3));
}

TEST(GapSearch, EachGapsSurfaceEnclosesExactlyItsEmptyVoxels) {
  const GapSearch search =
      Search(MakeAssembly(SealedBox(40, 30, 20, 3, RigidTransform(), 30)), 0.5);
  ASSERT_EQ(search.gaps.size(), 2u);
  std::vector<std::int32_t> gap_of_face;
  const TriangleMesh surface = GapSurface(search, &gap_of_face);
  ASSERT_EQ(gap_of_face.size(), surface.faces.size());
  // Divergence theorem per gap: the faces facing away from it bound its empty cells.
  for (std::int32_t g = 0; g < 2; ++g) {
    TriangleMesh walls;
    walls.vertices = surface.vertices;
    for (std::size_t f = 0; f < surface.faces.size(); ++f) {
      if (gap_of_face[f] == g) walls.faces.push_back(surface.faces[f]);
    }
    const double h3 = 0.5 * 0.5 * 0.5;
    EXPECT_NEAR(walls.SignedVolume(), search.gaps[g].voxels * h3, 1e-6) << g;
  }
  EXPECT_TRUE(
      GapSurface(Search(MakeAssembly({Slab("plate", {0, 0, 0}, {9, 9, 1})}), 1.0)).faces.empty());
}

TEST(GapSearch, ALeakOpensOnceTheVoxelIsNoWiderThanIt) {
  // The right wall in two pieces with a 1 mm x 1 mm channel through it at mid height: closed
  // at voxels over twice as wide, open at voxels no wider, whatever the alignment (at 0.9 mm
  // no whole voxel fits in the channel).
  std::vector<Part> parts = SealedBox(40, 30, 20, 3);
  parts[3] = Slab("right_low", {40, -3, 0}, {43, 33, 10});
  parts.push_back(Slab("right_high", {40, -3, 11}, {43, 33, 20}));
  parts.push_back(Slab("right_mid_a", {40, -3, 10}, {43, 15, 11}));
  parts.push_back(Slab("right_mid_b", {40, 16, 10}, {43, 33, 11}));
  const Assembly assembly = MakeAssembly(parts);
  for (const double voxel : {2.5, 2.2}) {
    const GapSearch coarse = Search(assembly, voxel);
    ASSERT_EQ(coarse.gaps.size(), 1u) << voxel;
    ExpectBracketed(coarse.gaps[0], 40 * 30 * 20 + 3, "leak closed");
  }
  for (const double voxel : {1.0, 0.9, 0.7, 0.25}) {
    EXPECT_TRUE(Search(assembly, voxel).gaps.empty()) << voxel;
  }
}

TEST(GapSearch, APlateExportedWithTJunctionsAndACrackStillSeals) {
  // The top plate's face towards the cavity (z = 20) as a grid of 1 mm squares that do not
  // share the side faces' edges (T-junctions), with one triangle missing: a mesh that is not
  // closed, as CAD exports often are.
  std::vector<Part> parts = SealedBox(40, 30, 20, 3);
  auto top = std::make_shared<TriangleMesh>(*parts[1].mesh);
  std::vector<TriangleMesh::Face> kept;
  for (const auto& f : top->faces) {
    if (top->vertices[f[0]].z() + top->vertices[f[1]].z() + top->vertices[f[2]].z() > 60) {
      kept.push_back(f);
    }
  }
  ASSERT_EQ(kept.size() + 2, top->faces.size());
  top->faces = kept;
  for (int i = -3; i < 43; ++i) {
    for (int j = -3; j < 33; ++j) {
      const auto v = static_cast<std::int32_t>(top->vertices.size());
      top->vertices.insert(top->vertices.end(), {{double(i), double(j), 20},
                                                 {i + 1.0, double(j), 20},
                                                 {i + 1.0, j + 1.0, 20},
                                                 {double(i), j + 1.0, 20}});
      // Seen from below (outside the plate) counter-clockwise.
      top->faces.push_back({v, v + 2, v + 1});
      if (i != 20 || j != 15) top->faces.push_back({v, v + 3, v + 2});
    }
  }
  parts[1].mesh = top;
  const GapSearch search = Search(MakeAssembly(parts), 1.0);
  ASSERT_EQ(search.gaps.size(), 1u);
  ExpectBracketed(search.gaps[0], 40 * 30 * 20, "open top plate");
}

TEST(GapSearch, OpenAssemblyHasNoGapsAndResultsAreDeterministic) {
  std::vector<Part> parts = SealedBox(40, 30, 20, 3);
  parts.erase(parts.begin() + 1);  // no top
  const Assembly assembly = MakeAssembly(parts);
  EXPECT_TRUE(Search(assembly, 1.0).gaps.empty());
  const Assembly sealed = MakeAssembly(SealedBox(10, 10, 10, 1));
  const GapSearch a = Search(sealed, 0.7), b = Search(sealed, 0.7);
  ASSERT_EQ(a.gaps.size(), 1u);
  EXPECT_EQ(a.gaps[0].volume, b.gaps[0].volume);
  EXPECT_EQ(a.gaps[0].p_gap_W, b.gaps[0].p_gap_W);
}

// Axis-aligned cavities as CAD exports them, on round coordinates: two plates and four walls
// (separate parts) and a one-piece block with a box-shaped cavity, at three voxel sizes, with
// faces exactly on voxel faces and shifted by fractions of a voxel. A gap that holds a whole
// voxel is found, its volume is within 2% and within the stated bound.
struct AlignedCase {
  double voxel;
  double shift;  // of the geometry along x, y and z, in voxels
};

std::vector<AlignedCase> AlignedCases() {
  std::vector<AlignedCase> cases;
  for (const double voxel : {0.25, 0.5, 1.0}) {
    for (const double shift : {0.0, 0.25, 0.5, 0.37}) cases.push_back({voxel, shift});
  }
  return cases;
}

std::string Describe(const AlignedCase& c) {
  return "voxel " + std::to_string(c.voxel) + " shift " + std::to_string(c.shift);
}

Part Anchor() { return Slab("anchor", {-10, -10, -10}, {-9, -9, -9}); }

// A cavity 20 x 12 x height mm between 2 mm plates and walls, shifted by `shift` mm along
// each axis, with the anchor that keeps the grid's origin put.
Assembly ShiftedCavity(double height, double shift) {
  const RigidTransform X_WA(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Constant(shift));
  std::vector<Part> parts = SealedBox(20, 12, height, 2, X_WA);
  parts.push_back(Anchor());
  return MakeAssembly(parts);
}

void ExpectWithinTwoPercent(const GapSearch& search, double truth, const std::string& what) {
  ASSERT_EQ(search.gaps.size(), 1u) << what;
  const Gap& gap = search.gaps[0];
  EXPECT_LE(std::abs(gap.volume - truth), 0.02 * truth)
      << what << ": " << gap.volume << " +/- " << gap.volume_error << " against " << truth;
  EXPECT_LE(std::abs(gap.volume - truth), gap.volume_error) << what;
}

TEST(GapSearch, AThinCavityBetweenPlatesOnRoundCoordinatesIsFoundAndMeasured) {
  // A cavity 20 x 12 x 2 mm between 2 mm plates and walls.
  for (const AlignedCase& c : AlignedCases()) {
    ExpectWithinTwoPercent(Search(ShiftedCavity(2, c.shift * c.voxel), c.voxel), 20 * 12 * 2,
                           Describe(c));
  }
}

TEST(GapSearch, ACavityInOneBlockOnRoundCoordinatesIsFoundAndMeasured) {
  // One closed mesh: a block and, wound inside out, a 16 x 10 x 3 mm cavity.
  for (const AlignedCase& c : AlignedCases()) {
    const Eigen::Vector3d d = Eigen::Vector3d::Constant(c.shift * c.voxel);
    const Part part =
        HollowBlock("block", d - Eigen::Vector3d(3, 2, 2), d + Eigen::Vector3d(19, 12, 5), d,
                    d + Eigen::Vector3d(16, 10, 3));
    ExpectWithinTwoPercent(Search(MakeAssembly({part, Anchor()}), c.voxel), 16 * 10 * 3,
                           Describe(c));
  }
}

TEST(GapSearch, ACavityOneVoxelHighWithFacesOnVoxelFacesIsFound) {
  for (const double voxel : {0.25, 0.5, 1.0}) {
    const GapSearch search = Search(MakeAssembly(SealedBox(20, 12, voxel, 2)), voxel);
    ExpectWithinTwoPercent(search, 20 * 12 * voxel, "voxel " + std::to_string(voxel));
  }
}

TEST(GapSearch, ACavityBetweenOneAndTwoVoxelsThickIsFoundAtAnyAlignment) {
  // A cavity 20 x 12 mm, 1 to 1.75 voxels high, between plates and walls shifted by
  // fractions of a voxel: most of these hold no whole voxel of the grid, only free octants.
  int thin = 0;
  for (const double voxel : {0.25, 0.5, 1.0}) {
    for (const double height : {1.0, 1.3, 1.75}) {
      for (const double shift : {0.13, 0.37, 0.5, 0.81}) {
        const GapSearch search = Search(ShiftedCavity(height * voxel, shift * voxel), voxel);
        const std::string what = "voxel " + std::to_string(voxel) + " height " +
                                 std::to_string(height) + " shift " + std::to_string(shift);
        ExpectWithinTwoPercent(search, 20 * 12 * height * voxel, what);
        if (!search.gaps.empty() && search.gaps[0].voxels == 0) {
          ++thin;
          EXPECT_EQ(search.gaps[0].parts.size(), 6u) << what;
          EXPECT_LE((search.gaps[0].box_W.max - search.gaps[0].box_W.min -
                     Eigen::Vector3d(20, 12, height * voxel))
                        .cwiseAbs()
                        .maxCoeff(),
                    voxel)
              << what;
        }
      }
    }
  }
  EXPECT_GE(thin, 20);
}

TEST(GapSearch, AThinGapsSurfaceEnclosesExactlyItsOctants) {
  const GapSearch search = Search(ShiftedCavity(1.3, 0.37), 1.0);
  ASSERT_EQ(search.gaps.size(), 1u);
  ASSERT_EQ(search.gaps[0].voxels, 0);
  int octants = 0;
  for (const auto& set : search.octree->thin_octants(search.gaps[0].component)) {
    octants += std::popcount(set.octants);
  }
  EXPECT_GT(octants, 100);
  std::vector<std::int32_t> gap_of_face;
  const TriangleMesh surface = GapSurface(search, &gap_of_face);
  ASSERT_EQ(gap_of_face.size(), surface.faces.size());
  EXPECT_TRUE(std::all_of(gap_of_face.begin(), gap_of_face.end(), [](int g) { return g == 0; }));
  EXPECT_NEAR(surface.SignedVolume(), octants * 0.125, 1e-6);
}

TEST(GapSearch, AThinCavityBetweenWallsHalfAVoxelThickIsFound) {
  // One voxel high, its faces half a voxel into the voxels, the outside half a voxel beyond:
  // every voxel of it has outside cells among its neighbours, none touching its octants.
  const RigidTransform X_WA(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Constant(0.5));
  std::vector<Part> parts = SealedBox(20, 12, 1, 0.5, X_WA);
  parts.push_back(Anchor());
  const GapSearch search = Search(MakeAssembly(parts), 1.0);
  ExpectWithinTwoPercent(search, 20 * 12 * 1, "walls half a voxel thick");
  ASSERT_EQ(search.gaps.size(), 1u);
  EXPECT_EQ(search.gaps[0].voxels, 0);
}

TEST(GapSearch, AThinCavityInsideAnotherPartIsNoGap) {
  // The plates of a thin cavity overlap a block that holds all of them.
  std::vector<Part> parts = SealedBox(20, 12, 1.3, 2);
  parts.push_back(Slab("block", {-5, -5, -5}, {25, 17, 7}));
  const RigidTransform X_WA(Eigen::Matrix3d::Identity(), Eigen::Vector3d::Constant(0.37));
  for (Part& part : parts) part.X_WP = X_WA;
  EXPECT_TRUE(Search(MakeAssembly(parts), 1.0).gaps.empty());
}

TEST(GapSearch, AShellWithWallsOnQuarterVoxelsDoesNotLeak) {
  // One piece, its inner faces a quarter or three quarters into the voxels, its outer faces on
  // voxel faces: octants cut by a face must not be taken as free.
  for (const double wall : {0.5, 1.5}) {
    const Part part = HollowBlock("shell", {0, 0, 0}, {12, 12, 12}, Eigen::Vector3d::Constant(wall),
                                  Eigen::Vector3d::Constant(12 - wall));
    const GapSearch search = Search(MakeAssembly({part}), 2.0);
    ASSERT_EQ(search.gaps.size(), 1u) << wall;
    ExpectBracketed(search.gaps[0], std::pow(12 - 2 * wall, 3), "shell");
  }
}

TEST(GapSearch, TheBoundShrinksOnAxisAlignedFaces) {
  // At half a voxel's shift the faces cross voxels; the stated error stays below 1% of the
  // volume where counting each partial voxel half would state about 50%.
  const GapSearch search = Search(ShiftedCavity(2, 0.25), 0.5);
  ASSERT_EQ(search.gaps.size(), 1u);
  EXPECT_LT(search.gaps[0].volume_error, 0.01 * 20 * 12 * 2);
}

TEST(GapSearch, RejectsBadVoxels) {
  const Assembly assembly = MakeAssembly(SealedBox(10, 10, 10, 1));
  EXPECT_THROW(Search(assembly, -1.0), std::invalid_argument);
  EXPECT_THROW(Search(assembly, 1e-6), std::invalid_argument);
}

}  // namespace
}  // namespace mechanist
