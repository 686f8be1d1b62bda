#include "kernel/mesh/mesh_check.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>

#include "kernel/assembly/assembly_check.h"

namespace mechanist {
namespace {

/// The unit cube [0, 1]^3: 8 vertices (corner i at (i & 1, i & 2, i & 4) scaled to 0/1) and
/// 12 outward-oriented triangles.
TriangleMesh UnitCube() {
  TriangleMesh mesh;
  for (int i = 0; i < 8; ++i) mesh.vertices.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    mesh.faces.push_back({q[0], q[1], q[2]});
    mesh.faces.push_back({q[0], q[2], q[3]});
  }
  return mesh;
}

void Flip(TriangleMesh::Face& face) { std::swap(face[1], face[2]); }

/// Problems() describes exactly the meshes ok() rejects.
void ExpectProblemsMatchOk(const MeshCheck& check) {
  const std::vector<std::string> problems = check.Problems();
  EXPECT_EQ(problems.empty(), check.ok()) << ::testing::PrintToString(problems);
  for (const std::string& problem : problems) EXPECT_FALSE(problem.empty());
}

bool AnyProblemContains(const MeshCheck& check, const std::string& text) {
  const std::vector<std::string> problems = check.Problems();
  return std::any_of(problems.begin(), problems.end(),
                     [&](const std::string& p) { return p.find(text) != std::string::npos; });
}

TEST(CheckAssembly, LikeProblemsOfSeveralPartsAreOneFinding) {
  // Three parts with their own copies of a cube missing a face, and a sound one: one
  // mesh_not_closed naming the three (the balls of a bearing, each its own solid).
  TriangleMesh open = UnitCube();
  open.faces.pop_back();
  AssemblySpec spec;
  for (const char* id : {"ball_c", "ball_a", "sound", "ball_b"}) {
    Part part;
    part.id = id;
    part.mesh = std::make_shared<TriangleMesh>(std::string(id) == "sound" ? UnitCube() : open);
    spec.parts.push_back(part);
  }
  const std::vector<Diagnostic> found = CheckAssembly(Assembly(std::move(spec)));
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].code, "mesh_not_closed");
  EXPECT_EQ(found[0].parts, (std::vector<std::string>{"ball_a", "ball_b", "ball_c"}));
  EXPECT_EQ(found[0].message.rfind("parts 'ball_a', 'ball_b' and 'ball_c': mesh is not closed", 0),
            0u)
      << found[0].message;
}

// Two unit cubes in one mesh sharing the vertical edge at (1, 1): watertight, but that edge
// belongs to four faces, as a sphere's poles do in a tessellator's output.
TriangleMesh TwoCubesSharingAnEdge() {
  TriangleMesh two = UnitCube();
  const TriangleMesh second = UnitCube();
  std::vector<std::int32_t> index(8);
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d v = second.vertices[i] + Eigen::Vector3d(1, 1, 0);
    const auto shared = std::find(two.vertices.begin(), two.vertices.begin() + 8, v);
    if (shared != two.vertices.begin() + 8) {
      index[i] = static_cast<std::int32_t>(shared - two.vertices.begin());
    } else {
      index[i] = static_cast<std::int32_t>(two.vertices.size());
      two.vertices.push_back(v);
    }
  }
  for (const TriangleMesh::Face& f : second.faces)
    two.faces.push_back({index[f[0]], index[f[1]], index[f[2]]});
  return two;
}

TEST(CheckAssembly, AWatertightMeshWithEdgesOfFourFacesIsOnlyNoted) {
  // Nothing for the designer to act on: an info, not the warning of an open mesh.
  const TriangleMesh two = TwoCubesSharingAnEdge();
  const MeshCheck check = CheckMesh(two);
  ASSERT_EQ(check.boundary_edges, 0u);
  ASSERT_GT(check.non_manifold_edges, 0u);
  AssemblySpec spec;
  Part part;
  part.id = "pair_of_cubes";
  part.mesh = std::make_shared<TriangleMesh>(two);
  spec.parts.push_back(part);
  const std::vector<Diagnostic> found = CheckAssembly(Assembly(std::move(spec)));
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].code, "mesh_non_manifold");
  EXPECT_EQ(found[0].severity, Severity::kInfo);
  EXPECT_NE(found[0].message.find("watertight"), std::string::npos) << found[0].message;
}

TEST(CheckAssembly, AStepSolidsTessellationIsNotFaultedForItsMeshersEdgesAndSlivers) {
  // Two cubes sharing an edge (edges of four faces) and a zero-area face: said for a mesh the
  // designer gave, not for Open CASCADE's tessellation of a STEP solid.
  TriangleMesh two = TwoCubesSharingAnEdge();
  two.faces.push_back({0, 0, 1});  // a sliver
  const MeshCheck check = CheckMesh(two);
  ASSERT_GT(check.degenerate_faces, 0u);
  for (const bool tessellated : {false, true}) {
    AssemblySpec spec;
    Part part;
    part.id = "cubes";
    part.mesh = std::make_shared<TriangleMesh>(two);
    part.tessellated = tessellated;
    spec.parts.push_back(part);
    std::vector<std::string> codes;
    for (const Diagnostic& d : CheckAssembly(Assembly(std::move(spec)))) codes.push_back(d.code);
    std::sort(codes.begin(), codes.end());
    if (tessellated) {
      EXPECT_TRUE(codes.empty()) << codes.front();
    } else {
      EXPECT_EQ(codes, (std::vector<std::string>{"mesh_degenerate_faces", "mesh_non_manifold"}));
    }
  }
}

TEST(MeshCheck, CubeIsOk) {
  const MeshCheck check = CheckMesh(UnitCube());
  EXPECT_TRUE(check.ok());
  EXPECT_TRUE(check.closed());
  EXPECT_TRUE(check.consistently_oriented());
  EXPECT_EQ(check.vertex_count, 8u);
  EXPECT_EQ(check.face_count, 12u);
  EXPECT_NEAR(check.signed_volume, 1.0, 1e-12);
  EXPECT_EQ(check.degenerate_faces + check.boundary_edges + check.non_manifold_edges +
                check.misoriented_edges + check.out_of_range_faces + check.non_finite_vertices,
            0u);
  ExpectProblemsMatchOk(check);
}

TEST(MeshCheck, FlippedFaceIsMisoriented) {
  TriangleMesh mesh = UnitCube();
  Flip(mesh.faces[5]);
  const MeshCheck check = CheckMesh(mesh);
  EXPECT_FALSE(check.ok());
  EXPECT_TRUE(check.closed());
  EXPECT_EQ(check.misoriented_edges, 3u);
  ExpectProblemsMatchOk(check);
  EXPECT_TRUE(AnyProblemContains(check, "consistently oriented"));
}

TEST(MeshCheck, FarApartIndicesAreCheckedAsNearOnes) {
  // The cube's vertices spread over 280,001 (unused ones between): edges keyed by indices
  // past 2^18 group as those of the compact cube.
  const TriangleMesh cube = UnitCube();
  TriangleMesh spread;
  spread.vertices.assign(280001, Eigen::Vector3d(0.5, 0.5, 0.5));
  for (int k = 0; k < 8; ++k) spread.vertices[40000 * k] = cube.vertices[k];
  for (TriangleMesh::Face f : cube.faces) {
    for (std::int32_t& i : f) i *= 40000;
    spread.faces.push_back(f);
  }
  EXPECT_TRUE(CheckMesh(spread).ok());
  Flip(spread.faces[5]);
  spread.faces.erase(spread.faces.begin() + 8);
  TriangleMesh compact = cube;
  Flip(compact.faces[5]);
  compact.faces.erase(compact.faces.begin() + 8);
  const MeshCheck spread_check = CheckMesh(spread), compact_check = CheckMesh(compact);
  EXPECT_EQ(spread_check.boundary_edges, compact_check.boundary_edges);
  EXPECT_EQ(spread_check.misoriented_edges, compact_check.misoriented_edges);
  EXPECT_EQ(spread_check.non_manifold_edges, compact_check.non_manifold_edges);
  EXPECT_EQ(spread_check.boundary_edges, 3u);
  EXPECT_EQ(spread_check.misoriented_edges, 2u);
}

TEST(MeshCheck, RemovedFaceLeavesBoundaryEdges) {
  TriangleMesh mesh = UnitCube();
  mesh.faces.erase(mesh.faces.begin() + 3);
  const MeshCheck check = CheckMesh(mesh);
  EXPECT_FALSE(check.ok());
  EXPECT_FALSE(check.closed());
  EXPECT_EQ(check.boundary_edges, 3u);
  EXPECT_EQ(check.misoriented_edges, 0u);
  ExpectProblemsMatchOk(check);
  EXPECT_TRUE(AnyProblemContains(check, "not closed"));
}

TEST(MeshCheck, AllFacesFlippedHasNegativeVolume) {
  TriangleMesh mesh = UnitCube();
  for (TriangleMesh::Face& face : mesh.faces) Flip(face);
  const MeshCheck check = CheckMesh(mesh);
  EXPECT_FALSE(check.ok());
  EXPECT_TRUE(check.closed());
  EXPECT_TRUE(check.consistently_oriented());
  EXPECT_NEAR(check.signed_volume, -1.0, 1e-12);
  ExpectProblemsMatchOk(check);
  ASSERT_EQ(check.Problems().size(), 1u);
  EXPECT_TRUE(AnyProblemContains(check, "negative volume"));
}

TEST(MeshCheck, EdgeSharedByThreeFacesIsNonManifold) {
  TriangleMesh mesh = UnitCube();
  mesh.vertices.emplace_back(0.5, -1, 0.5);
  mesh.faces.push_back({0, 1, 8});  // a fin on the edge from corner 0 to corner 1
  const MeshCheck check = CheckMesh(mesh);
  EXPECT_FALSE(check.ok());
  EXPECT_EQ(check.non_manifold_edges, 1u);
  EXPECT_EQ(check.boundary_edges, 2u);
  ExpectProblemsMatchOk(check);
}

TEST(MeshCheck, RepeatedIndexIsDegenerate) {
  TriangleMesh mesh = UnitCube();
  mesh.faces.push_back({2, 2, 5});
  const MeshCheck check = CheckMesh(mesh);
  EXPECT_FALSE(check.ok());
  EXPECT_EQ(check.degenerate_faces, 1u);
  ExpectProblemsMatchOk(check);
  EXPECT_TRUE(AnyProblemContains(check, "degenerate"));
}

TEST(MeshCheck, ZeroAreaFaceIsDegenerate) {
  // Two back-to-back triangles along the cube edge from corner 0 to corner 1.
  TriangleMesh mesh = UnitCube();
  mesh.vertices.emplace_back(0.5, 0, 0);
  mesh.faces.push_back({0, 8, 1});
  mesh.faces.push_back({0, 1, 8});
  const MeshCheck check = CheckMesh(mesh);
  EXPECT_EQ(check.degenerate_faces, 2u);
  EXPECT_FALSE(check.ok());
  ExpectProblemsMatchOk(check);
}

TEST(MeshCheck, OutOfRangeIndexIsReported) {
  TriangleMesh mesh = UnitCube();
  mesh.faces[0][2] = 99;
  mesh.faces[1][0] = -1;
  const MeshCheck check = CheckMesh(mesh);
  EXPECT_FALSE(check.ok());
  EXPECT_EQ(check.out_of_range_faces, 2u);
  ExpectProblemsMatchOk(check);
  EXPECT_TRUE(AnyProblemContains(check, "missing vertices"));
}

TEST(MeshCheck, NanVertexIsReported) {
  TriangleMesh mesh = UnitCube();
  mesh.vertices[7].x() = std::nan("");
  const MeshCheck check = CheckMesh(mesh);
  EXPECT_FALSE(check.ok());
  EXPECT_EQ(check.non_finite_vertices, 1u);
  // Only the six faces around the bad vertex lose their area.
  EXPECT_EQ(check.degenerate_faces, 6u);
  ExpectProblemsMatchOk(check);
  EXPECT_TRUE(AnyProblemContains(check, "non-finite"));
}

TEST(MeshCheck, EmptyMeshHasNoFaces) {
  const MeshCheck check = CheckMesh(TriangleMesh());
  EXPECT_FALSE(check.ok());
  EXPECT_EQ(check.face_count, 0u);
  ExpectProblemsMatchOk(check);
  EXPECT_TRUE(AnyProblemContains(check, "no faces"));
}

}  // namespace
}  // namespace mechanist
