#pragma once

#include <compare>
#include <cstddef>
#include <cstdint>

namespace mechanist {

/// A feature of an assembly by index: part `part`, its feature `feature`. Written
/// "part_id/feature_id" in files and reports. The indices are 32 bits (Assembly rejects more
/// parts, or more features in a part, than that): a pair holds three references and an
/// assembly of 100,000 parts has as many pairs, read by every pass of the analysis.
struct FeatureRef {
  FeatureRef() = default;
  /// From indices below 2^32.
  constexpr FeatureRef(std::size_t part_index, std::size_t feature_index)
      : part(static_cast<std::uint32_t>(part_index)),
        feature(static_cast<std::uint32_t>(feature_index)) {}
  std::uint32_t part = 0;
  std::uint32_t feature = 0;
  auto operator<=>(const FeatureRef&) const = default;
};

}  // namespace mechanist
