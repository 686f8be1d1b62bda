#include "kernel/support/heap_tuning.h"

#include <cstddef>  // defines __GLIBC__ on glibc

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace mechanist {

void KeepFreedHeapForReuse() {
#if defined(__GLIBC__)
  constexpr int kTopPad = 64 << 20;  // bytes
  mallopt(M_TOP_PAD, kTopPad);
#endif
}

}  // namespace mechanist
