// SPDX-License-Identifier: BSD-3-Clause
// End-to-end: `restitution eps --law NAME --zeta Z` for every member of the contact-law family.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.hpp"

namespace restitution {
namespace {

using nlohmann::json;
using test_support::run_cli;

TEST(CliEpsFamily, EveryMemberIsAcceptedAndSaysWhetherEpsDependsOnSpeed) {
  const struct {
    const char* law;
    bool speed_independent;
  } members[] = {{"viscoelastic-hertz", false},
                 {"tsuji-hertz", true},
                 {"hertz-constant-damping", false},
                 {"linear-dashpot", true}};
  for (const auto& m : members) {
    const auto outcome = run_cli(std::string("eps --law ") + m.law + " --zeta 0.5 --json");
    ASSERT_EQ(outcome.status, 0) << m.law << ": " << outcome.err;
    const json j = json::parse(outcome.out);
    EXPECT_EQ(j["law"], m.law);
    EXPECT_EQ(j["speed_independent"].get<bool>(), m.speed_independent) << m.law;
    for (const char* end : {"naive", "delayed_recovery"}) {
      const double eps = j[end]["eps"].get<double>();
      EXPECT_GT(eps, 0.0) << m.law << " " << end;
      EXPECT_LT(eps, 1.0) << m.law << " " << end;
    }
  }
}

TEST(CliEpsFamily, TsujiNaiveEndIsItsClosedForm) {
  const auto outcome = run_cli("eps --law tsuji-hertz --zeta 1 --end naive --json");
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  const json j = json::parse(outcome.out);
  EXPECT_EQ(j["zeta"].get<double>(), 1.0);
  EXPECT_NEAR(j["naive"]["eps"].get<double>(), std::exp(-M_PI / 2.0), 1e-10 * std::exp(-M_PI / 2.0));
}

TEST(CliEpsFamily, DashpotTakesZetaAsTwiceTheDampingRatio) {
  const json a = json::parse(run_cli("eps --law linear-dashpot --zeta 0.6 --json").out);
  const json b = json::parse(run_cli("eps --law linear-dashpot --damping-ratio 0.3 --json").out);
  EXPECT_EQ(a["damping_ratio"].get<double>(), 0.3);
  EXPECT_EQ(a["naive"]["eps"].get<double>(), b["naive"]["eps"].get<double>());
}

TEST(CliEpsFamily, TableSaysSpeedIndependence) {
  const auto outcome = run_cli("eps --law tsuji-hertz --zeta 0.5");
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  EXPECT_NE(outcome.out.find("tsuji-hertz"), std::string::npos);
  EXPECT_NE(outcome.out.find("does not depend on the impact speed"), std::string::npos);
}

TEST(CliEpsFamily, BadRequestsGiveOneLineAndStatusTwo) {
  const struct {
    const char* arguments;
    const char* mentions;
  } cases[] = {
      {"eps --law tsuji-hertz --zeta 3 --end naive", "naive end does not exist"},
      {"eps --law hertz-constant-damping --zeta 100 --end naive", "naive end does not exist"},
      {"eps --law tsuji-hertz --zeta 1 --method taylor", "tsuji-hertz"},
      {"eps --law tsuji-hertz --beta 0.2 --velocity 1", "--beta"},
      {"eps --law tsuji-hertz --damping-ratio 0.2", "damping-ratio"},
      {"eps --law linear-dashpot --zeta 0.6 --damping-ratio 0.3", "not both"},
      {"eps --law hertz-constant-damping --zeta -1", "zeta"},
  };
  for (const auto& c : cases) {
    const auto outcome = run_cli(c.arguments);
    EXPECT_EQ(outcome.status, 2) << c.arguments;
    EXPECT_EQ(std::count(outcome.err.begin(), outcome.err.end(), '\n'), 1)
        << c.arguments << ": " << outcome.err;
    EXPECT_NE(outcome.err.find(c.mentions), std::string::npos) << c.arguments << ": " << outcome.err;
  }
}

}  // namespace
}  // namespace restitution
