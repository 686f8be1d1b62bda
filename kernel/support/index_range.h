#pragma once

#include <cstddef>

namespace mechanist {

/// The consecutive indices [first, last), for a range-for without a container (clang 14, the
/// sanitizer and fuzzing compiler, cannot build libstdc++ 12's std::views::iota).
struct IndexRange {
  struct Iterator {
    std::size_t index = 0;
    std::size_t operator*() const { return index; }
    Iterator& operator++() {
      ++index;
      return *this;
    }
    bool operator==(const Iterator&) const = default;
  };

  std::size_t first = 0, last = 0;

  Iterator begin() const { return {first}; }
  Iterator end() const { return {last}; }
  std::size_t size() const { return last - first; }
  bool empty() const { return first == last; }
  std::size_t front() const { return first; }
};

}  // namespace mechanist
