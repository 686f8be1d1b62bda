#include "kernel/assembly/assembly.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>

#include "kernel/assembly/assembly_state.h"

namespace mechanist {
namespace {

std::shared_ptr<const TriangleMesh> UnitCube() {
  auto mesh = std::make_shared<TriangleMesh>();
  for (int i = 0; i < 8; ++i) mesh->vertices.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    mesh->faces.push_back({q[0], q[1], q[2]});
    mesh->faces.push_back({q[0], q[2], q[3]});
  }
  return mesh;
}

Feature MakeFeature(const std::string& id, FeatureKind kind) {
  Feature feature;
  feature.id = id;
  feature.kind = kind;
  return feature;
}

/// Two parts sharing a cube mesh: "base" (ground, features "bore" and "top") and "gear"
/// (features "axle" and "teeth", a quarter turn about z at (10, 0, 0)), and a driver on
/// gear/axle.
AssemblySpec ValidSpec() {
  AssemblySpec spec;
  spec.name = "test";
  const auto cube = UnitCube();
  Part base;
  base.id = "base";
  base.mesh = cube;
  base.ground = true;
  base.features = {MakeFeature("bore", FeatureKind::kHole), MakeFeature("top", FeatureKind::kFace)};
  Part gear;
  gear.id = "gear";
  gear.mesh = cube;
  gear.X_WP = RigidTransform::Translation(Eigen::Vector3d(10, 0, 0)) *
              RigidTransform::AxisAngle(Eigen::Vector3d::UnitZ(), std::numbers::pi / 2);
  gear.features = {MakeFeature("axle", FeatureKind::kShaft),
                   MakeFeature("teeth", FeatureKind::kGear)};
  spec.parts = {base, gear};
  Driver driver;
  driver.id = "motor";
  driver.feature = {1, 0};
  driver.relative_to = 0;
  spec.drivers = {driver};
  return spec;
}

/// The message of the std::invalid_argument that Assembly(spec) throws, or "" (a test failure).
std::string ConstructionError(AssemblySpec spec) {
  try {
    Assembly assembly(std::move(spec));
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  ADD_FAILURE() << "Assembly accepted the spec";
  return "";
}

TEST(Assembly, KeepsTheDescription) {
  const Assembly assembly(ValidSpec());
  EXPECT_EQ(assembly.name(), "test");
  ASSERT_EQ(assembly.parts().size(), 2u);
  EXPECT_EQ(assembly.part(1).id, "gear");
  EXPECT_EQ(assembly.drivers().size(), 1u);
  EXPECT_EQ(assembly.feature({1, 1}).kind, FeatureKind::kGear);
}

TEST(Assembly, FindsPartsAndFeaturesByName) {
  const Assembly assembly(ValidSpec());
  EXPECT_EQ(assembly.FindPart("base"), 0u);
  EXPECT_EQ(assembly.FindPart("gear"), 1u);
  EXPECT_FALSE(assembly.FindPart("Gear"));
  EXPECT_FALSE(assembly.FindPart(""));

  EXPECT_EQ(assembly.FindFeature("gear/teeth"), (FeatureRef{1, 1}));
  EXPECT_EQ(assembly.FindFeature("base/bore"), (FeatureRef{0, 0}));
  EXPECT_FALSE(assembly.FindFeature("gear"));
  EXPECT_FALSE(assembly.FindFeature("gear/"));
  EXPECT_FALSE(assembly.FindFeature("gear/bore"));
  EXPECT_FALSE(assembly.FindFeature("shaft/axle"));
  EXPECT_FALSE(assembly.FindFeature("/axle"));
}

TEST(Assembly, FeatureNameRoundTrips) {
  const Assembly assembly(ValidSpec());
  EXPECT_EQ(assembly.FeatureName({0, 1}), "base/top");
  EXPECT_EQ(assembly.FeatureName({1, 0}), "gear/axle");
  for (const std::string name : {"base/bore", "base/top", "gear/axle", "gear/teeth"}) {
    const auto ref = assembly.FindFeature(name);
    ASSERT_TRUE(ref) << name;
    EXPECT_EQ(assembly.FeatureName(*ref), name);
  }
}

TEST(Assembly, IndicesAndRanksOfPartsAndFeatures) {
  // Parts and features shuffled; sorting by rank must equal sorting the ids (the oracle).
  AssemblySpec spec;
  spec.name = "ranks";
  // "gear" with "gear-2" and "gear.b": ids extended by characters below '/', where ordering by
  // name "id/feature" and by id differ.
  const std::vector<std::string> part_ids = {"motor", "gear10", "gear-2", "base",
                                             "Arm",   "gear",   "gear.b", "gear2"};
  const std::vector<std::string> feature_ids = {"teeth", "bore", "axle", "Z", "axle2"};
  for (const std::string& id : part_ids) {
    Part part;
    part.id = id;
    part.mesh = UnitCube();
    for (const std::string& f : feature_ids) {
      part.features.push_back(MakeFeature(f, FeatureKind::kHole));
    }
    std::rotate(part.features.begin(), part.features.begin() + part.id.size() % 5,
                part.features.end());
    spec.parts.push_back(part);
  }
  const Assembly assembly(std::move(spec));
  // Flat indices count the features, parts in order.
  std::size_t next = 0;
  for (std::size_t x = 0; x < part_ids.size(); ++x) {
    for (std::size_t f = 0; f < assembly.part(x).features.size(); ++f) {
      EXPECT_EQ(assembly.FeatureIndex({x, f}), next++);
    }
  }
  EXPECT_EQ(assembly.feature_count(), next);
  // All of them are holes: listed by kind in the same order.
  const std::vector<FeatureRef>& holes = assembly.FeaturesOfKind(FeatureKind::kHole);
  ASSERT_EQ(holes.size(), next);
  for (std::size_t i = 0; i < holes.size(); ++i) EXPECT_EQ(assembly.FeatureIndex(holes[i]), i);
  for (std::size_t x = 0; x < part_ids.size(); ++x) {
    for (std::size_t y = 0; y < part_ids.size(); ++y) {
      EXPECT_EQ(assembly.PartRank(x) < assembly.PartRank(y), part_ids[x] < part_ids[y]);
    }
  }
  // Feature name ranks against comparing the names themselves.
  for (std::size_t x = 0; x < part_ids.size(); ++x) {
    for (std::size_t y = 0; y < part_ids.size(); ++y) {
      for (std::size_t f = 0; f < feature_ids.size(); ++f) {
        for (std::size_t g = 0; g < feature_ids.size(); ++g) {
          EXPECT_EQ(assembly.FeatureNameRank({x, f}) < assembly.FeatureNameRank({y, g}),
                    assembly.FeatureName({x, f}) < assembly.FeatureName({y, g}));
        }
      }
    }
  }
}

TEST(Assembly, ListsFeaturesByKind) {
  const Assembly assembly(ValidSpec());
  using Refs = std::vector<FeatureRef>;
  EXPECT_EQ(assembly.FeaturesOfKind(FeatureKind::kHole), (Refs{{0, 0}}));
  EXPECT_EQ(assembly.FeaturesOfKind(FeatureKind::kFace), (Refs{{0, 1}}));
  EXPECT_EQ(assembly.FeaturesOfKind(FeatureKind::kShaft), (Refs{{1, 0}}));
  EXPECT_EQ(assembly.FeaturesOfKind(FeatureKind::kGear), (Refs{{1, 1}}));
  EXPECT_TRUE(assembly.FeaturesOfKind(FeatureKind::kThread).empty());
}

TEST(Assembly, PartsMovingAsOneAreNamedAfterTheLargest) {
  // Boxes of 1, 3 and 1 mm^3 and a part without a mesh (a features-only pin).
  AssemblySpec spec;
  auto rod = std::make_shared<TriangleMesh>(*UnitCube());
  for (Eigen::Vector3d& v : rod->vertices) v.x() *= 3;
  const std::vector<std::shared_ptr<const TriangleMesh>> meshes = {UnitCube(), rod, nullptr,
                                                                   UnitCube()};
  for (std::size_t p = 0; p < meshes.size(); ++p) {
    Part part;
    part.id = "part" + std::to_string(p);
    part.mesh = meshes[p];
    part.features.push_back(MakeFeature("f", FeatureKind::kFace));
    spec.parts.push_back(part);
  }
  const Assembly assembly(std::move(spec));
  using Parts = std::vector<std::size_t>;
  EXPECT_EQ(MainPart(assembly, Parts{0, 1, 2, 3}), 1u);
  EXPECT_EQ(MainPart(assembly, Parts{3, 2, 0}), 3u);  // the first of equals, as given
  EXPECT_EQ(MainPart(assembly, Parts{2, 0}), 0u);     // a part without a mesh counts as none
  EXPECT_EQ(MainPart(assembly, Parts{2}), 2u);
  EXPECT_THROW(MainPart(assembly, Parts{}), std::logic_error);
}

TEST(Assembly, CompactTablesAgreeWithTheParts) {
  // Parts of 0, 3 and 1 features, the middle one ground, the last with a mesh of its own
  // (the first two share one) and each at its own pose: the per-feature kinds and origins,
  // per-part ground flags, ids, feature counts, file poses and mesh boxes, and the feature
  // names against the parts themselves.
  AssemblySpec spec;
  const std::vector<std::vector<FeatureKind>> kinds = {
      {}, {FeatureKind::kGear, FeatureKind::kHole, FeatureKind::kFace}, {FeatureKind::kShaft}};
  const auto shared = UnitCube();
  auto stretched = std::make_shared<TriangleMesh>(*shared);
  for (Eigen::Vector3d& v : stretched->vertices) v.x() *= 3;
  for (std::size_t p = 0; p < kinds.size(); ++p) {
    Part part;
    part.id = "part" + std::to_string(p);
    part.mesh = p == 2 ? std::shared_ptr<const TriangleMesh>(stretched) : shared;
    part.ground = p == 1;
    part.X_WP = RigidTransform::Translation(Eigen::Vector3d(p, 2.0 * p, -1));
    for (std::size_t f = 0; f < kinds[p].size(); ++f) {
      part.features.push_back(MakeFeature("f" + std::to_string(f), kinds[p][f]));
      part.features.back().origin = Eigen::Vector3d(0.5 * f, p, 0.25);
    }
    spec.parts.push_back(part);
  }
  const Assembly assembly(std::move(spec));
  ASSERT_EQ(assembly.FilePoses().size(), kinds.size());
  for (std::size_t p = 0; p < kinds.size(); ++p) {
    EXPECT_EQ(assembly.IsGround(p), assembly.part(p).ground);
    EXPECT_EQ(assembly.FeatureCount(p), assembly.part(p).features.size());
    EXPECT_TRUE(assembly.FilePoses()[p].IsNearlyEqualTo(assembly.part(p).X_WP, 0.0, 0.0)) << p;
    const Aabb expected = assembly.part(p).mesh->Bounds();
    EXPECT_EQ(assembly.MeshBox(p).min, expected.min) << p;
    EXPECT_EQ(assembly.MeshBox(p).max, expected.max) << p;
    EXPECT_EQ(assembly.PartId(p), assembly.part(p).id);
    for (std::size_t f = 0; f < kinds[p].size(); ++f) {
      EXPECT_EQ(assembly.kind({p, f}), assembly.feature({p, f}).kind);
      EXPECT_EQ(assembly.FeatureOrigin({p, f}), assembly.feature({p, f}).origin);
      EXPECT_EQ(assembly.FeatureName({p, f}),
                assembly.part(p).id + "/" + assembly.feature({p, f}).id);
    }
  }
  EXPECT_EQ(assembly.MeshBox(2).max.x(), 3.0);
  EXPECT_THROW(assembly.IsGround(3), std::out_of_range);
  EXPECT_THROW(assembly.FeatureCount(3), std::out_of_range);
  EXPECT_THROW(assembly.MeshBox(3), std::out_of_range);
  EXPECT_THROW(assembly.PartId(3), std::out_of_range);
  // A feature index past its part's features is no feature (not the next part's first).
  EXPECT_THROW(assembly.FeatureName({1, 3}), std::out_of_range);
  EXPECT_THROW(assembly.FeatureName({0, 0}), std::out_of_range);
  EXPECT_THROW(assembly.FeatureName({3, 0}), std::out_of_range);
}

TEST(Assembly, SameFeatureIdInDifferentPartsIsAllowed) {
  AssemblySpec spec = ValidSpec();
  spec.parts[1].features[0].id = "bore";
  const Assembly assembly(std::move(spec));
  EXPECT_EQ(assembly.FindFeature("gear/bore"), (FeatureRef{1, 0}));
  EXPECT_EQ(assembly.FindFeature("base/bore"), (FeatureRef{0, 0}));
}

TEST(Assembly, RejectsDuplicatePartIds) {
  AssemblySpec spec = ValidSpec();
  spec.parts[1].id = "base";
  EXPECT_NE(ConstructionError(std::move(spec)).find("'base'"), std::string::npos);
}

TEST(Assembly, RejectsDuplicateFeatureIds) {
  AssemblySpec spec = ValidSpec();
  spec.parts[1].features[1].id = "axle";
  const std::string message = ConstructionError(std::move(spec));
  EXPECT_NE(message.find("'axle'"), std::string::npos) << message;
  EXPECT_NE(message.find("'gear'"), std::string::npos) << message;
}

TEST(Assembly, APartWithoutMeshIsFeaturesOnly) {
  AssemblySpec spec = ValidSpec();
  spec.parts[0].mesh.reset();
  const Assembly assembly(std::move(spec));
  ASSERT_NE(assembly.part(0).mesh, nullptr);
  EXPECT_TRUE(assembly.part(0).mesh->faces.empty());
  EXPECT_FALSE(assembly.part(0).HasGeometry());
  EXPECT_TRUE(assembly.part(1).HasGeometry());
  EXPECT_TRUE(assembly.MeshBox(0).empty());
}

TEST(Assembly, RejectsADriverOnAMissingPart) {
  AssemblySpec spec = ValidSpec();
  spec.drivers[0].feature = {2, 0};
  EXPECT_NE(ConstructionError(std::move(spec)).find("driver"), std::string::npos);
}

TEST(Assembly, RejectsADriverOnAMissingFeature) {
  AssemblySpec spec = ValidSpec();
  spec.drivers[0].feature = {1, 2};
  const std::string message = ConstructionError(std::move(spec));
  EXPECT_NE(message.find("driver"), std::string::npos) << message;
  EXPECT_NE(message.find("'gear'"), std::string::npos) << message;
}

TEST(Assembly, RejectsADriverRelativeToAMissingPart) {
  AssemblySpec spec = ValidSpec();
  spec.drivers[0].relative_to = 5;
  EXPECT_NE(ConstructionError(std::move(spec)).find("relative_to"), std::string::npos);
}

TEST(Assembly, RejectsOtherBadReferences) {
  {
    AssemblySpec spec = ValidSpec();
    spec.adjustments.push_back({"turn", 3, Adjustment::Kind::kRotate, {1, 0}, 0.0, 1.0});
    ConstructionError(std::move(spec));
  }
  {
    AssemblySpec spec = ValidSpec();
    spec.goals.push_back({Goal::Kind::kMesh, {FeatureRef{1, 1}, FeatureRef{0, 9}}});
    ConstructionError(std::move(spec));
  }
  {
    AssemblySpec spec = ValidSpec();
    spec.steps.push_back({FeatureRef{1, 0}, FeatureRef{7, 0}});
    ConstructionError(std::move(spec));
  }
  {
    AssemblySpec spec = ValidSpec();
    PlacementCondition condition;
    condition.feature = 2;  // the gear has two features
    condition.target = {0, 0};
    spec.parts[1].placement.push_back(condition);
    ConstructionError(std::move(spec));
  }
  {
    AssemblySpec spec = ValidSpec();
    Expectation expectation;
    expectation.kind = Expectation::Kind::kSameSubassembly;
    expectation.parts = {0, 4};
    spec.expectations.push_back(expectation);
    ConstructionError(std::move(spec));
  }
}

TEST(Assembly, InitialStateCopiesThePoses) {
  const Assembly assembly(ValidSpec());
  const AssemblyState state = InitialState(assembly);
  ASSERT_EQ(state.X_WP.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_TRUE(state.X_WP[i].IsNearlyEqualTo(assembly.part(i).X_WP, 0.0, 0.0)) << i;
  }
  EXPECT_FALSE(state.X_WP[0].IsNearlyEqualTo(state.X_WP[1], 1.0, 1.0));
}

TEST(Assembly, WorldBoxPlacesTheMeshBoxAtTheStatePose) {
  const Assembly assembly(ValidSpec());
  AssemblyState state = InitialState(assembly);
  const Aabb base = WorldBox(assembly, state, 0);
  EXPECT_TRUE(base.min.isApprox(Eigen::Vector3d(0, 0, 0)));
  EXPECT_TRUE(base.max.isApprox(Eigen::Vector3d(1, 1, 1)));
  // A quarter turn about z takes the cube's x in [0, 1] to y in [0, 1] and y to x in [-1, 0].
  const Aabb gear = WorldBox(assembly, state, 1);
  EXPECT_LE((gear.min - Eigen::Vector3d(9, 0, 0)).norm(), 1e-12);
  EXPECT_LE((gear.max - Eigen::Vector3d(10, 1, 1)).norm(), 1e-12);
  // The state's pose counts, not the file's.
  state.X_WP[1] = RigidTransform::Translation(Eigen::Vector3d(0, 0, 5));
  const Aabb moved = WorldBox(assembly, state, 1);
  EXPECT_LE((moved.min - Eigen::Vector3d(0, 0, 5)).norm(), 1e-12);
  EXPECT_LE((moved.max - Eigen::Vector3d(1, 1, 6)).norm(), 1e-12);
}

}  // namespace
}  // namespace mechanist
