#include "kernel/support/parallel_for.h"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <atomic>
#include <fstream>
#include <stdexcept>
#include <string>
#include <thread>
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

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MECHANIST_ASAN 1
#endif
#endif

// This process's address space in use (kB), from /proc/self/status.
long VmSizeKilobytes() {
  std::ifstream status("/proc/self/status");
  std::string key;
  long value = 0;
  while (status >> key) {
    if (key == "VmSize:") {
      status >> value;
      return value;
    }
  }
  return 0;
}

TEST(ParallelFor, RunsOnTheCallingThreadWhenTheSystemGivesNoOther) {
#ifdef MECHANIST_ASAN
  GTEST_SKIP() << "AddressSanitizer's shadow memory does not fit under an address-space limit";
#endif
  // An address-space limit 4 MB above what the process uses: no thread's 8 MB stack fits.
  std::vector<std::thread::id> ran(200);
  rlimit saved{};
  ASSERT_EQ(getrlimit(RLIMIT_AS, &saved), 0);
  const long used = VmSizeKilobytes();
  ASSERT_GT(used, 0);
  rlimit tight = saved;
  tight.rlim_cur = static_cast<rlim_t>(used + 4096) * 1024;
  ASSERT_EQ(setrlimit(RLIMIT_AS, &tight), 0);
  ParallelFor(ran.size(), [&](std::size_t i) { ran[i] = std::this_thread::get_id(); });
  ASSERT_EQ(setrlimit(RLIMIT_AS, &saved), 0);
  for (const std::thread::id id : ran) EXPECT_EQ(id, std::this_thread::get_id());
}

}  // namespace
}  // namespace mechanist
