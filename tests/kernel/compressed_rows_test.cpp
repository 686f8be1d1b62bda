#include "kernel/support/compressed_rows.h"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <stdexcept>
#include <vector>

namespace mechanist {
namespace {

TEST(CompressedRows, GroupsLikeAMapOfVectorsKeepingTheOrderGiven) {
  // Oracle: a map of vectors filled in the same order.
  std::mt19937 random(3);
  std::uniform_int_distribution<std::size_t> key(0, 49);
  std::vector<std::pair<std::size_t, int>> entries;
  std::map<std::size_t, std::vector<int>> oracle;
  for (int i = 0; i < 1000; ++i) {
    entries.emplace_back(key(random), i);
    oracle[entries.back().first].push_back(i);
  }
  const CompressedRows<int> rows(60, entries);
  ASSERT_EQ(rows.key_count(), 60u);
  for (std::size_t k = 0; k < 60; ++k) {
    const std::vector<int> got(rows[k].begin(), rows[k].end());
    EXPECT_EQ(got, oracle[k]) << k;
  }
}

TEST(CompressedRows, EmptyAndOutOfRange) {
  EXPECT_EQ(CompressedRows<int>().key_count(), 0u);
  EXPECT_TRUE(CompressedRows<int>(3, {})[2].empty());
  EXPECT_THROW(CompressedRows<int>(3, {{3, 1}}), std::out_of_range);
}

}  // namespace
}  // namespace mechanist
