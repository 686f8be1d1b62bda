#include "viz/gap_volume_writer.h"

#include <fmt/format.h>
#include <vtkCellData.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLImageDataWriter.h>

#include <algorithm>
#include <cstdint>
#include <string>

#include "io/atomic_file.h"
#include "io/input_error.h"

namespace mechanist {

namespace {

std::uint8_t StateCode(const GapSearch& search, const OccupancyOctree::Cell& cell) {
  const OccupancyOctree& tree = *search.octree;
  switch (tree.state(cell)) {
    case CellState::kPartial:
      return 3;
    case CellState::kFull:
      return 2;
    case CellState::kEmpty:
      return search.gap_of_component[tree.component(cell)] >= 0 ? 1 : 0;
  }
  return 0;
}

std::int32_t GapNumber(const GapSearch& search, const OccupancyOctree::Cell& cell) {
  const std::int32_t c = search.octree->component(cell);
  return c < 0 ? 0 : search.gap_of_component[c] + 1;
}

// Fills one value per voxel, x fastest (VTK's cell order), each row run by run from the leaves
// it crosses.
template <typename T, typename Value>
void FillVoxels(T* values, const GapSearch& search, Value value) {
  const OccupancyOctree& tree = *search.octree;
  const auto& n = tree.extent();
  for (std::int32_t k = 0; k < n[2]; ++k) {
    for (std::int32_t j = 0; j < n[1]; ++j) {
      for (std::int32_t i = 0; i < n[0];) {
        const OccupancyOctree::Cell cell = tree.Locate({i, j, k});
        const T v = value(search, cell);
        const std::int32_t end = std::min(n[0], cell.min[0] + cell.size);
        for (; i < end; ++i) *values++ = v;
      }
    }
  }
}

}  // namespace

void WriteGapVolume(const std::filesystem::path& path, const GapSearch& search,
                    const std::filesystem::path& protect) {
  const OccupancyOctree& tree = *search.octree;
  const auto& n = tree.extent();
  const std::int64_t voxels = std::int64_t{n[0]} * n[1] * n[2];
  if (voxels > kMaxVolumeVoxels) {
    throw InputError(path.string(), "", 0, 0,
                     fmt::format("the volume would have {} voxels, more than {}; choose a coarser "
                                 "--voxel",
                                 voxels, kMaxVolumeVoxels));
  }
  vtkNew<vtkImageData> image;
  image->SetDimensions(n[0] + 1, n[1] + 1, n[2] + 1);  // points: one more than cells
  const Eigen::Vector3d& o = tree.origin_W();
  image->SetOrigin(o.x(), o.y(), o.z());
  image->SetSpacing(tree.voxel(), tree.voxel(), tree.voxel());
  vtkNew<vtkUnsignedCharArray> state;
  state->SetName("state");
  state->SetNumberOfTuples(voxels);
  FillVoxels<std::uint8_t>(state->GetPointer(0), search, StateCode);
  vtkNew<vtkIntArray> gap;
  gap->SetName("gap");
  gap->SetNumberOfTuples(voxels);
  FillVoxels<std::int32_t>(gap->GetPointer(0), search, GapNumber);
  image->GetCellData()->SetScalars(state);
  image->GetCellData()->AddArray(gap);

  // VTK's writer, raw appended arrays with UInt64 sizes and no compression, into a temporary
  // file that is renamed into place.
  AtomicOutput output(path, protect);
  vtkNew<vtkXMLImageDataWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(output.temporary().c_str());
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetHeaderTypeToUInt64();
  writer->SetCompressorTypeToNone();
  writer->SetByteOrderToLittleEndian();
  if (!writer->Write()) throw InputError(path.string(), "", 0, 0, "cannot write the volume file");
  output.Commit();
}

}  // namespace mechanist
