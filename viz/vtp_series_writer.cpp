#include "viz/vtp_series_writer.h"

#include <fmt/format.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTypeInt32Array.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/atomic_file.h"
#include "io/input_error.h"
#include "kernel/support/number_format.h"

namespace mechanist {
namespace {

// A PolyData file written by VTK's own XML writer: raw appended arrays (UInt64 sizes), no
// compression, so that any VTK reader reads it fast. (Into a string and then one write: VTK
// streaming into the file itself took 30% longer on animate_bench.)
std::string PolyDataText(vtkPolyData* data) {
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(data);
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetHeaderTypeToUInt64();
  writer->SetCompressorTypeToNone();
  writer->SetByteOrderToLittleEndian();
  writer->WriteToOutputStringOn();
  if (!writer->Write()) throw std::runtime_error("VTK could not write a PolyData file");
  return writer->GetOutputString();
}

// Triangles of `xyz` (3 floats per point) with `connectivity` (3 per triangle).
vtkSmartPointer<vtkPolyData> Triangles(const std::vector<float>& xyz,
                                       const std::vector<std::int32_t>& connectivity) {
  vtkNew<vtkFloatArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(static_cast<vtkIdType>(xyz.size() / 3));
  std::copy(xyz.begin(), xyz.end(), coordinates->GetPointer(0));
  vtkNew<vtkPoints> points;
  points->SetData(coordinates);
  // Offsets and connectivity handed over whole (32-bit, as the files store them).
  vtkNew<vtkTypeInt32Array> offsets;
  offsets->SetNumberOfTuples(static_cast<vtkIdType>(connectivity.size() / 3 + 1));
  for (vtkIdType i = 0; i < offsets->GetNumberOfTuples(); ++i) offsets->SetValue(i, 3 * i);
  vtkNew<vtkTypeInt32Array> indices;
  indices->SetNumberOfTuples(static_cast<vtkIdType>(connectivity.size()));
  std::copy(connectivity.begin(), connectivity.end(), indices->GetPointer(0));
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, indices);
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetPolys(polys);
  return data;
}

template <typename Array, typename T>
void AddCellArray(vtkPolyData* data, const char* name, const std::vector<T>& values) {
  vtkNew<Array> array;
  array->SetName(name);
  array->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  std::copy(values.begin(), values.end(), array->GetPointer(0));
  data->GetCellData()->AddArray(array);
}

vtkSmartPointer<vtkPolyData> FrameData(const Assembly& assembly, const Analysis& analysis,
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
  const vtkSmartPointer<vtkPolyData> data = Triangles(xyz, connectivity);
  AddCellArray<vtkIntArray>(data, "part", part_of);
  AddCellArray<vtkIntArray>(data, "subassembly", subassembly_of);
  AddCellArray<vtkUnsignedCharArray>(data, "clash", clash);
  return data;
}

vtkSmartPointer<vtkPolyData> GapData(const TriangleMesh& surface,
                                     const std::vector<std::int32_t>* gap_of_face) {
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
  const vtkSmartPointer<vtkPolyData> data = Triangles(xyz, connectivity);
  AddCellArray<vtkIntArray>(data, "gap", gap);
  return data;
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
    throw InputError(folder.string(), "", 0, 0,
                     fmt::format("cannot create the folder: {}", error.message()));
  }
  const std::string relative = folder.filename().string();
  const bool gaps = gap_surface_W != nullptr;
  if (gaps) {
    WriteFileAtomically(folder / "gaps.vtp", PolyDataText(GapData(*gap_surface_W, gap_of_face)),
                        protect);
  }
  std::string collection =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (std::size_t k = 0; k < animation.frame_count(); ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04zu.vtp", k);
    WriteFileAtomically(folder / name, PolyDataText(FrameData(assembly, analysis, animation, k)),
                        protect);
    const std::string time = FormatNumber(animation.s[k], 17);
    auto out = std::back_inserter(collection);
    fmt::format_to(out, "    <DataSet timestep=\"{}\" part=\"0\" file=\"{}/{}\"/>\n", time,
                   relative, name);
    if (gaps) {
      fmt::format_to(out, "    <DataSet timestep=\"{}\" part=\"1\" file=\"{}/gaps.vtp\"/>\n", time,
                     relative);
    }
  }
  collection += "  </Collection>\n</VTKFile>\n";
  WriteFileAtomically(pvd, collection, protect);
}

}  // namespace mechanist
