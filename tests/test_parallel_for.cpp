// SPDX-License-Identifier: BSD-3-Clause
// The library's thread pool (src/parallel/parallel_for.hpp): every index exactly once, one body per
// thread, stop requests, and its failure policy: a throwing body or a throwing per-thread constructor ends
// the run and is rethrown after every thread is joined (never std::terminate), while failures the body
// records per point let the rest go on.
#include <gtest/gtest.h>

#include <pthread.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "parallel/parallel_for.hpp"

namespace restitution::detail {
namespace {

TEST(ParallelFor, EveryIndexExactlyOnceWithOneBodyPerThread) {
  for (const unsigned threads : {1U, 2U, 4U}) {
    std::vector<std::atomic<int>> seen(1000);
    std::atomic<int> bodies{0};
    std::mutex lock;
    std::set<std::thread::id> ids;
    const bool stopped = parallel_for({seen.size(), threads, {}}, [&]() -> IndexBody {
      ++bodies;
      {
        const std::lock_guard guard(lock);
        ids.insert(std::this_thread::get_id());
      }
      return [&](std::size_t i) { ++seen[i]; };
    });
    EXPECT_FALSE(stopped);
    for (std::size_t i = 0; i < seen.size(); ++i) EXPECT_EQ(seen[i].load(), 1) << i;
    EXPECT_EQ(bodies.load(), static_cast<int>(threads));  // one per thread, the caller's included
    EXPECT_EQ(ids.size(), static_cast<std::size_t>(threads));
  }
}

TEST(ParallelFor, ThreadCountDefaultsToTheCoresAndNeverExceedsTheItems) {
  EXPECT_EQ(thread_count(4, 2), 2U);
  EXPECT_EQ(thread_count(3, 100), 3U);
  EXPECT_EQ(thread_count(5, 0), 1U);
  EXPECT_GE(thread_count(0, 1000), 1U);
  EXPECT_EQ(thread_count(0, 1000), std::max(1U, std::thread::hardware_concurrency()));
}

TEST(ParallelFor, NothingToDoRunsNoBody) {
  int calls = 0;
  parallel_for({0, 2, {}}, [&]() -> IndexBody { return [&](std::size_t) { ++calls; }; });
  EXPECT_EQ(calls, 0);
}

TEST(ParallelFor, PerPointFailuresRecordedByTheBodyLetTheRestGoOn) {
  std::vector<int> failed(200, 0);
  std::vector<int> done(200, 0);
  parallel_for({200, 2, {}}, [&]() -> IndexBody {
    return [&](std::size_t i) {
      try {
        if (i % 7 == 3) throw std::runtime_error("point failed");
        done[i] = 1;
      } catch (const std::runtime_error&) {
        failed[i] = 1;
      }
    };
  });
  for (std::size_t i = 0; i < 200; ++i) EXPECT_EQ(done[i] + failed[i], 1) << i;
  EXPECT_EQ(std::count(failed.begin(), failed.end(), 1), 29);
}

TEST(ParallelFor, AThrowingBodyStopsTheRunAndIsRethrownAfterTheJoin) {
  // With two threads how many indices the other thread finishes before it sees the stop depends on the
  // scheduler (a loaded machine may suspend the failing thread while the other runs to the end), so only
  // the rethrow and the join are checked there; one thread shows that no index starts after the failure.
  for (const unsigned threads : {1U, 2U}) {
    std::atomic<int> started{0};
    std::atomic<int> running{0};
    try {
      parallel_for({10000, threads, {}}, [&]() -> IndexBody {
        return [&](std::size_t i) {
          ++running;
          ++started;
          if (i == 5) {
            --running;
            throw std::logic_error("body failed at 5");
          }
          --running;
        };
      });
      FAIL() << "no exception";
    } catch (const std::logic_error& e) {
      EXPECT_STREQ(e.what(), "body failed at 5");
    }
    EXPECT_EQ(running.load(), 0);                    // every thread had finished its index: they were joined
    if (threads == 1) EXPECT_EQ(started.load(), 6);  // indices 0..5, none after the failure
  }
}

TEST(ParallelFor, AThrowingPerThreadConstructorIsRethrownNotTerminate) {
  // The scene runner's old pool called the solver's constructor outside any try: a throw there ended the
  // program. Here the second thread's constructor throws while the first is busy.
  for (const unsigned threads : {2U, 3U}) {
    std::atomic<int> made{0};
    try {
      parallel_for({100000, threads, {}}, [&]() -> IndexBody {
        if (made++ == 1) throw std::runtime_error("constructor failed");
        return [](std::size_t) {};
      });
      FAIL() << "no exception";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "constructor failed");
    }
    EXPECT_EQ(made.load(), static_cast<int>(threads));  // every thread started and was joined
  }
}

TEST(ParallelFor, AThreadEndedByPthreadExitUnwindsThroughTheRun) {
  // CPython ends a thread that wants the GIL back at interpreter exit with pthread_exit: a forced unwind that
  // a catch (...) must pass on, or the process aborts ("FATAL: exception not rethrown"). Here the caller's
  // thread ends itself at index 20 while the helper keeps working; the helper is stopped and joined.
  struct Run {
    std::atomic<int> done{0};
    std::atomic<bool> returned{false};
    std::thread::id caller;
  } run;
  pthread_t thread{};
  ASSERT_EQ(pthread_create(
                &thread, nullptr,
                [](void* argument) -> void* {
                  auto& r = *static_cast<Run*>(argument);
                  r.caller = std::this_thread::get_id();
                  parallel_for({1000000, 2, {}}, [&r]() -> IndexBody {
                    return [&r](std::size_t) {
                      if (std::this_thread::get_id() == r.caller && r.done.load() >= 20)
                        pthread_exit(nullptr);
                      ++r.done;
                      std::this_thread::sleep_for(std::chrono::microseconds(50));
                    };
                  });
                  r.returned = true;
                  return nullptr;
                },
                &run),
            0);
  ASSERT_EQ(pthread_join(thread, nullptr), 0);
  EXPECT_FALSE(run.returned.load());  // the thread ended inside the run
  const int done = run.done.load();
  EXPECT_GE(done, 20);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_EQ(run.done.load(), done);  // the helper was stopped and joined before the thread ended
}

TEST(ParallelFor, StopRequestStartsNoNewIndex) {
  std::atomic<int> calls{0};
  const bool stopped = parallel_for({1000, 2, [&] { return calls.load() >= 10; }},
                                    [&]() -> IndexBody { return [&](std::size_t) { ++calls; }; });
  EXPECT_TRUE(stopped);
  EXPECT_GE(calls.load(), 10);
  EXPECT_LE(calls.load(), 12);  // at most one index per thread in progress when the request came
}

}  // namespace
}  // namespace restitution::detail
