// SPDX-License-Identifier: BSD-3-Clause
// End-to-end: the `restitution eps` contract (JSON members, numbers that read back exactly, exit statuses).
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "restitution/collision_solver.hpp"

namespace restitution {
namespace {

using nlohmann::json;
using test_support::run_cli;

TEST(CliEps, JsonHasTheContractMembers) {
  const auto outcome = run_cli("eps --zeta 1 --json");
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  EXPECT_TRUE(outcome.err.empty());
  const json j = json::parse(outcome.out);
  EXPECT_EQ(j["law"], "viscoelastic-hertz");
  EXPECT_EQ(j["zeta"].get<double>(), 1.0);
  EXPECT_EQ(j["tolerance"].get<double>(), 1e-10);
  for (const char* end : {"naive", "delayed_recovery"}) {
    ASSERT_TRUE(j.contains(end)) << end;
    for (const char* member : {"eps", "one_minus_eps", "tau", "x"}) EXPECT_TRUE(j[end][member].is_number());
    EXPECT_NEAR(j[end]["eps"].get<double>() + j[end]["one_minus_eps"].get<double>(), 1.0, 1e-15);
  }
  EXPECT_TRUE(j["max_compression"]["tau"].is_number());
  EXPECT_TRUE(j["max_compression"]["x"].is_number());
  EXPECT_GT(j["stats"]["steps"].get<long>(), 0);
  EXPECT_GT(j["stats"]["rhs_evaluations"].get<long>(), 0);
  // ζ = 1: ε_naive = 0.33116481..., ε_delayed = 0.39393060... (this solver, tolerance 1e-10)
  EXPECT_NEAR(j["naive"]["eps"].get<double>(), 0.3311648104, 1e-9);
  EXPECT_NEAR(j["delayed_recovery"]["eps"].get<double>(), 0.3939306032, 1e-9);
}

TEST(CliEps, NumbersReadBackToTheLibrarysDoubles) {
  // Numbers are printed in the shortest form that reads back to the same double (docs/cli.md): the JSON
  // values equal the library's results bit for bit.
  const auto outcome = run_cli("eps --zeta 0.3 --json");
  ASSERT_EQ(outcome.status, 0);
  const json j = json::parse(outcome.out);
  CollisionSolver solver;
  const CollisionResult r = solver.solve(ContactLaw::hertz_natural(0.3), SolveOptions{});
  for (const CollisionEnd end : kCollisionEnds) {
    const json& e = j[end_key(end)];
    EXPECT_EQ(e["eps"].get<double>(), r[end]->eps);
    EXPECT_EQ(e["one_minus_eps"].get<double>(), r[end]->one_minus_eps);
    EXPECT_EQ(e["tau"].get<double>(), r[end]->tau);
    EXPECT_EQ(e["x"].get<double>(), r[end]->x);
  }
  EXPECT_EQ(j["max_compression"]["tau"].get<double>(), r.max_compression.tau);
  EXPECT_EQ(j["max_compression"]["x"].get<double>(), r.max_compression.x);
}

TEST(CliEps, EndNotRequestedIsAbsent) {
  const json j = json::parse(run_cli("eps --zeta 2 --end delayed-recovery --json").out);
  EXPECT_FALSE(j.contains("naive"));
  EXPECT_TRUE(j.contains("delayed_recovery"));
  const json n = json::parse(run_cli("eps --zeta 2 --end naive --json").out);
  EXPECT_TRUE(n.contains("naive"));
  EXPECT_FALSE(n.contains("delayed_recovery"));
}

TEST(CliEps, BetaVelocityFormReportsNaturalUnits) {
  const json a = json::parse(run_cli("eps --beta 0.2 --velocity 32 --json").out);
  const json b = json::parse(run_cli("eps --zeta 0.4 --json").out);  // 0.2 · 32^{1/5} = 0.4
  EXPECT_NEAR(a["zeta"].get<double>(), 0.4, 1e-15);
  EXPECT_NEAR(a["naive"]["eps"].get<double>(), b["naive"]["eps"].get<double>(), 1e-10);
  EXPECT_NEAR(a["naive"]["tau"].get<double>(), b["naive"]["tau"].get<double>(), 1e-8);
  EXPECT_NEAR(a["max_compression"]["x"].get<double>(), b["max_compression"]["x"].get<double>(), 1e-8);
}

TEST(CliEps, DashpotLaw) {
  const auto outcome = run_cli("eps --law linear-dashpot --damping-ratio 0.3 --json");
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  const json j = json::parse(outcome.out);
  EXPECT_EQ(j["law"], "linear-dashpot");
  EXPECT_EQ(j["damping_ratio"].get<double>(), 0.3);
  EXPECT_NEAR(j["naive"]["eps"].get<double>(), std::exp(-0.3 * M_PI / std::sqrt(1 - 0.09)), 1e-10);
}

TEST(CliEps, TableOutputWithoutJson) {
  const auto outcome = run_cli("eps --zeta 0.1");
  ASSERT_EQ(outcome.status, 0);
  EXPECT_NE(outcome.out.find("naive"), std::string::npos);
  EXPECT_NE(outcome.out.find("delayed-recovery"), std::string::npos);
  EXPECT_NE(outcome.out.find("natural units"), std::string::npos);
}

struct BadInput {
  const char* arguments;
  const char* mentions;
};

TEST(CliEps, BadInputGivesOneLineAndStatusTwo) {
  const BadInput cases[] = {
      {"eps --zeta -1", "zeta"},
      {"eps --zeta nan", "zeta"},
      {"eps --zeta inf", "zeta"},
      {"eps --zeta abc", "zeta"},
      {"eps", "zeta"},
      {"eps --zeta 1 --beta 0.2 --velocity 1", "zeta"},
      {"eps --beta 0.2", "velocity"},
      {"eps --beta 0.2 --velocity 0", "velocity"},
      {"eps --beta 0.2 --velocity -3", "velocity"},
      {"eps --zeta 1 --tolerance 1e-20", "tolerance"},
      {"eps --zeta 1 --tolerance 0.5", "tolerance"},
      {"eps --zeta 1 --end sideways", "end"},
      {"eps --zeta 1 --method rk4", "method"},
      {"eps --law linear-dashpot", "damping-ratio"},
      {"eps --law linear-dashpot --damping-ratio 2 --end naive", "naive"},
      {"eps --law linear-dashpot --damping-ratio -0.1", "damping-ratio"},
      {"eps --law spring --zeta 1", "law"},
      {"eps --zeta 1 --bogus", "bogus"},
      {"frobnicate", "frobnicate"},
      {"", "subcommand"},
  };
  for (const BadInput& c : cases) {
    const auto outcome = run_cli(c.arguments);
    EXPECT_EQ(outcome.status, 2) << c.arguments;
    EXPECT_TRUE(outcome.out.empty()) << c.arguments;
    EXPECT_EQ(std::count(outcome.err.begin(), outcome.err.end(), '\n'), 1)
        << c.arguments << ": " << outcome.err;
    EXPECT_NE(outcome.err.find(c.mentions), std::string::npos) << c.arguments << ": " << outcome.err;
  }
}

TEST(CliEps, HelpExitsZero) {
  const auto outcome = run_cli("eps --help");
  EXPECT_EQ(outcome.status, 0);
  EXPECT_NE(outcome.out.find("--zeta"), std::string::npos);
}

}  // namespace
}  // namespace restitution
