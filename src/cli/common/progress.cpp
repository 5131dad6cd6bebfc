// SPDX-License-Identifier: BSD-3-Clause
#include "cli/common/progress.hpp"

#include "cli/common/stop_signals.hpp"

#include <unistd.h>

#include <utility>

namespace restitution::cli {
namespace {

// Often enough to look alive, rarely enough to cost nothing against the work it reports.
constexpr std::chrono::milliseconds kRedrawInterval{100};

}  // namespace

ProgressLine::ProgressLine(std::string what)
    : ProgressLine(std::move(what), stderr, isatty(fileno(stderr)) != 0) {}

ProgressLine::ProgressLine(std::string what, std::FILE* stream, bool enabled)
    : what_(std::move(what)), stream_(stream), enabled_(enabled) {}

ProgressLine::~ProgressLine() {
  if (open_) std::fputc('\n', stream_);
}

void ProgressLine::update(std::size_t done, std::size_t total) {
  if (!enabled_ || finished_) return;
  const auto now = std::chrono::steady_clock::now();
  const bool last = done >= total;
  if (!last && open_ && now - last_draw_ < kRedrawInterval) return;
  last_draw_ = now;
  const double percent = total == 0 ? 100.0 : 100.0 * static_cast<double>(done) / static_cast<double>(total);
  std::fprintf(stream_, "\r  %s: %zu/%zu (%.0f%%)", what_.c_str(), done, total, percent);
  open_ = !last;
  finished_ = last;
  if (last) std::fputc('\n', stream_);
  std::fflush(stream_);
}

std::function<void(std::size_t, std::size_t)> ProgressLine::callback() {
  return [this](std::size_t done, std::size_t total) { update(done, total); };
}

std::function<void(std::size_t, std::size_t)> ProgressLine::stoppable_callback() {
  return [this](std::size_t done, std::size_t total) {
    throw_if_interrupted();
    update(done, total);
  };
}

}  // namespace restitution::cli
