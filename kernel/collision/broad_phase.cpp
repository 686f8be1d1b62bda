#include "kernel/collision/broad_phase.h"

#include <algorithm>
#include <numeric>

namespace mechanist {

std::vector<std::pair<std::size_t, std::size_t>> OverlappingBoxes(const std::vector<Aabb>& boxes,
                                                                  double margin) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    if (!boxes[i].empty()) order.push_back(i);
  }
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return boxes[a].min.x() < boxes[b].min.x() || (boxes[a].min.x() == boxes[b].min.x() && a < b);
  });
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const Aabb& a = boxes[order[k]];
    for (std::size_t l = k + 1; l < order.size(); ++l) {
      const Aabb& b = boxes[order[l]];
      if (b.min.x() > a.max.x() + 2.0 * margin) break;
      if ((a.min.array() <= b.max.array() + 2.0 * margin).all() &&
          (b.min.array() <= a.max.array() + 2.0 * margin).all()) {
        pairs.emplace_back(std::min(order[k], order[l]), std::max(order[k], order[l]));
      }
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace mechanist
