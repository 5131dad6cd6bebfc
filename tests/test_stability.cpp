// SPDX-License-Identifier: BSD-3-Clause
// The stability report: its checks on a few points, the Adams work bound as a finding, the per-decade
// summary, and the `restitution stability` contract end to end (JSON, CSV, output folder, bad input).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "analysis/stability_report.hpp"
#include "cli_runner.hpp"
#include "restitution/errors.hpp"

namespace restitution {
namespace {

using nlohmann::json;
using test_support::run_cli;
using test_support::slurp;

TEST(Stability, ChecksPassAcrossTheRangeAndAdamsRunsOutOfWorkOnTheStiffTail) {
  StabilityOptions options;
  options.tolerance = 1e-8;
  options.max_steps_per_phase = 20000;
  const StabilityReport report = stability_report({0.0, 1e-8, 1.0, 1e4}, options);
  ASSERT_EQ(report.points.size(), 8U);
  EXPECT_EQ(report.flagged(), 0);
  for (const StabilityPoint& p : report.points) {
    EXPECT_LE(p.self_convergence, options.tolerance) << p.zeta;
    ASSERT_EQ(p.engines.size(), std::size(kCrossCheckedMethods));
    EXPECT_GT(p.steps, 0);
  }
  const StabilityPoint& stiff_naive = report.points[6];
  ASSERT_EQ(stiff_naive.end, CollisionEnd::naive);
  EXPECT_EQ(stiff_naive.method, Method::bdf);
  const EngineCheck& adams = stiff_naive.engines[1];
  EXPECT_FALSE(adams.solved);
  EXPECT_EQ(adams.failure, EngineFailure::too_much_work);
  // Decades: ζ = 0, 1e-8, 1, 1e4, each for both ends; the Adams failure is counted at 1e4.
  ASSERT_EQ(report.decades.size(), 8U);
  EXPECT_EQ(report.decades[6].decade, 1e4);
  EXPECT_EQ(report.decades[6].engine_failures, 1);
}

TEST(Stability, RelativeDifferenceUsesTheSmallPart) {
  EndResult a;
  EndResult b;
  a.eps = 0.999;
  a.one_minus_eps = 1e-3;
  b.eps = 0.999;
  b.one_minus_eps = 1.001e-3;
  EXPECT_NEAR(relative_difference(a, b), 1e-3 / 1.001, 1e-12);
  a.eps = b.eps = 1.0;
  a.one_minus_eps = b.one_minus_eps = 0.0;
  EXPECT_EQ(relative_difference(a, b), 0.0);
}

TEST(Stability, TheSmallestToleranceItAcceptsIsTightenedToTheEnginesSmallest) {
  // 100 kMinTolerance rounds to 9.999999999999999e-10, a hundredth of which lies an ulp below kMinTolerance:
  // a scene's [[stability]] at the default tolerance asked for it and was refused by the engine.
  StabilityOptions options;
  options.tolerance = 100.0 * kMinTolerance;
  ASSERT_LT(options.tolerance / 100.0, kMinTolerance);
  const StabilityReport report = stability_report({1.0}, options);
  ASSERT_EQ(report.points.size(), 2U);
  for (const StabilityPoint& p : report.points) EXPECT_LE(p.self_convergence, options.tolerance);
}

TEST(Stability, RefusesToleranceItCannotTighten) {
  EXPECT_THROW(stability_report({1.0}, {1e-10}), InvalidInput);
  EXPECT_THROW(stability_report({-1.0}, {}), InvalidInput);
  EXPECT_THROW(stability_grid(0), InvalidInput);
  const std::vector<double> grid = stability_grid(1);
  EXPECT_EQ(grid.size(), 20U);
  EXPECT_EQ(grid.front(), 0.0);
  EXPECT_EQ(grid.back(), 1e6);
}

TEST(CliStability, WritesCsvJsonAndReportsOnStdout) {
  // One folder per process: other checkouts may run this test at the same time.
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("restitution-stability-test-" + std::to_string(getpid()));
  std::filesystem::remove_all(folder);
  const auto outcome = run_cli("stability --tolerance 1e-7 --json --out " + folder.string());
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  const json j = json::parse(outcome.out);
  EXPECT_EQ(j["tolerance"].get<double>(), 1e-7);
  EXPECT_EQ(j["flagged"].get<int>(), 0);
  ASSERT_EQ(j["points"].size(), 40U);
  const json& last = j["points"][39];
  EXPECT_EQ(last["zeta"].get<double>(), 1e6);
  EXPECT_EQ(last["end"], "delayed-recovery");
  EXPECT_EQ(last["verdict"], "ok");
  EXPECT_TRUE(last["engines"]["adams"]["solved"].get<bool>());
  EXPECT_EQ(json::parse(slurp((folder / "stability.json").string())), j);
  const std::string csv = slurp((folder / "stability.csv").string());
  EXPECT_EQ(csv.rfind("zeta,end,method,eps,", 0), 0U);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 41);
  std::filesystem::remove_all(folder);
}

TEST(CliStability, BadToleranceExitsTwo) {
  const auto outcome = run_cli("stability --tolerance 1e-11");
  EXPECT_EQ(outcome.status, 2);
  EXPECT_EQ(outcome.err.rfind("restitution: error: ", 0), 0U) << outcome.err;
}

}  // namespace
}  // namespace restitution
