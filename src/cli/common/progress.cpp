// SPDX-License-Identifier: BSD-3-Clause
#include "cli/common/progress.hpp"

#include "cli/common/stop_signals.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace restitution::cli {
namespace {

// Often enough to look alive, rarely enough to cost nothing against the work it reports.
constexpr std::chrono::milliseconds kRedrawInterval{100};

std::string rate_text(double items_per_second) {
  return items_per_second >= 100 ? fmt::format("{:.0f}/s", items_per_second)
                                 : fmt::format("{:.3g}/s", items_per_second);
}

}  // namespace

std::string duration_text(double seconds) {
  const auto whole = static_cast<long long>(std::llround(std::max(seconds, 0.0)));
  if (whole < 60) return fmt::format("{} s", whole);
  if (whole < 3600) return fmt::format("{} min {:02} s", whole / 60, whole % 60);
  return fmt::format("{} h {:02} min", whole / 3600, (whole % 3600) / 60);
}

std::string progress_text(std::string_view what, std::size_t done, std::size_t total, double items_per_second,
                          double elapsed_seconds) {
  const double percent = total == 0 ? 100.0 : 100.0 * static_cast<double>(done) / static_cast<double>(total);
  std::string text = fmt::format("{}: {}/{} ({:.0f}%)", what, done, total, percent);
  if (!(items_per_second > 0) || !std::isfinite(items_per_second)) return text;
  if (done >= total)
    return text + fmt::format(", {}, took {}", rate_text(items_per_second), duration_text(elapsed_seconds));
  const double left = static_cast<double>(total - done) / items_per_second;
  return text + fmt::format(", {}, {} left", rate_text(items_per_second), duration_text(left));
}

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
  if (!open_) {
    start_ = now;
    done_at_start_ = done;
  }
  if (!last && open_ && now - last_draw_ < kRedrawInterval) return;
  last_draw_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double rate = done > done_at_start_ && elapsed > 0
                          ? static_cast<double>(done - done_at_start_) / elapsed
                          : 0.0;  // unknown until an item is done after the first update
  const std::string text = "  " + progress_text(what_, done, total, rate, elapsed);
  // A shorter line (fewer digits left) is padded so that no character of the longer one stays behind.
  std::fprintf(stream_, "\r%-*s", static_cast<int>(std::max(text.size(), drawn_width_)), text.c_str());
  drawn_width_ = text.size();
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
