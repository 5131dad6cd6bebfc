// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The library's one thread pool: indices 0 … count-1 handed out to worker threads from a shared counter,
// for sweeps (src/sweep) and scenes (src/scene). Private to the library.
//
// Failure policy: an exception from a worker (from making its body, or from the body at some index) stops
// the run: no new index is handed out, the indices in progress finish, every thread is joined, and the
// first exception is rethrown to the caller. A failure that should only mark its point (a sweep's
// NumericalFailure) is caught by the body itself and recorded with the point. Threads are std::jthread, so
// no path, not even a failure to start a thread, leaves a joinable thread behind (std::terminate).
#include <cstddef>
#include <functional>

namespace restitution::detail {

struct ParallelRun {
  std::size_t count = 0;
  unsigned threads = 0;  // as thread_count(); the caller's thread works as one of them
  // Polled before each index: once it returns true no new index starts (may be empty).
  std::function<bool()> stop_requested;
};

// The threads a run uses: `requested`, or all cores for 0, but at least 1 and at most one per item.
unsigned thread_count(unsigned requested, std::size_t items);

// What one worker thread does with an index.
using IndexBody = std::function<void(std::size_t index)>;

// Calls make_body() once on each worker thread (so each has its own solver, buffers, …) and then the body
// for the indices that thread takes; every index is taken by exactly one thread unless the run stops.
// Returns true when stop_requested ended the run before every index was taken. Rethrows the first
// exception of a worker, as above.
bool parallel_for(const ParallelRun& run, const std::function<IndexBody()>& make_body);

}  // namespace restitution::detail
