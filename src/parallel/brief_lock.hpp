// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A mutex for critical sections of about a microsecond that several workers enter once per item (a sweep's
// finished point: a row appended to its files). lock() first retries for some tens of microseconds and only
// then sleeps: with a plain std::mutex a contended lock sleeps at once, and on two threads a 1e5-point Taylor
// sweep made some 4000 context switches, each costing more than the section it waited for
// (docs/performance.md). Meets the Lockable requirements (std::lock_guard, std::unique_lock). Private to the
// library.
#include <mutex>

namespace restitution::detail {

class BriefLock {
 public:
  void lock() {
    for (int attempt = 0; attempt < kSpins; ++attempt) {
      if (mutex_.try_lock()) return;
      relax();
    }
    mutex_.lock();  // the holder was preempted or the section is long: sleep
  }
  bool try_lock() { return mutex_.try_lock(); }
  void unlock() { mutex_.unlock(); }

 private:
  static constexpr int kSpins = 1000;  // ~50 µs of pause instructions
  static void relax() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#elif defined(__aarch64__)
    asm volatile("yield");
#endif
  }
  std::mutex mutex_;
};

}  // namespace restitution::detail
