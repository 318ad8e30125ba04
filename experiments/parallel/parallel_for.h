#pragma once
// The one thread pool of dvpr: ParallelFor runs fn(i) for i in [0, count) on `threads`
// std::threads (0: hardware concurrency), the calling thread being one of them. Work is handed
// out one index at a time, so results written to slot i are the same for any thread count. The
// first exception thrown by fn stops the hand-out and is rethrown after all threads have joined.
// ParallelForInOrder (parallel_for_in_order.h) adds an in-order consumer on top of it.
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace dvpr {

inline int ResolveThreads(int threads) {
  if (threads > 0) return threads;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

template <typename Fn>
void ParallelFor(std::int64_t count, int threads, Fn&& fn) {
  const int workers = static_cast<int>(std::min<std::int64_t>(ResolveThreads(threads), count));
  if (workers <= 1) {
    for (std::int64_t i = 0; i < count; ++i) fn(i);
    return;
  }
  std::atomic<std::int64_t> next{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto work = [&] {
    for (std::int64_t i = next++; i < count; i = next++) {
      try {
        fn(i);
      } catch (...) {
        const std::lock_guard lock(error_mutex);
        if (!error) error = std::current_exception();
        next = count;  // stop handing out work
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < workers; ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace dvpr
