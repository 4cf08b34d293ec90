// Work items on worker threads: items 0..count-1 taken in turn by `threads` workers (the calling
// thread is one of them); the first exception any item raises is rethrown once all have stopped.
#pragma once

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace cig {

// work(item, worker): worker in 0..threads-1 (for per-worker state).
template <class Work>
void parallel_for(std::size_t count, int threads, Work&& work) {
  const int n = std::max(1, std::min<int>(threads, int(count)));
  std::atomic<std::size_t> next{0};
  std::atomic<int> next_worker{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto worker = [&] {
    const int self = next_worker++;
    try {
      for (std::size_t k; (k = next++) < count;) work(k, self);
    } catch (...) {
      std::lock_guard<std::mutex> lock(error_mutex);
      if (!error) error = std::current_exception();
      next = count;  // the others stop after their current item
    }
  };
  std::vector<std::thread> pool;
  for (int i = 1; i < n; ++i) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace cig
