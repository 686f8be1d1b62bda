#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "kernel/geometry/aabb.h"

namespace mechanist {

/// Index pairs (i < j) of the boxes that overlap or touch, each box grown by `margin` (mm),
/// by sort and sweep along x (Baraff 1992); sorted by (i, j). Empty boxes never overlap.
/// O(n log n + k) for n boxes and k pairs overlapping in x.
std::vector<std::pair<std::size_t, std::size_t>> OverlappingBoxes(const std::vector<Aabb>& boxes,
                                                                  double margin);

}  // namespace mechanist
