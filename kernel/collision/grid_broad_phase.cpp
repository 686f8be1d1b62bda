#include "kernel/collision/grid_broad_phase.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "kernel/support/radix_sort.h"

namespace mechanist {
namespace {

/// Keys of grid cells along a Morton (Z-order) curve: the bits of the three cell coordinates
/// interleaved, so that cells near in key order are near in space along every axis. The broad
/// phase visits cells in key order; neighbouring cells share features, which then stay in the
/// cache whichever axis the file lists its parts along (with one axis most significant, the
/// visit runs down long columns and reloads each feature from memory in every column).
class MortonKeys {
 public:
  /// For cell coordinates of `bits` bits along x, y, z, 32 bits in all at most.
  explicit MortonKeys(const std::array<int, 3>& bits) {
    std::array<std::array<int, 32>, 3> position{};  // key bit of each coordinate bit
    int next = 0;
    for (int b = 0; b < 32; ++b) {
      for (int k = 2; k >= 0; --k) {
        if (b < bits[k]) position[k][b] = next++;
      }
    }
    for (int k = 0; k < 3; ++k) {
      for (int b = 0; b < bits[k]; ++b) {
        const int q = position[k][b];  // key bit q is bit b of coordinate k
        for (std::uint32_t v = 0; v < 256; ++v) {
          if (v >> (b % 8) & 1) spread_[k][b / 8][v] |= std::uint32_t{1} << q;
          if (v >> (q % 8) & 1) gather_[k][q / 8][v] |= std::uint32_t{1} << b;
        }
      }
    }
  }

  std::uint32_t Key(const std::array<std::uint32_t, 3>& cell) const {
    std::uint32_t key = 0;
    for (int k = 0; k < 3; ++k) {
      for (int i = 0; i < 4; ++i) key |= spread_[k][i][cell[k] >> (8 * i) & 0xff];
    }
    return key;
  }

  std::array<std::uint32_t, 3> Cell(std::uint32_t key) const {
    std::array<std::uint32_t, 3> cell{};
    for (int k = 0; k < 3; ++k) {
      for (int i = 0; i < 4; ++i) cell[k] |= gather_[k][i][key >> (8 * i) & 0xff];
    }
    return cell;
  }

 private:
  // Per axis and byte: the key bits of a coordinate byte, the coordinate bits of a key byte.
  std::array<std::array<std::array<std::uint32_t, 256>, 4>, 3> spread_{}, gather_{};
};

}  // namespace

std::vector<std::pair<std::uint32_t, std::uint32_t>> OverlappingBoxPairs(
    std::span<const Aabb> boxes, std::span<const std::uint32_t> owners) {
  if (owners.size() != boxes.size()) {
    throw std::invalid_argument("OverlappingBoxPairs: one owner per box");
  }
  if (boxes.empty()) return {};
  // The boxes in floats rounded outward, with their owners: a compact first test before the
  // exact one, so that rejected candidates touch 28 bytes each. Made in the same read of the
  // boxes as their extents.
  struct CompactBox {
    std::array<float, 3> lo, hi;
    std::uint32_t part;
  };
  std::vector<CompactBox> compact(boxes.size());
  std::vector<double> extents;
  extents.reserve(boxes.size());
  Aabb all;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const Aabb& b = boxes[i];
    compact[i].part = owners[i];
    if (b.empty()) {  // fails the compact test with any box
      compact[i].lo.fill(1.0f);
      compact[i].hi.fill(0.0f);
      continue;
    }
    extents.push_back(b.size().maxCoeff());
    all.Extend(b);
    for (int k = 0; k < 3; ++k) {
      compact[i].lo[k] = std::nextafter(static_cast<float>(b.min[k]), -HUGE_VALF);
      compact[i].hi[k] = std::nextafter(static_cast<float>(b.max[k]), HUGE_VALF);
    }
  }
  if (extents.empty()) return {};
  std::nth_element(extents.begin(), extents.begin() + extents.size() / 2, extents.end());
  constexpr std::int64_t kMaxCellsPerBox = 512;
  constexpr int kKeyBits = 32;       // an entry is its cell's key over its box's index
  std::vector<std::uint32_t> large;  // boxes spanning too many cells: tested against all
  // Cell coordinates fit 32 bits once the key does: 12 bytes a corner, for the cache.
  std::vector<std::array<std::uint32_t, 3>> low(boxes.size()), high(boxes.size());
  std::array<int, 3> bits{};
  std::size_t entry_count = 0;
  // Cells of twice the median reach (most boxes then cover one or two cells along each axis:
  // fewer entries to sort, a few more candidates per cell), doubled while the grid needs more
  // than kKeyBits bits of key (a huge assembly of small features: more candidates per cell,
  // still every pair once).
  for (double cell = std::max(2 * extents[extents.size() / 2], 1e-3);; cell *= 2) {
    large.clear();
    entry_count = 0;
    std::array<std::int64_t, 3> extent{1, 1, 1};  // cells per axis over the small boxes
    for (std::uint32_t i = 0; i < boxes.size(); ++i) {
      const Aabb& b = boxes[i];
      if (b.empty()) {  // entered in no cell: low above high
        low[i].fill(1);
        high[i].fill(0);
        continue;
      }
      std::int64_t count = 1;
      std::array<std::int64_t, 3> hi{};
      for (int k = 0; k < 3; ++k) {
        const auto lo = static_cast<std::int64_t>(std::floor((b.min[k] - all.min[k]) / cell));
        hi[k] = static_cast<std::int64_t>(std::floor((b.max[k] - all.min[k]) / cell));
        count *= std::min(hi[k] - lo + 1, kMaxCellsPerBox + 1);
        // Exact, once the loop ends, for the boxes that are entered in cells.
        low[i][k] = static_cast<std::uint32_t>(lo);
        high[i][k] = static_cast<std::uint32_t>(hi[k]);
      }
      if (count > kMaxCellsPerBox) {
        large.push_back(i);
        continue;
      }
      entry_count += static_cast<std::size_t>(count);
      for (int k = 0; k < 3; ++k) extent[k] = std::max(extent[k], hi[k] + 1);
    }
    bits = {};
    for (int k = 0; k < 3; ++k) {
      while (bits[k] <= kKeyBits && (std::int64_t{1} << bits[k]) < extent[k]) ++bits[k];
    }
    if (bits[0] + bits[1] + bits[2] <= kKeyBits) break;
  }
  const MortonKeys morton(bits);
  const int key_bits = bits[0] + bits[1] + bits[2];
  std::vector<std::uint64_t> entries;
  entries.reserve(entry_count);
  std::size_t next_large = 0;
  for (std::uint32_t i = 0; i < boxes.size(); ++i) {
    if (next_large < large.size() && large[next_large] == i) {
      ++next_large;
      continue;
    }
    for (std::uint32_t x = low[i][0]; x <= high[i][0]; ++x) {
      for (std::uint32_t y = low[i][1]; y <= high[i][1]; ++y) {
        for (std::uint32_t z = low[i][2]; z <= high[i][2]; ++z) {
          entries.push_back(std::uint64_t{morton.Key({x, y, z})} << 32 | i);
        }
      }
    }
  }
  // Stable, so entries of one cell stay in feature order: the same order as sorting the
  // pairs, in linear time.
  RadixSort(entries, key_bits, [](std::uint64_t e) { return e >> 32; });
  // The candidates that pass the compact test are tested afterwards in the order of their
  // first feature: the features are then read in the file's order, which the memory
  // prefetches, rather than cell by cell, which it cannot foresee.
  std::vector<std::uint64_t> found;  // first feature's index over the second's
  found.reserve(entries.size());
  auto candidate = [&](std::uint32_t i, std::uint32_t j) {
    const CompactBox &p = compact[i], &q = compact[j];
    if (p.part == q.part) return;
    for (int k = 0; k < 3; ++k) {
      if (p.hi[k] < q.lo[k] || q.hi[k] < p.lo[k]) return;
    }
    found.push_back(std::uint64_t{i} << 32 | j);
  };
  for (std::size_t begin = 0; begin < entries.size();) {
    const std::uint64_t key = entries[begin] >> 32;
    std::size_t end = begin;
    while (end < entries.size() && entries[end] >> 32 == key) ++end;
    const std::array<std::uint32_t, 3> here = morton.Cell(static_cast<std::uint32_t>(key));
    for (std::size_t a = begin; a < end; ++a) {
      for (std::size_t b = a + 1; b < end; ++b) {
        const auto i = static_cast<std::uint32_t>(entries[a]);
        const auto j = static_cast<std::uint32_t>(entries[b]);
        bool owner = true;
        for (int k = 0; k < 3; ++k) owner &= std::max(low[i][k], low[j][k]) == here[k];
        if (owner) candidate(std::min(i, j), std::max(i, j));
      }
    }
    begin = end;
  }
  std::vector<bool> is_large(boxes.size(), false);
  for (std::uint32_t i : large) is_large[i] = true;
  for (std::uint32_t i : large) {
    for (std::uint32_t j = 0; j < boxes.size(); ++j) {
      if (j == i || (is_large[j] && j < i)) continue;
      candidate(std::min(i, j), std::max(i, j));
    }
  }
  RadixSort(found, BitWidth(boxes.size()), [](std::uint64_t e) { return e >> 32; });
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  pairs.reserve(found.size());
  for (const std::uint64_t e : found) {
    const auto i = static_cast<std::uint32_t>(e >> 32), j = static_cast<std::uint32_t>(e);
    if (boxes[i].Intersects(boxes[j])) pairs.emplace_back(i, j);
  }
  return pairs;
}

}  // namespace mechanist
