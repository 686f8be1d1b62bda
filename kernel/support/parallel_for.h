#pragma once

#include <cstddef>
#include <functional>

namespace mechanist {

/// Calls `body(i)` once for every i in [0, count), on up to `std::thread::hardware_concurrency()`
/// threads (the calling thread among them; fewer when the system gives no more, down to the
/// calling thread alone), and returns when all calls have returned. The calls must be
/// independent of each other (each writes only its own results); the order in which they run
/// is unspecified. If calls throw, the exception of the lowest such index is
/// rethrown once every call started has finished: every index below it has run, indices above
/// it may have been skipped, and the exception is the same whatever the threads' timing.
void ParallelFor(std::size_t count, const std::function<void(std::size_t)>& body);

}  // namespace mechanist
