// SPDX-License-Identifier: BSD-3-Clause
// Progress of long work (issue 12, item 13): the library's callbacks count monotonically up to the total,
// and the command line's progress line draws only on a terminal.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "cli/common/progress.hpp"
#include "cli/solve/work_precision_files.hpp"
#include "cli_runner.hpp"
#include "reference/reference_solution.hpp"
#include "reference/work_precision.hpp"
#include "restitution/sweep.hpp"

namespace restitution {
namespace {

struct Calls {
  std::vector<std::size_t> done;
  std::vector<std::size_t> total;
  [[nodiscard]] std::function<void(std::size_t, std::size_t)> callback() {
    return [this](std::size_t d, std::size_t t) {
      done.push_back(d);
      total.push_back(t);
    };
  }
};

void expect_monotone_to(const Calls& calls, std::size_t total) {
  ASSERT_FALSE(calls.done.empty());
  for (std::size_t i = 0; i < calls.done.size(); ++i) {
    EXPECT_EQ(calls.total[i], total);
    EXPECT_LE(calls.done[i], total);
    if (i > 0) EXPECT_GT(calls.done[i], calls.done[i - 1]);
  }
  EXPECT_EQ(calls.done.back(), total);
}

TEST(Progress, SweepCountsEveryPointOnceUpToTheTotal) {
  const std::vector<double> zetas = zeta_values({0.0, 3.0, 13, false});
  SolveOptions options;
  options.tolerance = 1e-8;
  Calls calls;
  SweepControl control;
  control.threads = 2;
  control.progress = calls.callback();
  (void)run_sweep(zetas, options, control);
  expect_monotone_to(calls, zetas.size());
  EXPECT_EQ(calls.done.size(), zetas.size());
}

TEST(Progress, AResumedSweepCountsThePointsAlreadyDone) {
  const std::vector<double> zetas = zeta_values({0.0, 3.0, 6, false});
  Calls calls;
  SweepControl control;
  control.already_done = {true, false, true, false, false, true};
  control.progress = calls.callback();
  (void)run_sweep(zetas, SolveOptions{}, control);
  EXPECT_EQ(calls.done, (std::vector<std::size_t>{4, 5, 6}));
}

TEST(Progress, WorkPrecisionReachesItsTotal) {
  const std::vector<ReferenceRow> reference = read_reference_file(cli::default_reference_file());
  Calls calls;
  const auto rows = measure_work_precision(reference, 1, {"taylor"}, calls.callback());
  EXPECT_FALSE(rows.empty());
  ASSERT_FALSE(calls.total.empty());
  const std::size_t total = calls.total.front();
  EXPECT_GT(total, 1U);
  for (std::size_t i = 0; i < calls.done.size(); ++i) EXPECT_EQ(calls.done[i], i);  // 0, 1, ..., total
  EXPECT_EQ(calls.done.back(), total);
}

std::string drawn(bool enabled, const std::vector<std::pair<std::size_t, std::size_t>>& updates) {
  std::FILE* file = std::tmpfile();
  {
    cli::ProgressLine line("work", file, enabled);
    for (const auto& [done, total] : updates) line.update(done, total);
  }
  std::string text(static_cast<std::size_t>(std::ftell(file)), '\0');
  std::rewind(file);
  text.resize(std::fread(text.data(), 1, text.size(), file));
  std::fclose(file);
  return text;
}

TEST(Progress, TheLineIsDrawnOnlyWhenEnabledAndEndsWithItsTotal) {
  EXPECT_EQ(drawn(false, {{1, 3}, {2, 3}, {3, 3}}), "");
  const std::string text = drawn(true, {{1, 3}, {2, 3}, {3, 3}});
  EXPECT_EQ(text.rfind("\r  work: 1/3 (33%)", 0), 0U) << text;  // the first update is always drawn
  // The last draw has the rate of the two items done after the first update, and the time they took.
  EXPECT_NE(text.find("\r  work: 3/3 (100%), "), std::string::npos) << text;
  EXPECT_NE(text.find("/s, took 0 s"), std::string::npos) << text;
  EXPECT_EQ(text.back(), '\n');
  // Interrupted before the total: the line is still ended, so the next message starts on its own line.
  EXPECT_EQ(drawn(true, {{1, 3}}), "\r  work: 1/3 (33%)\n");
}

TEST(Progress, DurationsReadAsAPersonSaysThem) {
  EXPECT_EQ(cli::duration_text(0.0), "0 s");
  EXPECT_EQ(cli::duration_text(42.4), "42 s");
  EXPECT_EQ(cli::duration_text(59.6), "1 min 00 s");  // rounded to the second first
  EXPECT_EQ(cli::duration_text(111.0), "1 min 51 s");
  EXPECT_EQ(cli::duration_text(7500.0), "2 h 05 min");
  EXPECT_EQ(cli::duration_text(-3.0), "0 s");  // a clock step backwards is no negative time
}

TEST(Progress, RateAndTimeLeftOnceTheRateIsKnown) {
  // No rate yet (the first update): the count alone.
  EXPECT_EQ(cli::progress_text("collisions", 0, 400, 0.0, 0.0), "collisions: 0/400 (0%)");
  // 100 of 400 at 2.5 items/s: 300 left take 120 s.
  EXPECT_EQ(cli::progress_text("collisions", 100, 400, 2.5, 40.0),
            "collisions: 100/400 (25%), 2.5/s, 2 min 00 s left");
  // Fast work: whole items per second; at the total the time it took instead of the time left.
  EXPECT_EQ(cli::progress_text("zeta", 4000, 4000, 1234.4, 3.24), "zeta: 4000/4000 (100%), 1234/s, took 3 s");
  EXPECT_EQ(cli::progress_text("slow", 1, 10, 0.0123, 81.3), "slow: 1/10 (10%), 0.0123/s, 12 min 12 s left");
  // A rate that is no number (0/0) draws nothing rather than "nan".
  EXPECT_EQ(cli::progress_text("x", 1, 2, std::nan(""), 0.0), "x: 1/2 (50%)");
}

TEST(Progress, NothingOnStderrWhenItIsNotATerminal) {
  // The default line checks isatty(stderr): the test harness redirects stderr to a file.
  char folder[] = "/tmp/restitution-progress-XXXXXX";
  ASSERT_NE(mkdtemp(folder), nullptr);
  const std::string out = std::string(folder) + "/s.csv";
  const auto sweep = test_support::run_cli("sweep --zeta-range 0:1:5 --out " + out);
  std::remove(out.c_str());
  std::remove(folder);
  EXPECT_EQ(sweep.status, 0) << sweep.err;
  EXPECT_EQ(sweep.err, "");
  const auto fit = test_support::run_cli("fit --end naive --zeta-range 1:10:5 --json");
  EXPECT_EQ(fit.status, 0) << fit.err;
  EXPECT_EQ(fit.err, "");
  EXPECT_EQ(cli::ProgressLine("x").enabled(), isatty(fileno(stderr)) != 0);
}

}  // namespace
}  // namespace restitution
