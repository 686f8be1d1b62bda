#include "kernel/support/radix_sort.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

namespace mechanist {
namespace {

struct Item {
  std::uint64_t key;
  int order;  // position before sorting: ties must keep it
  bool operator==(const Item&) const = default;
};

TEST(BitWidth, CountsTheBitsOfTheLargestValueBelowTheCount) {
  EXPECT_EQ(BitWidth(0), 0);
  EXPECT_EQ(BitWidth(1), 0);
  EXPECT_EQ(BitWidth(2), 1);
  EXPECT_EQ(BitWidth(3), 2);
  EXPECT_EQ(BitWidth(1024), 10);
  EXPECT_EQ(BitWidth(1025), 11);
  EXPECT_EQ(BitWidth(~std::uint64_t{0}), 64);
}

TEST(RadixSort, SortsStablyLikeAStableComparisonSort) {
  // Oracle: std::stable_sort by key, for keys of every width from none to 64 bits (one pass,
  // several passes, digits that do not divide the width), with many ties.
  std::mt19937_64 random(11);
  for (int bits : {0, 1, 7, 11, 12, 22, 33, 50, 64}) {
    const std::uint64_t mask = bits == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1;
    for (std::uint64_t distinct : {std::uint64_t{3}, std::uint64_t{1} << 20}) {
      std::vector<std::uint64_t> keys(distinct < 1000 ? distinct : 1000);
      for (std::uint64_t& k : keys) k = random() & mask;
      std::vector<Item> items;
      for (int i = 0; i < 3000; ++i) items.push_back({keys[random() % keys.size()], i});
      std::vector<Item> expected = items;
      std::stable_sort(expected.begin(), expected.end(),
                       [](const Item& x, const Item& y) { return x.key < y.key; });
      RadixSort(items, bits, [](const Item& item) { return item.key; });
      EXPECT_EQ(items, expected) << bits << " bits";
    }
  }
}

TEST(RadixSort, LeavesEmptyAndSingleItemsAlone) {
  std::vector<std::uint64_t> none;
  RadixSort(none, 20, [](std::uint64_t k) { return k; });
  EXPECT_TRUE(none.empty());
  std::vector<std::uint64_t> one{5};
  RadixSort(one, 20, [](std::uint64_t k) { return k; });
  EXPECT_EQ(one, std::vector<std::uint64_t>{5});
}

}  // namespace
}  // namespace mechanist
