// SPDX-License-Identifier: BSD-3-Clause
// End-to-end: the `restitution series` contract (coefficients, eval, validate, certify; JSON members,
// 17 significant digits, exit statuses).
#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.hpp"
#include "restitution/series.hpp"
#include "restitution_series_study/series_coefficients.hpp"

namespace restitution {
namespace {

using nlohmann::json;
using test_support::run_cli;
using test_support::slurp;

json run_json(const std::string& arguments) {
  const auto outcome = run_cli(arguments);
  EXPECT_EQ(outcome.status, 0) << arguments << ": " << outcome.err;
  EXPECT_TRUE(outcome.err.empty()) << outcome.err;
  return json::parse(outcome.out);
}

TEST(CliSeries, CoefficientsNaive) {
  const json j = run_json("series coefficients --kind naive --count 12 --json");
  EXPECT_EQ(j["kind"], "naive");
  ASSERT_EQ(j["coefficients"].size(), 12u);
  EXPECT_NEAR(j["coefficients"][0].get<double>(), -series::c1_closed_form(), 3e-16);
  EXPECT_EQ(j["coefficients"][11].get<double>(), series::compute_coefficients(12).c[12]);
}

TEST(CliSeries, CoefficientsDelayedRecoveryAndMaxCompression) {
  const json h = run_json("series coefficients --kind delayed-recovery --count 7 --json");
  ASSERT_EQ(h["coefficients"].size(), 8u);  // h_0 ... h_7
  EXPECT_EQ(h["coefficients"][0].get<double>(), 1.0);
  EXPECT_EQ(h["coefficients"][1].get<double>(), 0.0);
  EXPECT_NEAR(h["coefficients"][5].get<double>(), 4.0 / 15.0, 1e-16);
  const json m = run_json("series coefficients --kind max-compression --count 5 --json");
  EXPECT_EQ(m["kind"], "max-compression");
  ASSERT_EQ(m["a"].size(), 5u);  // a_1 ... a_5
  ASSERT_EQ(m["b"].size(), 6u);  // b_0 ... b_5
  EXPECT_EQ(m["b"][0].get<double>(), series::undamped_max_compression());
  EXPECT_NEAR(m["a"][0].get<double>(), -0.28674712506759399, 1e-16);
}

TEST(CliSeries, EvalSeriesAndApproximations) {
  const json naive = run_json("series eval --kind naive --zeta 0.1 --terms 40 --json");
  EXPECT_EQ(naive["kind"], "naive");
  EXPECT_EQ(naive["terms"], 40);
  EXPECT_NEAR(naive["eps"].get<double>() + naive["one_minus_eps"].get<double>(), 1.0, 1e-16);
  const json published =
      run_json("series eval --kind delayed-recovery --zeta 0.1 --coefficients published --json");
  EXPECT_EQ(published["terms"], 20);
  EXPECT_NEAR(published["eps"].get<double>(),
              run_json("series eval --kind delayed-recovery --zeta 0.1 --json")["eps"].get<double>(), 1e-8);
  for (const char* kind : {"pade-1999", "simple-theory-1999", "pade-2011-1-4", "pade-2011-3-6"}) {
    const json j = run_json(std::string("series eval --kind ") + kind + " --zeta 2 --json");
    EXPECT_EQ(j["kind"], kind);
    EXPECT_FALSE(j.contains("terms"));
    EXPECT_GT(j["eps"].get<double>(), 0.0);
    EXPECT_LT(j["eps"].get<double>(), 1.0);
  }
  const json simple = run_json("series eval --kind simple-theory-1999 --zeta 1 --json");
  EXPECT_EQ(simple["eps"].get<double>(), series::simple_theory_1999(1.0).eps);
}

TEST(CliSeries, BadInputExitsWithStatusTwo) {
  for (const char* arguments :
       {"series eval --kind pade-1999 --zeta 1 --terms 3", "series eval --kind naive --zeta -1",
        "series eval --kind naive --zeta 1 --terms 61",
        "series eval --kind naive --zeta 1 --coefficients published --terms 11",
        "series coefficients --kind naive --count 0",
        "series coefficients --kind delayed-recovery --count 121",
        "series coefficients --kind wrong --count 3", "series coefficients --kind naive", "series"}) {
    SCOPED_TRACE(arguments);
    const auto outcome = run_cli(arguments);
    EXPECT_EQ(outcome.status, 2);
    EXPECT_TRUE(outcome.out.empty());
    EXPECT_EQ(outcome.err.rfind("restitution: error: ", 0), 0u) << outcome.err;
    EXPECT_EQ(std::count(outcome.err.begin(), outcome.err.end(), '\n'), 1) << outcome.err;
  }
}

TEST(CliSeries, ValidateWritesCsvJsonAndPlot) {
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("restitution-series-validate-" + std::to_string(::getpid()));
  std::filesystem::remove_all(folder);
  const auto outcome = run_cli("series validate --out " + folder.string());
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  const std::string csv = slurp((folder / "series_validation.csv").string());
  EXPECT_EQ(
      csv.rfind("zeta,naive_eps,naive_one_minus_eps,delayed_recovery_eps,delayed_recovery_one_minus_eps,", 0),
      0u);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 101);  // header + 20 points per decade
  const json j = json::parse(slurp((folder / "series_validation.json").string()));
  EXPECT_EQ(j["approximations"].size(), 9u);
  EXPECT_EQ(j["radii"].size(), 5u);
  EXPECT_EQ(j["approximations"][0]["first_zeta_exceeding"].size(), 3u);
  EXPECT_TRUE(std::filesystem::exists(folder / "series_validation.png")) << outcome.err;
  std::filesystem::remove_all(folder);
}

TEST(CliSeries, CertifyPrintsCertifiedDigitsAndPublishedCheck) {
  const auto outcome = run_cli("series certify --order 10");
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  EXPECT_NE(outcome.out.find("series,k,value,certified_digits\n"), std::string::npos);
  EXPECT_NE(outcome.out.find("c,1,-1.15344885809528879913056743909"), std::string::npos);
  EXPECT_NE(outcome.out.find("2008 Table III,c,1,-1.153448854,"), std::string::npos);
}

}  // namespace
}  // namespace restitution
