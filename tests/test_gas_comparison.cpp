// SPDX-License-Identifier: BSD-3-Clause
// A gas deck's runs against the theory (gas_deck/gas_comparison.hpp): the collision-rate factor is recovered
// from a Haff curve made with it, a run that is the theory deviates by nothing and has the theory's late
// exponent, and a run 3 % off is reported 3 % off.
#include <gtest/gtest.h>

#include <cmath>

#include "gas_deck/gas_comparison.hpp"
#include "restitution/errors.hpp"

namespace {

namespace gd = restitution::gas_deck;

gd::GasDeckRequest issue_gas() {
  gd::GasDeckRequest r;
  r.material.young_modulus_pa = 1e8;
  r.material.poisson_ratio = 0.4;
  r.material.density_kg_m3 = 920.0;
  r.material.radius1_m = r.material.radius2_m = 0.005;
  r.damping.eps = 0.8;
  r.damping.velocity_m_s = 2.0;
  r.packing_fraction = 0.1;
  return r;
}

gd::CoolingCurve curve_of(const std::string& law, const std::vector<double>& t,
                          const std::vector<double>& temperature, double t0) {
  gd::CoolingCurve c;
  c.law = law;
  c.source = "synthetic";
  c.time_s = {0.0};
  c.time_s.insert(c.time_s.end(), t.begin(), t.end());
  c.temperature_j = {t0};
  c.temperature_j.insert(c.temperature_j.end(), temperature.begin(), temperature.end());
  return c;
}

TEST(GasComparison, RecoversTheFactorAndTheTheory) {
  const gd::GasSetup setup = gd::gas_setup(issue_gas());
  EXPECT_NEAR(setup.constant_eps, 0.8, 1e-9);
  const double t0 = 4.8e-4;
  restitution::gas::CoolingRequest haff;
  haff.particles = setup.particles;
  haff.law = restitution::gas::constant_eps_law(setup.constant_eps);
  haff.initial_temperature_j = t0;
  const double tau0 = restitution::gas::haff_reference(haff).tau0_s;
  const double factor = 0.93;
  std::vector<double> t, haff_t;
  for (int i = 0; i < 25; ++i) t.push_back(0.1 * tau0 * std::pow(10.0, i / 10.0));
  for (double x : t) haff_t.push_back(t0 / std::pow(1.0 + factor * x / tau0, 2));
  // The viscoelastic run: the theory itself at that factor, and 3 % warmer.
  restitution::gas::CoolingRequest visco = haff;
  visco.law = setup.law;
  visco.times_s = t;
  visco.duration = t.back();
  visco.collision_rate_factor = factor;
  const auto theory = restitution::gas::cooling_curve(visco);
  std::vector<double> warmer = theory.temperature_j;
  warmer[10] *= 1.03;

  const gd::GasComparison c = gd::compare_with_theory(
      setup, {curve_of("viscoelastic", t, theory.temperature_j, t0), curve_of("constant-eps", t, haff_t, t0),
              curve_of("viscoelastic", t, warmer, t0)});
  EXPECT_NEAR(c.collision_rate_factor, factor, 1e-9);
  ASSERT_EQ(c.runs.size(), 3U);
  EXPECT_EQ(c.runs[0].run, "synthetic viscoelastic");
  EXPECT_LT(c.runs[0].max_relative_deviation, 1e-6);
  EXPECT_NEAR(c.runs[0].late_exponent, c.runs[0].theory_late_exponent, 1e-6);
  EXPECT_LT(c.runs[1].max_relative_deviation, 1e-6);
  EXPECT_NEAR(c.runs[2].max_relative_deviation, 0.03, 1e-6);
  // Haff's late exponent over the last half decade of 25 tau0 is near -2; the viscoelastic one is slower.
  EXPECT_NEAR(c.runs[1].late_exponent,
              -2.0 * std::log((1 + factor * t.back() / tau0) / (1 + factor * t[t.size() - 6] / tau0)) /
                  std::log(t.back() / t[t.size() - 6]),
              0.02);
  EXPECT_GT(c.runs[0].late_exponent, c.runs[1].late_exponent + 0.1);
}

TEST(GasComparison, RefusesRunsWithoutAStart) {
  const gd::GasSetup setup = gd::gas_setup(issue_gas());
  gd::CoolingCurve c = curve_of("viscoelastic", {1, 2, 3, 4}, {4, 3, 2, 1}, 5);
  c.time_s.front() = 0.5;
  EXPECT_THROW(gd::compare_with_theory(setup, {c}), restitution::InvalidInput);
  EXPECT_THROW(gd::compare_with_theory(setup, {curve_of("viscoelastic", {1, 2}, {4, 3}, 5)}),
               restitution::InvalidInput);
  EXPECT_THROW(gd::compare_with_theory(setup, {curve_of("other", {1, 2, 3, 4}, {4, 3, 2, 1}, 5)}),
               restitution::InvalidInput);
}

}  // namespace
