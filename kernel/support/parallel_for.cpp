#include "kernel/support/parallel_for.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>
#include <vector>

namespace mechanist {

void ParallelFor(std::size_t count, const std::function<void(std::size_t)>& body) {
  std::vector<std::exception_ptr> failures(count);
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> first_failure{count};  // the lowest failing index known yet
  const auto work = [&] {
    // Indices above a failing one are skipped; those below it always run to their end, so
    // the lowest failing index is the same whatever the threads' timing.
    for (std::size_t i = next++; i < count && i < first_failure; i = next++) {
      try {
        body(i);
      } catch (...) {
        failures[i] = std::current_exception();
        std::size_t known = first_failure;
        while (i < known && !first_failure.compare_exchange_weak(known, i)) {
        }
      }
    }
  };
  const std::size_t threads =
      std::min<std::size_t>(count, std::max(1u, std::thread::hardware_concurrency()));
  std::vector<std::thread> helpers;
  helpers.reserve(threads);
  for (std::size_t t = 1; t < threads; ++t) {
    try {
      helpers.emplace_back(work);
    } catch (const std::exception&) {
      break;  // no more threads to be had (an address-space limit): those started do the work
    }
  }
  work();
  for (std::thread& helper : helpers) helper.join();
  for (const std::exception_ptr& failure : failures) {
    if (failure) std::rethrow_exception(failure);
  }
}

}  // namespace mechanist
