#include "io/mesh_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "io/input_error.h"
#include "kernel/mesh/mesh_check.h"

namespace mechanist {
namespace {

namespace fs = std::filesystem;

/// The unit cube's corner i is (i & 1, i & 2, i & 4) scaled to 0/1.
Eigen::Vector3d CubeCorner(int i) { return Eigen::Vector3d(i & 1, (i >> 1) & 1, (i >> 2) & 1); }

/// The cube's faces as quads, counter-clockwise seen from outside.
constexpr std::array<std::array<int, 4>, 6> kCubeQuads = {{
    {0, 2, 3, 1},  // z = 0
    {4, 5, 7, 6},  // z = 1
    {0, 1, 5, 4},  // y = 0
    {2, 6, 7, 3},  // y = 1
    {0, 4, 6, 2},  // x = 0
    {1, 3, 7, 5},  // x = 1
}};

/// The cube's twelve triangles as corner indices.
std::vector<std::array<int, 3>> CubeTriangles() {
  std::vector<std::array<int, 3>> triangles;
  for (const auto& q : kCubeQuads) {
    triangles.push_back({q[0], q[1], q[2]});
    triangles.push_back({q[0], q[2], q[3]});
  }
  return triangles;
}

/// Appends `value`'s bytes in the given byte order.
template <class T>
void Put(std::string& out, T value, bool big_endian = false) {
  auto bytes = std::bit_cast<std::array<char, sizeof(T)>>(value);
  if (big_endian != (std::endian::native == std::endian::big)) {
    std::reverse(bytes.begin(), bytes.end());
  }
  out.append(bytes.data(), bytes.size());
}

/// A binary STL of the unit cube (12 triangles) with the given 80-byte header text.
std::string BinaryStlCube(std::string_view header_text) {
  std::string out(80, ' ');
  std::copy(header_text.begin(), header_text.end(), out.begin());
  const auto triangles = CubeTriangles();
  Put<std::uint32_t>(out, static_cast<std::uint32_t>(triangles.size()));
  for (const auto& t : triangles) {
    for (int i = 0; i < 3; ++i) Put<float>(out, 0.0f);  // normal: readers ignore it
    for (int corner : t) {
      for (int i = 0; i < 3; ++i) Put<float>(out, static_cast<float>(CubeCorner(corner)[i]));
    }
    Put<std::uint16_t>(out, 0);
  }
  return out;
}

std::string AsciiStlCube() {
  std::string out = "solid cube\n";
  for (const auto& t : CubeTriangles()) {
    out += "  facet normal 0 0 0\n    outer loop\n";
    for (int corner : t) {
      const Eigen::Vector3d p = CubeCorner(corner);
      out += "      vertex " + std::to_string(p.x()) + " " + std::to_string(p.y()) + " " +
             std::to_string(p.z()) + "\n";
    }
    out += "    endloop\n  endfacet\n";
  }
  return out + "endsolid cube\n";
}

/// A PLY cube in `format` with properties the reader must skip: colours, a short, an extra
/// face scalar and list, and a trailing "edge" element; z is a double, the rest floats.
std::string PlyCube(const std::string& format) {
  std::string out = "ply\nformat " + format +
                    " 1.0\n"
                    "comment written by the mesh reader test\n"
                    "element vertex 8\n"
                    "property float x\nproperty float y\nproperty double z\n"
                    "property uchar red\nproperty short s\n"
                    "element face 6\n"
                    "property uchar flags\n"
                    "property list uchar int vertex_indices\n"
                    "property list ushort float texcoord\n"
                    "element edge 1\n"
                    "property int vertex1\nproperty int vertex2\n"
                    "end_header\n";
  if (format == "ascii") {
    for (int i = 0; i < 8; ++i) {
      const Eigen::Vector3d p = CubeCorner(i);
      out += std::to_string(p.x()) + " " + std::to_string(p.y()) + " " + std::to_string(p.z()) +
             " 255 -7\n";
    }
    for (const auto& q : kCubeQuads) {
      out += "9 4 " + std::to_string(q[0]) + " " + std::to_string(q[1]) + " " +
             std::to_string(q[2]) + " " + std::to_string(q[3]) + " 2 0.5 0.25\n";
    }
    return out + "0 1\n";
  }
  const bool big = format == "binary_big_endian";
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d p = CubeCorner(i);
    Put<float>(out, static_cast<float>(p.x()), big);
    Put<float>(out, static_cast<float>(p.y()), big);
    Put<double>(out, p.z(), big);
    Put<std::uint8_t>(out, 255, big);
    Put<std::int16_t>(out, -7, big);
  }
  for (const auto& q : kCubeQuads) {
    Put<std::uint8_t>(out, 9, big);
    Put<std::uint8_t>(out, 4, big);
    for (int corner : q) Put<std::int32_t>(out, corner, big);
    Put<std::uint16_t>(out, 2, big);
    Put<float>(out, 0.5f, big);
    Put<float>(out, 0.25f, big);
  }
  Put<std::int32_t>(out, 0, big);
  Put<std::int32_t>(out, 1, big);
  return out;
}

/// Each test writes its files into its own fresh directory.
class MeshReader : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    dir_ = fs::temp_directory_path() /
           ("mechanist_mesh_reader_" + name + "_" + std::to_string(std::random_device{}()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path Write(const std::string& name, std::string_view contents) const {
    const fs::path path = dir_ / name;
    std::ofstream(path, std::ios::binary).write(contents.data(), contents.size());
    return path;
  }

  fs::path dir_;
};

/// The InputError ReadMesh throws for `path`, or nothing (a test failure) when it reads it.
std::optional<InputError> ReadError(const fs::path& path) {
  try {
    ReadMesh(path);
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "ReadMesh accepted " << path;
  return std::nullopt;
}

bool Contains(const char* text, std::string_view part) {
  return std::string_view(text).find(part) != std::string_view::npos;
}

/// Expects the unit cube: 8 shared vertices, 12 triangles, volume 1, a valid closed mesh.
void ExpectUnitCube(const TriangleMesh& mesh) {
  EXPECT_EQ(mesh.vertices.size(), 8u);
  EXPECT_EQ(mesh.faces.size(), 12u);
  EXPECT_NEAR(mesh.SignedVolume(), 1.0, 1e-12);
  const MeshCheck check = CheckMesh(mesh);
  EXPECT_TRUE(check.ok()) << ::testing::PrintToString(check.Problems());
}

TEST_F(MeshReader, ReadsAsciiStlAndWeldsVertices) {
  ExpectUnitCube(ReadMesh(Write("cube.stl", AsciiStlCube())));
}

TEST_F(MeshReader, ReadsAsciiStlWithCrlfUppercaseAndSeveralSolids) {
  std::string text = AsciiStlCube();
  // A second copy of the cube as another solid; welding makes its vertices the same.
  text += text;
  std::string crlf;
  for (char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  std::transform(crlf.begin(), crlf.end(), crlf.begin(), ::toupper);
  const TriangleMesh mesh = ReadMesh(Write("CUBE.STL", "  " + crlf));
  EXPECT_EQ(mesh.vertices.size(), 8u);
  EXPECT_EQ(mesh.faces.size(), 24u);
}

TEST_F(MeshReader, ReadsBinaryStl) {
  ExpectUnitCube(ReadMesh(Write("cube.stl", BinaryStlCube("binary cube"))));
}

TEST_F(MeshReader, ReadsBinaryStlWhoseHeaderStartsWithSolid) {
  ExpectUnitCube(ReadMesh(Write("cube.stl", BinaryStlCube("solid cube exported by a CAD tool"))));
}

TEST_F(MeshReader, WeldsALargeBinaryStlGrid) {
  // An n x n grid of unit squares in the plane z = 0: (n + 1)^2 distinct vertices.
  constexpr int n = 150;
  std::string out(80, ' ');
  Put<std::uint32_t>(out, 2 * n * n);
  auto corner = [&out](int i, int j) {
    Put<float>(out, static_cast<float>(i));
    Put<float>(out, static_cast<float>(j));
    Put<float>(out, -0.0f);  // -0 and +0 are the same coordinate
  };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (const auto& t : {std::array<int, 6>{0, 0, 1, 0, 1, 1}, {0, 0, 1, 1, 0, 1}}) {
        for (int k = 0; k < 3; ++k) Put<float>(out, 0.0f);
        for (int k = 0; k < 3; ++k) corner(i + t[2 * k], j + t[2 * k + 1]);
        Put<std::uint16_t>(out, 0);
      }
    }
  }
  const TriangleMesh mesh = ReadMesh(Write("grid.stl", out));
  EXPECT_EQ(mesh.vertices.size(), static_cast<std::size_t>((n + 1) * (n + 1)));
  ASSERT_EQ(mesh.faces.size(), static_cast<std::size_t>(2 * n * n));
  EXPECT_NEAR(mesh.Area(), n * n, 1e-6);
  const MeshCheck check = CheckMesh(mesh);
  EXPECT_EQ(check.boundary_edges, static_cast<std::size_t>(4 * n));
  EXPECT_EQ(check.misoriented_edges, 0u);
}

TEST_F(MeshReader, ReadsObjWithQuadsNormalsAndNegativeIndices) {
  std::string text = "# cube\r\nmtllib cube.mtl\r\no cube\r\n";
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d p = CubeCorner(i);
    text += "  v " + std::to_string(p.x()) + "\t" + std::to_string(p.y()) + " " +
            std::to_string(p.z()) + "   \r\n";
  }
  text += "vn 0 0 1\r\nvt 0 0\r\ns off\r\n";
  for (std::size_t f = 0; f < kCubeQuads.size(); ++f) {
    text += "f";
    for (int corner : kCubeQuads[f]) {
      // Alternate the index forms: v//vn, negative v/vt/vn, v/vt, plain v.
      const std::array<std::string, 4> forms = {
          std::to_string(corner + 1) + "//1", std::to_string(corner - 8) + "/1/1",
          std::to_string(corner + 1) + "/1", std::to_string(corner + 1)};
      text += ' ';
      text += forms[f % 4];
    }
    text += " # quad\r\n";
  }
  ExpectUnitCube(ReadMesh(Write("cube.obj", text)));
}

TEST_F(MeshReader, ReadsObjFacesListedBeforeTheirVertices) {
  const TriangleMesh mesh = ReadMesh(Write("forward.obj", "f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"));
  ASSERT_EQ(mesh.faces.size(), 1u);
  EXPECT_EQ(mesh.faces[0], (TriangleMesh::Face{0, 1, 2}));
}

TEST_F(MeshReader, ReadsAsciiPlyWithExtraProperties) {
  ExpectUnitCube(ReadMesh(Write("cube.ply", PlyCube("ascii"))));
}

TEST_F(MeshReader, ReadsBinaryLittleEndianPly) {
  ExpectUnitCube(ReadMesh(Write("cube.ply", PlyCube("binary_little_endian"))));
}

TEST_F(MeshReader, ReadsBinaryBigEndianPly) {
  ExpectUnitCube(ReadMesh(Write("cube.PLY", PlyCube("binary_big_endian"))));
}

TEST_F(MeshReader, ReadsBinaryPlyWithCrlfHeader) {
  std::string text = PlyCube("binary_little_endian");
  const std::size_t end = text.find("end_header\n") + std::string("end_header").size();
  std::string header = text.substr(0, end + 1);
  std::string crlf;
  for (char c : header) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  ExpectUnitCube(ReadMesh(Write("cube.ply", crlf + text.substr(end + 1))));
}

TEST_F(MeshReader, ReadsOffWithCommentsAndCrlf) {
  std::string text = "OFF\r\n# a unit cube\r\n\r\n8 6 0   # counts\r\n";
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d p = CubeCorner(i);
    text +=
        std::to_string(p.x()) + " " + std::to_string(p.y()) + " " + std::to_string(p.z()) + "\r\n";
  }
  for (const auto& q : kCubeQuads) {
    text += "# face\r\n 4 " + std::to_string(q[0]) + " " + std::to_string(q[1]) + " " +
            std::to_string(q[2]) + " " + std::to_string(q[3]) + " 255 0 0\r\n";
  }
  ExpectUnitCube(ReadMesh(Write("cube.off", text)));
}

TEST_F(MeshReader, ReadsOffWithoutHeaderAndWithTooFewDeclaredFaces) {
  // The face count says 1, but the data holds 2 faces: each face line gives its own length.
  const TriangleMesh mesh =
      ReadMesh(Write("tet.off", "4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n"));
  EXPECT_EQ(mesh.vertices.size(), 4u);
  EXPECT_EQ(mesh.faces.size(), 2u);
}

TEST_F(MeshReader, ReadsFclObjWithCountHeaderAndCrlf) {
  const TriangleMesh env = ReadMesh(fs::path(MECHANIST_SHARED_DATA) / "fcl" / "env.obj");
  EXPECT_EQ(env.faces.size(), 2180u);
  EXPECT_EQ(env.vertices.size(), 6540u);
  const TriangleMesh rob = ReadMesh(fs::path(MECHANIST_SHARED_DATA) / "fcl" / "rob.obj");
  EXPECT_EQ(rob.faces.size(), 216u);
  EXPECT_EQ(CheckMesh(rob).out_of_range_faces, 0u);
}

TEST_F(MeshReader, WeldsARealBinaryStlIntoAClosedMesh) {
  const TriangleMesh gear =
      ReadMesh(fs::path(MECHANIST_SHARED_DATA) / "gears" / "spur_singles" / "spur_m1_z12.stl");
  EXPECT_EQ(gear.faces.size(), (81684u - 84u) / 50u);
  const MeshCheck check = CheckMesh(gear);
  EXPECT_TRUE(check.closed()) << ::testing::PrintToString(check.Problems());
  EXPECT_GT(check.signed_volume, 0.0);
}

// Errors.

TEST_F(MeshReader, TruncatedBinaryStlIsAnInputError) {
  const std::string cube = BinaryStlCube("binary cube");
  const fs::path path = Write("cut.stl", cube.substr(0, cube.size() - 20));
  const auto error = ReadError(path);
  ASSERT_TRUE(error);
  EXPECT_EQ(error->file(), path.string());
  EXPECT_EQ(error->line(), 0);
  EXPECT_TRUE(Contains(error->what(), path.string())) << error->what();
  EXPECT_TRUE(Contains(error->what(), "declares 12 triangles")) << error->what();
}

TEST_F(MeshReader, BinaryStlWithSolidHeaderAndWrongSizeIsAnInputError) {
  const fs::path path = Write("long.stl", BinaryStlCube("solid cube") + "extra");
  const auto error = ReadError(path);
  ASSERT_TRUE(error);
  EXPECT_TRUE(Contains(error->what(), "but the file has 689 bytes")) << error->what();
}

TEST_F(MeshReader, ShortBinaryStlIsAnInputError) {
  const auto error = ReadError(Write("short.stl", std::string("\0\1\2", 3)));
  ASSERT_TRUE(error);
  EXPECT_TRUE(Contains(error->what(), "at least 84 bytes")) << error->what();
}

TEST_F(MeshReader, NonFiniteBinaryStlCoordinateIsAnInputError) {
  std::string cube = BinaryStlCube("cube");
  const float inf = std::numeric_limits<float>::infinity();
  std::memcpy(cube.data() + 84 + 50 * 3 + 12, &inf, sizeof inf);
  const auto error = ReadError(Write("inf.stl", cube));
  ASSERT_TRUE(error);
  EXPECT_TRUE(Contains(error->what(), "triangle 3 (counting from 0)")) << error->what();
}

TEST_F(MeshReader, TruncatedAsciiStlNamesTheLastLine) {
  const std::string text = AsciiStlCube();
  // Cut after the first facet's second vertex line: lines 1-5 remain.
  std::size_t end = 0;
  for (int line = 0; line < 5; ++line) end = text.find('\n', end) + 1;
  const auto error = ReadError(Write("cut.stl", text.substr(0, end)));
  ASSERT_TRUE(error);
  EXPECT_EQ(error->line(), 5);
  EXPECT_TRUE(Contains(error->what(), "expected 'vertex' or 'endloop', found end of file"))
      << error->what();
}

TEST_F(MeshReader, BadNumberInAsciiStlNamesLineAndToken) {
  const fs::path path =
      Write("bad.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 O 0\n");
  const auto error = ReadError(path);
  ASSERT_TRUE(error);
  EXPECT_EQ(error->line(), 5);
  EXPECT_EQ(error->column(), 10);
  EXPECT_TRUE(Contains(error->what(), path.string() + ":5:10:")) << error->what();
  EXPECT_TRUE(Contains(error->what(), "expected 3 numbers after 'vertex', found 'O'"))
      << error->what();
}

TEST_F(MeshReader, BadNumberInObjNamesLineAndToken) {
  const fs::path path = Write("bad.obj", "# header\nv 0 0 0\nv 1 abc 0\nv 0 1 0\nf 1 2 3\n");
  const auto error = ReadError(path);
  ASSERT_TRUE(error);
  EXPECT_EQ(error->file(), path.string());
  EXPECT_EQ(error->line(), 3);
  EXPECT_TRUE(Contains(error->what(), "expected 3 numbers after 'v', found 'abc'"))
      << error->what();
}

TEST_F(MeshReader, MissingObjCoordinateSaysEndOfLine) {
  const auto error = ReadError(Write("short.obj", "v 0 0 0\nv 1 0\n"));
  ASSERT_TRUE(error);
  EXPECT_EQ(error->line(), 2);
  EXPECT_TRUE(Contains(error->what(), "found end of line")) << error->what();
}

TEST_F(MeshReader, NonFiniteObjCoordinateIsAnInputError) {
  const auto error = ReadError(Write("nan.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n"));
  ASSERT_TRUE(error);
  EXPECT_EQ(error->line(), 3);
  EXPECT_TRUE(Contains(error->what(), "finite")) << error->what();
}

TEST_F(MeshReader, ObjIndexOutOfRangeNamesItsLine) {
  const auto error = ReadError(Write("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 4\n"));
  ASSERT_TRUE(error);
  EXPECT_EQ(error->line(), 5);
  EXPECT_TRUE(Contains(error->what(), "vertex index 4 is out of range")) << error->what();
}

TEST_F(MeshReader, ObjNegativeIndexBeforeTheFirstVertexIsAnInputError) {
  const auto error = ReadError(Write("negative.obj", "v 0 0 0\nv 1 0 0\nf -1 -2 -3\n"));
  ASSERT_TRUE(error);
  EXPECT_EQ(error->line(), 3);
  EXPECT_TRUE(Contains(error->what(), "vertex index -3 is out of range")) << error->what();
}

TEST_F(MeshReader, ObjZeroIndexIsAnInputError) {
  const auto error = ReadError(Write("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"));
  ASSERT_TRUE(error);
  EXPECT_EQ(error->line(), 4);
  EXPECT_TRUE(Contains(error->what(), "found '0'")) << error->what();
}

TEST_F(MeshReader, ObjFaceWithTwoVerticesIsAnInputError) {
  const auto error = ReadError(Write("edge.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n"));
  ASSERT_TRUE(error);
  EXPECT_EQ(error->line(), 3);
  EXPECT_TRUE(Contains(error->what(), "at least 3 vertex indices")) << error->what();
}

TEST_F(MeshReader, MeshWithoutFacesIsAnInputError) {
  const auto error = ReadError(Write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"));
  ASSERT_TRUE(error);
  EXPECT_TRUE(Contains(error->what(), "no faces")) << error->what();
}

TEST_F(MeshReader, OffIndexOutOfRangeNamesItsLine) {
  const auto error = ReadError(Write("range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"));
  ASSERT_TRUE(error);
  EXPECT_EQ(error->line(), 6);
  EXPECT_EQ(error->column(), 7);
  EXPECT_TRUE(Contains(error->what(), "vertex index 3 is out of range")) << error->what();
}

TEST_F(MeshReader, OffWithMissingFacesIsAnInputError) {
  const auto error = ReadError(Write("cut.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
  ASSERT_TRUE(error);
  EXPECT_EQ(error->line(), 6);
  EXPECT_TRUE(Contains(error->what(), "expected 2 faces, found 1")) << error->what();
}

TEST_F(MeshReader, OffWithBadHeaderIsAnInputError) {
  const auto error = ReadError(Write("bad.off", "# comment\nMESH\n"));
  ASSERT_TRUE(error);
  EXPECT_EQ(error->line(), 2);
  EXPECT_TRUE(Contains(error->what(), "expected 'OFF'")) << error->what();
}

TEST_F(MeshReader, PlyIndexOutOfRangeNamesItsLine) {
  const auto error = ReadError(
      Write("range.ply",
            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
            "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
            "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"));
  ASSERT_TRUE(error);
  EXPECT_EQ(error->line(), 13);
  EXPECT_TRUE(Contains(error->what(), "vertex index 7 of face 0 is out of range")) << error->what();
}

TEST_F(MeshReader, AsciiPlyWithFewerElementsThanDeclaredIsAnInputError) {
  std::string text = PlyCube("ascii");
  text.replace(text.find("element edge 1"), 14, "element edge 2");
  const auto error = ReadError(Write("cut.ply", text));
  ASSERT_TRUE(error);
  EXPECT_EQ(error->line(), 32);  // the last line
  EXPECT_TRUE(Contains(error->what(),
                       "expected property 'vertex1' of edge 1, found end of file (the header "
                       "declares 2 edge elements)"))
      << error->what();
}

TEST_F(MeshReader, AsciiPlyWithMoreDataThanDeclaredIsAnInputError) {
  const auto error = ReadError(Write("long.ply", PlyCube("ascii") + "5 6\n"));
  ASSERT_TRUE(error);
  EXPECT_EQ(error->line(), 33);  // 17 header lines, 8 vertices, 6 faces, 1 edge
  EXPECT_TRUE(Contains(error->what(), "element counts")) << error->what();
}

TEST_F(MeshReader, TruncatedBinaryPlyIsAnInputError) {
  const std::string text = PlyCube("binary_big_endian");
  const auto error = ReadError(Write("cut.ply", text.substr(0, text.size() - 30)));
  ASSERT_TRUE(error);
  EXPECT_EQ(error->line(), 0);
  EXPECT_TRUE(Contains(error->what(), "of face 5")) << error->what();
  EXPECT_TRUE(Contains(error->what(), "found end of file")) << error->what();
}

TEST_F(MeshReader, PlyWithoutVertexIndicesIsAnInputError) {
  const auto error = ReadError(Write(
      "noindices.ply",
      "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
      "property float z\nelement face 0\nproperty list uchar float vertex_indices\nend_header\n"));
  ASSERT_TRUE(error);
  EXPECT_EQ(error->line(), 7);
  EXPECT_TRUE(Contains(error->what(), "'vertex_indices'")) << error->what();
  EXPECT_TRUE(Contains(error->what(), "found a list of reals")) << error->what();
}

TEST_F(MeshReader, PlyWithUnknownTypeNamesLineAndColumn) {
  const auto error = ReadError(
      Write("type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty real x\nend_header\n"));
  ASSERT_TRUE(error);
  EXPECT_EQ(error->line(), 4);
  EXPECT_EQ(error->column(), 10);
  EXPECT_TRUE(Contains(error->what(), "found 'real'")) << error->what();
}

TEST_F(MeshReader, MissingFileIsAnInputError) {
  const fs::path path = dir_ / "absent.stl";
  const auto error = ReadError(path);
  ASSERT_TRUE(error);
  EXPECT_EQ(error->file(), path.string());
  EXPECT_TRUE(Contains(error->what(), "not found")) << error->what();
}

TEST_F(MeshReader, UnknownExtensionListsTheSupportedOnes) {
  const fs::path path = Write("cube.xyz", AsciiStlCube());
  const auto error = ReadError(path);
  ASSERT_TRUE(error);
  EXPECT_TRUE(Contains(error->what(), path.string())) << error->what();
  EXPECT_TRUE(Contains(error->what(), "'.xyz'")) << error->what();
  EXPECT_TRUE(Contains(error->what(), ".stl, .obj, .ply, .off")) << error->what();
}

TEST_F(MeshReader, StepIsNotSupported) {
  const auto error = ReadError(Write("part.STEP", "ISO-10303-21;\n"));
  ASSERT_TRUE(error);
  EXPECT_TRUE(Contains(error->what(), "read by ReadStep, not as a mesh")) << error->what();
}

}  // namespace
}  // namespace mechanist
