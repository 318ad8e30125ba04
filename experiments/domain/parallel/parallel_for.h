#pragma once
// The one thread pool of dvpr: ParallelFor runs fn(i) for i in [0, count) on `threads`
// std::threads (0: hardware concurrency), the calling thread being one of them. Work is handed
// out one index at a time, so results written to slot i are the same for any thread count. The
// first exception thrown by fn stops the hand-out and is rethrown after all threads have joined.
// ParallelForInOrder (parallel_for_in_order.h) adds an in-order consumer on top of it.
//
// When the system refuses a thread (std::system_error, EAGAIN: the process limit RLIMIT_NPROC,
// a cgroup's pids.max, kernel.threads-max), the threads already started finish the index they
// hold and are joined, and ParallelFor throws std::runtime_error "cannot start threads: ..."
// (before, the vector of joinable threads was destroyed and std::terminate aborted dvpr with
// its temporary folder left behind).
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace dvpr {

inline int ResolveThreads(int threads) {
  if (threads > 0) return threads;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

// How ParallelFor starts each worker: a std::thread. A test passes its own to make a start fail.
struct StartStdThread {
  template <typename Work>
  void operator()(std::vector<std::thread>& pool, Work& work) const {
    pool.emplace_back(std::ref(work));
  }
};

template <typename Fn, typename Start = StartStdThread>
void ParallelFor(std::int64_t count, int threads, Fn&& fn, Start start = {}) {
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
  pool.reserve(static_cast<std::size_t>(workers - 1));
  for (int t = 1; t < workers; ++t) {
    try {
      start(pool, work);
    } catch (const std::system_error& e) {
      next = count;  // the started threads stop after the index they hold
      for (auto& started : pool) started.join();
      throw std::runtime_error("cannot start threads: " + std::string(e.what()) + " (started " +
                               std::to_string(pool.size() + 1) + " of " + std::to_string(workers) +
                               "; a process or thread limit is reached: try --threads 1)");
    }
  }
  work();
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace dvpr
