#pragma once

#include <compare>
#include <cstddef>

namespace mechanist {

/// A feature of an assembly by index: part `part`, its feature `feature`. Written
/// "part_id/feature_id" in files and reports.
struct FeatureRef {
  std::size_t part = 0;
  std::size_t feature = 0;
  auto operator<=>(const FeatureRef&) const = default;
};

}  // namespace mechanist
