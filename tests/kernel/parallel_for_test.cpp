#include "kernel/support/parallel_for.h"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

namespace mechanist {
namespace {

TEST(ParallelFor, CallsTheBodyOnceForEveryIndex) {
  for (const std::size_t count : {0u, 1u, 2u, 3u, 1000u}) {
    std::vector<std::atomic<int>> calls(count);
    ParallelFor(count, [&](std::size_t i) { ++calls[i]; });
    for (std::size_t i = 0; i < count; ++i) EXPECT_EQ(calls[i], 1) << i << " of " << count;
  }
}

TEST(ParallelFor, RethrowsTheExceptionOfTheLowestFailingIndex) {
  // Every index from 500 on fails; whichever thread reaches one first, the caller sees 500's:
  // all lower indices were started before it and run to their end.
  for (int repeat = 0; repeat < 20; ++repeat) {
    std::atomic<int> below{0};
    try {
      ParallelFor(1000, [&](std::size_t i) {
        if (i >= 500) throw std::runtime_error(std::to_string(i));
        ++below;
      });
      FAIL() << "no exception";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "500");
    }
    EXPECT_EQ(below, 500);
  }
}

}  // namespace
}  // namespace mechanist
