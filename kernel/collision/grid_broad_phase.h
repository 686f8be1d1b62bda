#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "kernel/geometry/aabb.h"

namespace mechanist {

/// Index pairs (i < j) of boxes with different owners that overlap or touch (closed boxes),
/// ordered by i, for one i in an order fixed by the input. A uniform grid of cells twice the
/// median box extent, doubled until the cell coordinates fit a 32-bit key; each box is entered
/// in the cells it covers, keyed along a Morton (Z-order) curve so that cells near in key order
/// are near in space, and radix-sorted; a pair is reported only in the cell of the maximum of
/// the two lower corners, so once; a box covering more than 512 cells is tested against all.
/// Linear in the boxes and candidate pairs for boxes of similar sizes (the features of an
/// assembly: 100,000 parts in tens of milliseconds). `owners` has one entry per box. Empty
/// boxes never overlap.
std::vector<std::pair<std::uint32_t, std::uint32_t>> OverlappingBoxPairs(
    std::span<const Aabb> boxes, std::span<const std::uint32_t> owners);

}  // namespace mechanist
