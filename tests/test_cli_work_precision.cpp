// SPDX-License-Identifier: BSD-3-Clause
// End-to-end: `restitution work-precision` (CSV per point and summary, errors against the reference) and
// `restitution reference` (one ζ, and bad input), and `eps --method taylor`.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "cli_runner.hpp"
#include "reference_checks.hpp"

namespace restitution {
namespace {

using test_support::run_cli;
using test_support::slurp;

TEST(CliWorkPrecision, TaylorEngineRowsStayWithinTheirTolerance) {
  // A folder of this process only: other test runs (other checkouts) may run at the same time.
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("restitution-wp-test-" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  const auto outcome = run_cli("work-precision --engine taylor --repeats 1 --out " + dir.string());
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  std::istringstream csv(slurp((dir / "work_precision.csv").string()));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "engine,end,tolerance,zeta,error,median_us,rhs_evaluations,steps");
  int rows = 0;
  while (std::getline(csv, line)) {
    char engine[32], end[32];
    double tolerance = 0, zeta = 0, error = 0, us = 0;
    ASSERT_EQ(std::sscanf(line.c_str(), "%31[^,],%31[^,],%lf,%lf,%lf,%lf", engine, end, &tolerance, &zeta,
                          &error, &us),
              6)
        << line;
    EXPECT_STREQ(engine, "taylor");
    EXPECT_LE(error, tolerance) << line;
    EXPECT_GT(us, 0.0);
    ++rows;
  }
  // 10 tolerances x (9 ζ delayed + 7 ζ naive: the Taylor naive end stops at ζ = 100).
  EXPECT_EQ(rows, 10 * (9 + 7));
  EXPECT_TRUE(std::filesystem::exists(dir / "work_precision_summary.csv"));
  std::filesystem::remove_all(dir);
}

TEST(CliWorkPrecision, UnknownEngineIsAnInputError) {
  const auto outcome = run_cli("work-precision --engine rk4 --out /nonexistent-unused");
  EXPECT_EQ(outcome.status, 2);
  EXPECT_NE(outcome.err.find("unknown engine 'rk4'"), std::string::npos) << outcome.err;
}

TEST(CliReference, PrintsOneZetaWithThirtyFourDigits) {
  const auto outcome = run_cli("reference --zeta 0");
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  // τ_max0 = 1.609032729859521542267965022808740 (the undamped collision's closed form, to 34 digits).
  EXPECT_NE(outcome.out.find("tau = 1.609032729859521542267965022808"), std::string::npos) << outcome.out;
  EXPECT_EQ(run_cli("reference --zeta -1").status, 2);
  EXPECT_EQ(run_cli("reference").status, 2);
}

TEST(CliEps, TaylorMethodMatchesTheReferenceAndItsRange) {
  const auto outcome = run_cli("eps --zeta 1 --method taylor --tolerance 1e-12 --json");
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  const auto j = nlohmann::json::parse(outcome.out);
  EXPECT_EQ(j["method"], "taylor");
  const ReferenceRow* row = reference_row_for(test_support::reference_rows(), 1.0);
  ASSERT_NE(row, nullptr);
  EXPECT_NEAR(j["delayed_recovery"]["eps"].get<double>(), row->ends[CollisionEnd::delayed_recovery]->eps,
              1e-12);
  EXPECT_NEAR(j["naive"]["eps"].get<double>(), row->ends[CollisionEnd::naive]->eps, 1e-12);
  const auto too_tight = run_cli("eps --zeta 1 --method taylor --tolerance 1e-14");
  EXPECT_EQ(too_tight.status, 2);
  EXPECT_NE(too_tight.err.find("below what the Taylor engine can deliver (1e-13)"), std::string::npos)
      << too_tight.err;
  const auto naive_stiff = run_cli("eps --zeta 1000 --method taylor --end naive");
  EXPECT_EQ(naive_stiff.status, 2);
  EXPECT_NE(naive_stiff.err.find("--method bdf"), std::string::npos) << naive_stiff.err;
}

}  // namespace
}  // namespace restitution
