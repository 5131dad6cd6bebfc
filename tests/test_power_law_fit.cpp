// SPDX-License-Identifier: BSD-3-Clause
// Power-law fits and local slopes: exact laws are recovered, the solver's ε follows the derived large-ζ laws
// (docs/asymptotics.md), and the `restitution fit` contract holds end to end.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "analysis/asymptotics.hpp"
#include "analysis/power_law_fit.hpp"
#include "analysis/power_law_study.hpp"
#include "cli_runner.hpp"
#include "restitution/errors.hpp"

namespace restitution {
namespace {

using nlohmann::json;
using test_support::run_cli;

TEST(PowerLawFit, RecoversAnExactLaw) {
  const std::vector<double> zeta = log_grid(2.0, 2e3, 7);
  std::vector<double> eps;
  eps.reserve(zeta.size());
  for (const double z : zeta) eps.push_back(0.7 * std::pow(z, -1.25));
  const PowerLawFit fit = fit_power_law(zeta, eps);
  EXPECT_NEAR(fit.exponent, -1.25, 1e-13);
  EXPECT_NEAR(fit.prefactor, 0.7, 1e-13);
  EXPECT_LT(fit.exponent_stderr, 1e-13);
  EXPECT_EQ(fit.points, 7);
}

TEST(PowerLawFit, StandardErrorMatchesTheClosedFormForThreePoints) {
  // ln ε = -x + r_i with residuals (+a, -2a, +a) at x = -1, 0, 1: slope stays -1, σ² = 6a², Sxx = 2.
  const double a = 1e-3;
  const std::vector<double> zeta{std::exp(-1.0), 1.0, std::exp(1.0)};
  const std::vector<double> eps{std::exp(1.0 + a), std::exp(-2.0 * a), std::exp(-1.0 + a)};
  const PowerLawFit fit = fit_power_law(zeta, eps);
  EXPECT_NEAR(fit.exponent, -1.0, 1e-13);
  EXPECT_NEAR(fit.exponent_stderr, std::sqrt(6.0 * a * a / 2.0), 1e-12);
  EXPECT_NEAR(fit.max_residual, 2.0 * a, 1e-12);
}

TEST(PowerLawFit, RefusesBadInput) {
  EXPECT_THROW(fit_power_law({1.0, 2.0}, {1.0, 0.5}), InvalidInput);
  EXPECT_THROW(fit_power_law({1.0, 2.0, 3.0}, {1.0, 0.0, 0.5}), InvalidInput);
  EXPECT_THROW(log_grid(10.0, 1.0, 5), InvalidInput);
  EXPECT_THROW(end_from_name("both"), InvalidInput);
}

// κ from the reduced slow-manifold problem, two independent ways: this library's Runge-Kutta and mpmath's
// Taylor integrator at 30 digits (docs/asymptotics.md gives the script): 5.15838170426768521641...
TEST(NaivePrefactor, AgreesWithTheHighPrecisionValueAndTheSolver) {
  const asymptotics::Prefactor kappa = asymptotics::naive_prefactor();
  EXPECT_NEAR(kappa.value, 5.15838170426768521641, 1e-13);
  EXPECT_LT(kappa.error_estimate, 1e-12);
  CollisionSolver solver;
  SolveOptions options;
  options.tolerance = 1e-11;
  options.ends = EndSet{CollisionEnd::naive};
  // Corrections fall off like exp(-2 q ζ^{5/3}): already below the tolerance at ζ = 10.
  const double eps = solver.solve(ContactLaw::hertz_natural(10.0), options)[CollisionEnd::naive]->eps;
  EXPECT_NEAR(eps / asymptotics::naive_eps(10.0, kappa.value), 1.0, 1e-11);
}

TEST(LocalSlope, NaiveSlopeIsMinusFive) {
  CollisionSolver solver;
  const LocalSlope s = local_slope(solver, 100.0, CollisionEnd::naive, 1e-11);
  EXPECT_LT(s.error_estimate, 1e-9);
  EXPECT_NEAR(s.slope, -5.0, s.error_estimate);
}

TEST(LocalSlope, DelayedSlopeFollowsTheDerivedApproach) {
  CollisionSolver solver;
  for (const double zeta : {1e3, 1e4}) {
    const LocalSlope s = local_slope(solver, zeta, CollisionEnd::delayed_recovery, 1e-11);
    const double delta = std::pow(zeta, -5.0 / 3.0);
    const double omitted = 10.0 * std::pow(delta * std::log(delta), 2);
    EXPECT_NEAR(s.slope, asymptotics::delayed_recovery_local_slope(zeta), s.error_estimate + omitted);
    // ... and the approach is resolved: the slope is measurably above -5/3.
    EXPECT_GT(s.slope + 5.0 / 3.0, 10.0 * (s.error_estimate + omitted));
  }
}

TEST(PowerLawStudy, NaiveTailFollowsTheDerivedLawAndReportsProgress) {
  // Beyond ζ = 10 the naive end is ε = κ ζ^{-5} to the tolerance: the fit recovers the derived law it
  // reports.
  const std::vector<double> zetas = log_grid(10.0, 1000.0, 4);
  std::vector<std::size_t> done;
  const PowerLawStudy s =
      power_law_study(zetas, CollisionEnd::naive, 1e-10, [&](std::size_t i, std::size_t n) {
        EXPECT_EQ(n, zetas.size());
        done.push_back(i);
      });
  EXPECT_EQ(done, (std::vector<std::size_t>{1, 2, 3, 4}));
  ASSERT_EQ(s.eps.size(), zetas.size());
  ASSERT_EQ(s.slopes.size(), zetas.size());
  EXPECT_EQ(s.derived_exponent, -5.0);
  EXPECT_NEAR(s.fit.exponent, s.derived_exponent, 1e-6);
  EXPECT_NEAR(s.fit.prefactor / s.derived_prefactor, 1.0, 1e-6);
  for (std::size_t i = 0; i < zetas.size(); ++i) {
    EXPECT_EQ(s.slopes[i].zeta, zetas[i]);
    EXPECT_NEAR(s.slopes[i].slope, -5.0, 1e-6 + s.slopes[i].error_estimate);
  }
}

TEST(PowerLawStudy, DelayedRecoveryComparesWithItsOwnLawAndRefusesUncheckedZeta) {
  const PowerLawStudy s = power_law_study(log_grid(1e2, 1e4, 3), CollisionEnd::delayed_recovery, 1e-10);
  EXPECT_EQ(s.derived_exponent, asymptotics::kDelayedRecoveryExponent);
  EXPECT_EQ(s.derived_prefactor, asymptotics::delayed_recovery_prefactor());
  // The approach to -5/3 is from above (LocalSlope.DelayedSlopeFollowsTheDerivedApproach).
  EXPECT_GT(s.fit.exponent, s.derived_exponent);
  EXPECT_LT(s.fit.exponent, s.derived_exponent + 0.1);
  bool called = false;
  EXPECT_THROW((void)power_law_study({1.0, 10.0, 2e6}, CollisionEnd::naive, 1e-10,
                                     [&](std::size_t, std::size_t) { called = true; }),
               InvalidInput);
  EXPECT_FALSE(called);  // refused before any solve
}

TEST(CliFit, NaiveContractAndDerivedLaw) {
  const auto outcome = run_cli("fit --end naive --zeta-range 10:1e5:4 --json");
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  const json j = json::parse(outcome.out);
  EXPECT_EQ(j["end"], "naive");
  EXPECT_EQ(j["points"].get<int>(), 4);
  EXPECT_NEAR(j["exponent_zeta"].get<double>(), -5.0, 1e-9);
  EXPECT_DOUBLE_EQ(j["exponent_velocity"].get<double>(), j["exponent_zeta"].get<double>() / 5.0);
  EXPECT_NEAR(j["prefactor"].get<double>() / asymptotics::naive_prefactor().value, 1.0, 1e-8);
  EXPECT_TRUE(j["stderr"].is_number());
  ASSERT_EQ(j["local_slopes"].size(), 4U);
  EXPECT_EQ(j["local_slopes"][0]["zeta"].get<double>(), 10.0);
  EXPECT_NEAR(j["local_slopes"][3]["slope"].get<double>(), -5.0, 1e-8);
}

TEST(CliFit, DelayedFitApproachesMinusFiveThirdsFromAbove) {
  const auto outcome = run_cli("fit --end delayed-recovery --zeta-range 1e4:1e6:3 --json");
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  const json j = json::parse(outcome.out);
  const double exponent = j["exponent_zeta"].get<double>();
  EXPECT_GT(exponent, -5.0 / 3.0);
  EXPECT_LT(exponent, -5.0 / 3.0 + 1e-5);
  EXPECT_NEAR(j["derived"]["prefactor"].get<double>(), std::pow(1.5, 2.0 / 3.0), 1e-15);
}

TEST(CliFit, BadInputExitsTwo) {
  for (const char* args : {"fit --end both --zeta-range 1:10:9", "fit --end naive --zeta-range 10:1:9",
                           "fit --end naive --zeta-range 1:10:2", "fit --end naive"}) {
    const auto outcome = run_cli(args);
    EXPECT_EQ(outcome.status, 2) << args;
    EXPECT_EQ(outcome.err.rfind("restitution: error: ", 0), 0U) << outcome.err;
  }
}

}  // namespace
}  // namespace restitution
