#pragma once

namespace mechanist {

/// Makes the C heap keep up to 64 MB of freed memory at the top of each arena for reuse,
/// instead of returning it to the system at once (glibc's M_TOP_PAD; nothing elsewhere).
/// Open CASCADE's mesher allocates and frees a face's working memory face after face, and
/// with glibc's defaults each free gives the pages back and each new face faults them in
/// again: importing a 4 MB STEP assembly spent a fifth of its time so (real_cad_bench).
/// For programs to call first in `main`, before any thread starts; it raises the resident
/// size by what the arenas keep (about 10 MB on the robot hand of ../shared/data/real). Like
/// any such setting it also stops glibc from raising its mmap threshold as blocks are freed:
/// blocks over 128 kB are then always mapped afresh; with a threshold of 4 or 32 MB set as
/// well, the robot hand took as long (2.71 and 2.72 s against 2.61 s, one pair of runs each).
void KeepFreedHeapForReuse();

}  // namespace mechanist
