// SPDX-License-Identifier: BSD-3-Clause
#include "cli/common/stop_signals.hpp"

#include <fmt/core.h>

#include <atomic>
#include <csignal>

namespace restitution::cli {
namespace {

// The signal that asked the command to stop (0: none). The only mutable global of the program: a signal
// handler can do nothing but set a lock-free atomic.
std::atomic<int> stop_signal{0};  // NOLINT(cppcoreguidelines-avoid-non-const-global-variables)
static_assert(std::atomic<int>::is_always_lock_free);

// The handlers StopSignals replaced (one StopSignals lives at a time).
struct sigaction previous_int {};   // NOLINT(cppcoreguidelines-avoid-non-const-global-variables)
struct sigaction previous_term {};  // NOLINT(cppcoreguidelines-avoid-non-const-global-variables)

extern "C" void request_stop(int signal_number) {
  stop_signal.store(signal_number);
}

}  // namespace

StopSignals::StopSignals() {
  stop_signal.store(0);
  struct sigaction action {};
  action.sa_handler = request_stop;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &previous_int);
  sigaction(SIGTERM, &action, &previous_term);
}

StopSignals::~StopSignals() {
  sigaction(SIGINT, &previous_int, nullptr);
  sigaction(SIGTERM, &previous_term, nullptr);
}

int stop_signal_received() {
  return stop_signal.load();
}

Interrupted::Interrupted(int signal_number)
    : std::runtime_error(fmt::format("interrupted by signal {}", signal_number)),
      signal_number_(signal_number) {}

void throw_if_interrupted() {
  if (const int s = stop_signal.load(); s != 0) throw Interrupted(s);
}

}  // namespace restitution::cli
