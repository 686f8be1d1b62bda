#pragma once

#include <algorithm>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

namespace mechanist {

/// Items grouped by a key in [0, key_count), stored as compressed rows: one array of items
/// and one of offsets, rather than a container per key (which costs an allocation per key
/// and scatters the items over the heap in assemblies of 100,000 parts). Each key's items
/// keep the order in which they were given.
template <typename T>
class CompressedRows {
 public:
  CompressedRows() : start_(1, 0) {}

  /// Groups `entries` (key, item); throws std::out_of_range when a key is not below
  /// `key_count`.
  CompressedRows(std::size_t key_count, const std::vector<std::pair<std::size_t, T>>& entries)
      : start_(key_count + 1, 0) {
    for (const auto& [key, item] : entries) ++start_.at(key + 1);
    for (std::size_t k = 0; k < key_count; ++k) start_[k + 1] += start_[k];
    std::vector<std::size_t> next(start_.begin(), start_.end() - 1);
    items_.resize(entries.size());
    for (const auto& [key, item] : entries) items_[next[key]++] = item;
  }

  /// Rows given already grouped: key k's items are items[start[k] .. start[k + 1]). Throws
  /// std::invalid_argument unless start begins at 0, never decreases and ends at items.size().
  CompressedRows(std::vector<std::size_t> start, std::vector<T> items)
      : start_(std::move(start)), items_(std::move(items)) {
    if (start_.empty() || start_.front() != 0 || start_.back() != items_.size() ||
        !std::is_sorted(start_.begin(), start_.end())) {
      throw std::invalid_argument("CompressedRows: offsets do not partition the items");
    }
  }

  std::size_t key_count() const { return start_.size() - 1; }
  /// The items of `key`, in the order given.
  std::span<const T> operator[](std::size_t key) const {
    return {items_.data() + start_[key], start_[key + 1] - start_[key]};
  }

 private:
  std::vector<std::size_t> start_;  ///< per key: its first item; then the item count
  std::vector<T> items_;
};

}  // namespace mechanist
