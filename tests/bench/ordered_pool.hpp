#pragma once
// Independent jobs on several threads, their results taken in job order: `run(i)` for i in
// [0, n) on up to `threads` threads (each job on its own data, nothing shared), and `take(i)` on
// the calling thread for i = 0, 1, ... as soon as job i and every job before it are done. A bench
// of many runs thus prints exactly what it prints on one thread, run by run as they come in.
#include <algorithm>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace entourage::bench {

// The threads a bench uses when asked for `requested` (0: one per logical CPU), for `jobs` jobs.
inline int pool_threads(int requested, std::size_t jobs) {
  const int cpus = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const int wanted = requested > 0 ? requested : cpus;
  return static_cast<int>(std::max<std::size_t>(1, std::min<std::size_t>(static_cast<std::size_t>(wanted), jobs)));
}

// Runs `run(0..n-1)` on `threads` threads and calls `take(i)` in order on this thread. An exception
// thrown by a job is rethrown here, once the jobs started so far have ended.
inline void run_in_order(std::size_t n, int threads, const std::function<void(std::size_t)>& run,
                         const std::function<void(std::size_t)>& take) {
  if (threads <= 1) {
    for (std::size_t i = 0; i < n; ++i) {
      run(i);
      take(i);
    }
    return;
  }
  std::mutex mutex;
  std::condition_variable done_one;
  std::vector<char> done(n, 0);
  std::size_t next_job = 0;
  std::exception_ptr failure;
  auto worker = [&] {
    for (;;) {
      std::size_t i = 0;
      {
        std::lock_guard<std::mutex> lock(mutex);
        if (next_job >= n || failure) return;
        i = next_job++;
      }
      try {
        run(i);
      } catch (...) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!failure) failure = std::current_exception();
      }
      {
        std::lock_guard<std::mutex> lock(mutex);
        done[i] = 1;
      }
      done_one.notify_all();
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(threads));
  for (int t = 0; t < threads; ++t) pool.emplace_back(worker);
  for (std::size_t i = 0; i < n; ++i) {
    {
      std::unique_lock<std::mutex> lock(mutex);
      done_one.wait(lock, [&] { return done[i] != 0 || failure; });
      if (failure) break;
    }
    take(i);
  }
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace entourage::bench
