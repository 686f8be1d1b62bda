#include "viz/gap_volume_writer.h"

#include <algorithm>
#include <bit>
#include <string>
#include <vector>

#include "io/atomic_file.h"
#include "io/input_error.h"
#include "kernel/number_format.h"

namespace mechanist {

namespace {

// The file says LittleEndian and the arrays are written as they lie in memory.
static_assert(std::endian::native == std::endian::little);

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

// Writes one value per voxel, x fastest, as little-endian bytes of T: each row is filled run
// by run from the leaves it crosses.
template <typename T, typename Value>
void WriteVoxels(std::ostream& out, const GapSearch& search, Value value) {
  const OccupancyOctree& tree = *search.octree;
  const auto& n = tree.extent();
  std::vector<T> row(n[0]);
  for (std::int32_t k = 0; k < n[2]; ++k) {
    for (std::int32_t j = 0; j < n[1]; ++j) {
      for (std::int32_t i = 0; i < n[0];) {
        const OccupancyOctree::Cell cell = tree.Locate({i, j, k});
        const T v = value(search, cell);
        const std::int32_t end = std::min(n[0], cell.min[0] + cell.size);
        for (; i < end; ++i) row[i] = v;
      }
      out.write(reinterpret_cast<const char*>(row.data()),
                static_cast<std::streamsize>(row.size() * sizeof(T)));
    }
  }
}

void WriteLength(std::ostream& out, std::uint64_t bytes) {
  out.write(reinterpret_cast<const char*>(&bytes), sizeof bytes);
}

}  // namespace

void WriteGapVolume(const std::filesystem::path& path, const GapSearch& search,
                    const std::filesystem::path& protect) {
  const OccupancyOctree& tree = *search.octree;
  const auto& n = tree.extent();
  const std::int64_t voxels = std::int64_t{n[0]} * n[1] * n[2];
  if (voxels > kMaxVolumeVoxels) {
    throw InputError(path.string(), "", 0, 0,
                     "the volume would have " + std::to_string(voxels) + " voxels, more than " +
                         std::to_string(kMaxVolumeVoxels) + "; choose a coarser --voxel");
  }
  const auto count = static_cast<std::uint64_t>(voxels);
  const std::string extent =
      "0 " + std::to_string(n[0]) + " 0 " + std::to_string(n[1]) + " 0 " + std::to_string(n[2]);
  const Eigen::Vector3d& o = tree.origin_W();
  const std::string spacing = FormatNumber(tree.voxel(), 17);
  std::string header =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n"
      "  <ImageData WholeExtent=\"" +
      extent + "\" Origin=\"" + FormatNumber(o.x(), 17) + " " + FormatNumber(o.y(), 17) + " " +
      FormatNumber(o.z(), 17) + "\" Spacing=\"" + spacing + " " + spacing + " " + spacing +
      "\">\n"
      "    <Piece Extent=\"" +
      extent +
      "\">\n"
      "      <CellData Scalars=\"state\">\n"
      "        <DataArray type=\"UInt8\" Name=\"state\" format=\"appended\" offset=\"0\"/>\n"
      "        <DataArray type=\"Int32\" Name=\"gap\" format=\"appended\" offset=\"" +
      std::to_string(8 + count) +
      "\"/>\n"
      "      </CellData>\n"
      "    </Piece>\n"
      "  </ImageData>\n"
      "  <AppendedData encoding=\"raw\">\n_";
  WriteFileAtomically(
      path,
      [&](std::ostream& out) {
        out << header;
        WriteLength(out, count);
        WriteVoxels<std::uint8_t>(out, search, StateCode);
        WriteLength(out, count * sizeof(std::int32_t));
        WriteVoxels<std::int32_t>(out, search, GapNumber);
        out << "\n  </AppendedData>\n</VTKFile>\n";
      },
      protect);
}

}  // namespace mechanist
