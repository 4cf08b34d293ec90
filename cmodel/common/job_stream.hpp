// A stream of jobs to one worker thread that runs them in the order they were pushed (so that
// whatever they accumulate, floating-point sums included, is the same as running them inline).
// Jobs travel in batches (one lock per batch); at most kMaxBatches wait, then the producer waits.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

namespace cig {

template <class Job>
class JobStream {
 public:
  static constexpr std::size_t kBatch = 512;
  static constexpr std::size_t kMaxBatches = 64;

  JobStream() = default;
  JobStream(const JobStream&) = delete;
  JobStream& operator=(const JobStream&) = delete;
  ~JobStream() { finish(); }

  // Starts the worker: it calls work(job) for every job pushed until finish().
  void start(std::function<void(Job&)> work) {
    finish();
    work_ = std::move(work);
    done_ = false;
    thread_ = std::thread([this] { loop(); });
  }
  bool running() const { return thread_.joinable(); }

  // The next job's slot (filled by the caller before the next push or finish).
  Job& push() {
    if (batch_.size() >= kBatch) hand_over();
    batch_.emplace_back();
    return batch_.back();
  }

  // Hands over the last batch and waits until the worker has run every job.
  void finish() {
    if (!thread_.joinable()) return;
    hand_over();
    {
      std::lock_guard<std::mutex> lock(mutex_);
      done_ = true;
    }
    ready_.notify_all();
    thread_.join();
  }

 private:
  void hand_over() {
    if (batch_.empty()) return;
    std::vector<Job> next;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      room_.wait(lock, [&] { return full_.size() < kMaxBatches; });
      full_.push_back(std::move(batch_));
      if (!spare_.empty()) {
        next = std::move(spare_.back());
        spare_.pop_back();
      }
    }
    ready_.notify_one();
    batch_ = std::move(next);
    batch_.clear();
    batch_.reserve(kBatch);
  }

  void loop() {
    for (;;) {
      std::vector<Job> batch;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        ready_.wait(lock, [&] { return !full_.empty() || done_; });
        if (full_.empty()) return;
        batch = std::move(full_.front());
        full_.pop_front();
      }
      room_.notify_one();
      for (Job& job : batch) work_(job);
      batch.clear();
      std::lock_guard<std::mutex> lock(mutex_);
      spare_.push_back(std::move(batch));
    }
  }

  std::function<void(Job&)> work_;
  std::vector<Job> batch_;  // being filled by the producer
  std::mutex mutex_;
  std::condition_variable ready_, room_;
  std::deque<std::vector<Job>> full_;  // handed over, in order
  std::vector<std::vector<Job>> spare_;
  bool done_ = false;
  std::thread thread_;
};

}  // namespace cig
