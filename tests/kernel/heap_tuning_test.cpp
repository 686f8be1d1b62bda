#include "kernel/support/heap_tuning.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <memory>
#include <vector>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace mechanist {
namespace {

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MECHANIST_ASAN 1
#endif
#endif

TEST(HeapTuning, FreedMemoryStaysInTheHeapForTheNextAllocations) {
#if defined(__GLIBC__) && !defined(MECHANIST_ASAN)
  KeepFreedHeapForReuse();
  constexpr std::size_t kBlocks = 16 << 10, kBlockSize = 1 << 10;  // 16 MB in small blocks
  std::vector<std::unique_ptr<char[]>> blocks;
  for (std::size_t i = 0; i < kBlocks; ++i) blocks.emplace_back(new char[kBlockSize]);
  blocks.clear();
  // Without the setting, glibc gives the freed top of the heap back to the system at once
  // (its trim threshold then is far below 16 MB).
  EXPECT_GE(mallinfo2().arena, kBlocks * kBlockSize);
#else
  GTEST_SKIP() << "the setting is glibc's heap's (AddressSanitizer has its own)";
#endif
}

}  // namespace
}  // namespace mechanist
