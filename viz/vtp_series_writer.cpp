#include "viz/vtp_series_writer.h"

#include <bit>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "io/atomic_file.h"
#include "io/input_error.h"
#include "kernel/number_format.h"

namespace mechanist {
namespace {

// The files say LittleEndian and the arrays are written as they lie in memory.
static_assert(std::endian::native == std::endian::little);

// A PolyData file in VTK's XML format with raw appended arrays (UInt64 sizes).
class PolyDataFile {
 public:
  void AddPoints(const std::vector<float>& xyz) {
    points_ = Array("Float32", "Points", 3, Bytes(xyz));
  }
  void AddTriangles(std::size_t count, const std::vector<std::int32_t>& connectivity) {
    std::vector<std::int32_t> offsets(count);
    for (std::size_t i = 0; i < count; ++i) offsets[i] = static_cast<std::int32_t>(3 * (i + 1));
    polys_ = Array("Int32", "connectivity", 1, Bytes(connectivity)) +
             Array("Int32", "offsets", 1, Bytes(offsets));
    triangles_ = count;
  }
  template <typename T>
  void AddCellArray(const char* type, const char* name, const std::vector<T>& values) {
    cells_ += Array(type, name, 1, Bytes(values));
  }
  std::string Text(std::size_t point_count) const {
    return "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
           "header_type=\"UInt64\">\n"
           "  <PolyData>\n"
           "    <Piece NumberOfPoints=\"" +
           std::to_string(point_count) + "\" NumberOfPolys=\"" + std::to_string(triangles_) +
           "\">\n"
           "      <Points>\n" +
           points_ +
           "      </Points>\n"
           "      <Polys>\n" +
           polys_ +
           "      </Polys>\n"
           "      <CellData>\n" +
           cells_ +
           "      </CellData>\n"
           "    </Piece>\n"
           "  </PolyData>\n"
           "  <AppendedData encoding=\"raw\">\n_" +
           data_ + "\n  </AppendedData>\n</VTKFile>\n";
  }

 private:
  template <typename T>
  static std::string Bytes(const std::vector<T>& values) {
    return std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
  }
  std::string Array(const char* type, const char* name, int components, const std::string& bytes) {
    const std::string line = "        <DataArray type=\"" + std::string(type) + "\" Name=\"" +
                             name + "\" NumberOfComponents=\"" + std::to_string(components) +
                             "\" format=\"appended\" offset=\"" + std::to_string(data_.size()) +
                             "\"/>\n";
    const auto size = static_cast<std::uint64_t>(bytes.size());
    data_.append(reinterpret_cast<const char*>(&size), sizeof size);
    data_ += bytes;
    return line;
  }

  std::string points_, polys_, cells_, data_;
  std::size_t triangles_ = 0;
};

std::string FrameFile(const Assembly& assembly, const Analysis& analysis,
                      const Animation& animation, std::size_t frame) {
  std::vector<float> xyz;
  std::vector<std::int32_t> connectivity;
  std::vector<std::int32_t> part_of, subassembly_of;
  std::vector<std::uint8_t> clash;
  for (std::size_t p = 0; p < assembly.parts().size(); ++p) {
    const Part& part = assembly.part(p);
    if (!part.mesh) continue;
    const auto first = static_cast<std::int32_t>(xyz.size() / 3);
    const RigidTransform& X_WP = animation.states[frame].X_WP[p];
    for (const Eigen::Vector3d& v : part.mesh->vertices) {
      const Eigen::Vector3d p_W = X_WP * v;
      xyz.insert(xyz.end(), {static_cast<float>(p_W.x()), static_cast<float>(p_W.y()),
                             static_cast<float>(p_W.z())});
    }
    for (const TriangleMesh::Face& f : part.mesh->faces) {
      for (const std::int32_t i : f) connectivity.push_back(first + i);
      part_of.push_back(static_cast<std::int32_t>(p));
      subassembly_of.push_back(static_cast<std::int32_t>(analysis.subassembly_of[p]));
      clash.push_back(animation.InClash(p, frame) ? 1 : 0);
    }
  }
  PolyDataFile file;
  const std::size_t points = xyz.size() / 3;
  file.AddPoints(xyz);
  file.AddTriangles(part_of.size(), connectivity);
  file.AddCellArray("Int32", "part", part_of);
  file.AddCellArray("Int32", "subassembly", subassembly_of);
  file.AddCellArray("UInt8", "clash", clash);
  return file.Text(points);
}

std::string GapFile(const TriangleMesh& surface, const std::vector<std::int32_t>* gap_of_face) {
  std::vector<float> xyz;
  for (const Eigen::Vector3d& v : surface.vertices) {
    xyz.insert(xyz.end(),
               {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())});
  }
  std::vector<std::int32_t> connectivity;
  for (const TriangleMesh::Face& f : surface.faces)
    connectivity.insert(connectivity.end(), f.begin(), f.end());
  std::vector<std::int32_t> gap(surface.faces.size(), 0);
  if (gap_of_face && gap_of_face->size() == gap.size()) {
    for (std::size_t i = 0; i < gap.size(); ++i) gap[i] = (*gap_of_face)[i] + 1;
  }
  PolyDataFile file;
  file.AddPoints(xyz);
  file.AddTriangles(surface.faces.size(), connectivity);
  file.AddCellArray("Int32", "gap", gap);
  return file.Text(surface.vertices.size());
}

}  // namespace

void WriteVtpSeries(const std::filesystem::path& pvd, const Assembly& assembly,
                    const Analysis& analysis, const Animation& animation,
                    const TriangleMesh* gap_surface_W, const std::vector<std::int32_t>* gap_of_face,
                    const std::filesystem::path& protect) {
  const std::filesystem::path folder = std::filesystem::path(pvd).replace_extension();
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) {
    throw InputError(folder.string(), "", 0, 0, "cannot create the folder: " + error.message());
  }
  const std::string relative = folder.filename().string();
  const bool gaps = gap_surface_W != nullptr;
  if (gaps) WriteFileAtomically(folder / "gaps.vtp", GapFile(*gap_surface_W, gap_of_face), protect);
  std::string collection =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (std::size_t k = 0; k < animation.frame_count(); ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04zu.vtp", k);
    WriteFileAtomically(folder / name, FrameFile(assembly, analysis, animation, k), protect);
    const std::string time = FormatNumber(animation.s[k], 17);
    collection += "    <DataSet timestep=\"" + time + "\" part=\"0\" file=\"" + relative + "/" +
                  name + "\"/>\n";
    if (gaps) {
      collection += "    <DataSet timestep=\"" + time + "\" part=\"1\" file=\"" + relative +
                    "/gaps.vtp\"/>\n";
    }
  }
  collection += "  </Collection>\n</VTKFile>\n";
  WriteFileAtomically(pvd, collection, protect);
}

}  // namespace mechanist
