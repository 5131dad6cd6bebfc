// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The progress line every long command draws on stderr: "\r  what: done/total (percent), rate/s, time left",
// redrawn at most ten times a second and once at the end. Only on a terminal: when stderr is a file or a
// pipe (tests, scripts) nothing is written. The library reports progress through callbacks; this draws them.
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <functional>
#include <string>
#include <string_view>

namespace restitution::cli {

// "42 s", "1 min 51 s", "2 h 05 min": a duration rounded to the second, as a person reads it.
std::string duration_text(double seconds);

// One progress line without its leading "\r": "what: done/total (P%)", then, when the rate is known
// (items_per_second > 0), ", R/s, T left" before the total and ", R/s, took T" (elapsed_seconds) at it.
std::string progress_text(std::string_view what, std::size_t done, std::size_t total, double items_per_second,
                          double elapsed_seconds);

class ProgressLine {
 public:
  // Draws on stderr when it is a terminal.
  explicit ProgressLine(std::string what);
  // Draws on `stream` when `enabled` (tests).
  ProgressLine(std::string what, std::FILE* stream, bool enabled);
  ~ProgressLine();  // ends an unfinished line so that what follows starts on its own line
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  void update(std::size_t done, std::size_t total);
  // update() as a callback for the library (the line must outlive it).
  [[nodiscard]] std::function<void(std::size_t, std::size_t)> callback();
  // callback() that first throws Interrupted once SIGINT/SIGTERM arrived (with a StopSignals alive): a
  // command that writes its files only at the end stops at the next point, saying so.
  [[nodiscard]] std::function<void(std::size_t, std::size_t)> stoppable_callback();
  [[nodiscard]] bool enabled() const { return enabled_; }

 private:
  std::string what_;
  std::FILE* stream_;
  bool enabled_;
  bool open_ = false;      // a line is drawn and not yet ended by a newline
  bool finished_ = false;  // the line reached its total and was ended
  std::chrono::steady_clock::time_point last_draw_{};
  // The first update: the rate counts the items done since then (a resumed sweep starts part-way).
  std::chrono::steady_clock::time_point start_{};
  std::size_t done_at_start_ = 0;
  std::size_t drawn_width_ = 0;  // characters of the line drawn last, blanked when a shorter one replaces it
};

}  // namespace restitution::cli
