// SPDX-License-Identifier: BSD-3-Clause
#include "parallel/parallel_for.hpp"

#include <cxxabi.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace restitution::detail {
namespace {

class Pool {
 public:
  Pool(const ParallelRun& run, const std::function<IndexBody()>& make_body)
      : run_(run), make_body_(make_body) {}

  bool run() {
    const unsigned threads = thread_count(run_.threads, run_.count);
    {
      std::vector<std::jthread> helpers;
      try {
        helpers.reserve(threads - 1);
        for (unsigned t = 1; t < threads; ++t) helpers.emplace_back([this] { work(); });
      } catch (...) {
        fail(std::current_exception());  // the helpers started so far stop and are joined below
      }
      work();
    }  // every helper is joined here, whatever happened
    if (error_) std::rethrow_exception(error_);
    return stopped_by_request_.load();
  }

 private:
  void work() {
    try {
      const IndexBody body = make_body_();
      while (!stop_.load(std::memory_order_relaxed)) {
        if (run_.stop_requested && run_.stop_requested()) {
          stopped_by_request_ = true;
          stop_ = true;
          return;
        }
        // The only write shared between threads per index: one atomic increment.
        const std::size_t i = next_.fetch_add(1, std::memory_order_relaxed);
        if (i >= run_.count) return;
        body(i);
      }
    } catch (abi::__forced_unwind&) {
      // This thread is being ended (pthread_exit or cancellation): the unwind must go on, or the process
      // aborts; the other threads stop at their next index.
      stop_ = true;
      throw;
    } catch (...) {
      fail(std::current_exception());
    }
  }

  void fail(std::exception_ptr e) {
    const std::lock_guard lock(mutex_);
    if (!error_) error_ = std::move(e);
    stop_ = true;
  }

  const ParallelRun& run_;
  const std::function<IndexBody()>& make_body_;
  // On its own cache line: the counter is written by every thread, the flags are read at every index.
  alignas(64) std::atomic<std::size_t> next_{0};
  alignas(64) std::atomic<bool> stop_{false};
  std::atomic<bool> stopped_by_request_{false};
  std::mutex mutex_;  // guards error_
  std::exception_ptr error_;
};

}  // namespace

unsigned thread_count(unsigned requested, std::size_t items) {
  const unsigned wanted = requested != 0 ? requested : std::max(1U, std::thread::hardware_concurrency());
  return static_cast<unsigned>(std::clamp<std::size_t>(items, 1, wanted));
}

bool parallel_for(const ParallelRun& run, const std::function<IndexBody()>& make_body) {
  return Pool(run, make_body).run();
}

}  // namespace restitution::detail
