#pragma once

#include <cstddef>

namespace mechanist {

/// The consecutive indices [first, last), for a range-for without a container (clang 14, the
/// sanitizer and fuzzing compiler, cannot build libstdc++ 12's std::views::iota).
struct IndexRange {
  /// Walks the indices in increasing order; dereferencing gives the index itself.
  struct Iterator {
    std::size_t index = 0;
    std::size_t operator*() const { return index; }
    Iterator& operator++() {
      ++index;
      return *this;
    }
    bool operator==(const Iterator&) const = default;
  };

  std::size_t first = 0;  ///< the first index
  std::size_t last = 0;   ///< one past the last index

  Iterator begin() const { return {first}; }
  Iterator end() const { return {last}; }
  /// How many indices: last - first.
  std::size_t size() const { return last - first; }
  /// Whether there is no index.
  bool empty() const { return first == last; }
  /// The first index; only when not empty().
  std::size_t front() const { return first; }
};

}  // namespace mechanist
