#pragma once

#include <cstdint>
#include <utility>
#include <vector>

namespace mechanist {

/// The number of bits needed to write every integer below `count` (0 for counts up to 1).
inline int BitWidth(std::uint64_t count) {
  int bits = 0;
  while (bits < 64 && (std::uint64_t{1} << bits) < count) ++bits;
  return bits;
}

/// Sorts `items` by `key(item)`, an unsigned integer below 2^key_bits (key_bits <= 64),
/// stably, in linear time: a least-significant-digit radix sort with as few passes of at most
/// 11-bit digits as the key needs (a pass's 2048 counts stay in the L1 cache), every digit's
/// counts taken in one read of the items. For the large sorts of big assemblies, where a
/// comparison sort's log factor and scattered compares show.
template <typename T, typename Key>
void RadixSort(std::vector<T>& items, int key_bits, Key key) {
  const int passes = (key_bits + 10) / 11;
  if (passes == 0 || items.size() < 2) return;
  const int digit_bits = (key_bits + passes - 1) / passes;
  const std::uint64_t mask = (std::uint64_t{1} << digit_bits) - 1;
  std::vector<std::vector<std::size_t>> counts(passes, std::vector<std::size_t>(mask + 1, 0));
  for (const T& item : items) {
    const std::uint64_t k = key(item);
    for (int d = 0; d < passes; ++d) ++counts[d][(k >> (d * digit_bits)) & mask];
  }
  std::vector<T> buffer(items.size());
  for (int d = 0; d < passes; ++d) {
    std::vector<std::size_t>& next = counts[d];
    std::size_t sum = 0;
    for (std::size_t& n : next) sum += std::exchange(n, sum);
    const int shift = d * digit_bits;
    for (T& item : items) buffer[next[(key(item) >> shift) & mask]++] = std::move(item);
    items.swap(buffer);
  }
}

}  // namespace mechanist
