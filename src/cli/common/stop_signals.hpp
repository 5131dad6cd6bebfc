// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Ctrl-C (SIGINT) and SIGTERM while a command works: instead of dying mid-write, the command notices the
// signal at its next check, leaves nothing that looks complete, and exits with 128 + the signal number.
#include <stdexcept>

namespace restitution::cli {

// Routes SIGINT and SIGTERM to a flag while it lives; restores the previous handlers after.
class StopSignals {
 public:
  StopSignals();
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;
};

// The signal received since the last StopSignals was installed (0: none).
int stop_signal_received();

// Thrown where work stops for a signal; main() exits with 128 + signal_number.
class Interrupted : public std::runtime_error {
 public:
  explicit Interrupted(int signal_number);
  [[nodiscard]] int signal_number() const { return signal_number_; }

 private:
  int signal_number_;
};

// Throws Interrupted when a signal was received.
void throw_if_interrupted();

}  // namespace restitution::cli
