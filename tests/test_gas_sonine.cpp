// SPDX-License-Identifier: BSD-3-Clause
// The evolving first Sonine coefficient a2(t) of the freely cooling gas (src/gas/, docs/gas.md, "The first
// Sonine correction"): the moments mu2 and mu4 of the collision integral against their closed forms for a
// constant eps, a2(t) against the exact solution of its equation for a constant eps and its stationary value
// (van Noije & Ernst), the quasi-static a2 of the viscoelastic gas at small dissipation, and the cooling that
// a2 changes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "gas/collision_integral.hpp"
#include "restitution/errors.hpp"
#include "restitution_gas/cooling.hpp"

namespace restitution::gas {
namespace {

// Spheres of the gas (rho = 920 kg/m^3, R = 5 mm, phi = 0.1, rms speed 1 m/s), a2 evolving.
CoolingRequest evolving_gas(const ImpactLaw& law, double haff_times) {
  CoolingRequest r;
  r.particles.diameter_m = 0.01;
  r.particles.mass_kg = 4.0 / 3.0 * std::numbers::pi * 0.005 * 0.005 * 0.005 * 920.0;
  r.particles.packing_fraction = 0.1;
  r.initial_temperature_j = r.particles.mass_kg;
  r.law = law;
  r.duration = haff_times;
  r.duration_in_haff_times = true;
  r.a2_evolving = true;
  return r;
}

TEST(GasSonineMoments, ConstantEpsGivesTheClosedForms) {
  for (const double eps : {0.1, 0.5, 0.8, 0.99}) {
    ImpactDissipation d(constant_eps_law(eps));
    CollisionIntegral integral(d, 1e-3, 0.0);
    const SonineMoments m = integral.moments(1e-3);
    const double loss = 1.0 - eps * eps;
    // Brilliantov & Poeschel (2000); van Noije & Ernst (1998): mu/sqrt(2 pi).
    // The trapezoidal rule in ln z loses accuracy with the degree of the moment (its error for z^k e^{-z}
    // grows as (2 pi/h)^{k + 1/2} e^{-pi^2/h}): measured 4e-15 for mu2, 6e-13 for the a2 part of mu2, 9e-13
    // for that of mu4.
    EXPECT_NEAR(m.mu2 / loss, 1.0, 1e-13) << eps;
    EXPECT_NEAR(m.mu2_a2 / (3.0 / 16.0 * loss), 1.0, 5e-12) << eps;
    EXPECT_NEAR(m.mu4 / (loss * (4.5 + eps * eps)), 1.0, 5e-12) << eps;
    const double mu4_a2 =
        (1.0 + eps) * (271.0 - 207.0 * eps + 30.0 * eps * eps - 30.0 * eps * eps * eps) / 32.0;
    EXPECT_NEAR(m.mu4_a2 / mu4_a2, 1.0, 5e-12) << eps;
  }
}

// For a constant eps the moments are constant and da2/dx = (p + q a2)/(d0 + d1 a2) (x = ln(T0/T)) integrates
// in closed form from a2 = 0: x(a2) = (d1/q) a2 + ((d0 q - d1 p)/q^2) ln(1 + q a2/p), increasing from 0 to
// the fixed point -p/q, which is van Noije & Ernst's a2 exactly: both are the stationary point of the same
// equation linearised in a2. The exact a2 at each computed T, found by bisection on x(a2), against a2(t).
TEST(GasSonineEvolving, ConstantEpsFollowsTheExactSolutionToVanNoijeErnst) {
  for (const double eps : {0.5, 0.8, 0.95}) {
    const CoolingRequest r = evolving_gas(constant_eps_law(eps), 1e4);
    const CoolingCurve c = cooling_curve(r);
    ASSERT_EQ(c.sonine_a2.size(), c.time_s.size());
    const double d0 = 1.0 - eps * eps;
    const double d1 = 3.0 / 16.0 * d0;
    const double mu4 = d0 * (4.5 + eps * eps);
    const double mu4_a2 =
        (1.0 + eps) * (271.0 - 207.0 * eps + 30.0 * eps * eps - 30.0 * eps * eps * eps) / 32.0;
    const double p = 2.0 * d0 - 0.4 * mu4;
    const double q = 2.0 * (d0 + d1) - 0.4 * mu4_a2;
    const double stationary =
        16.0 * (1.0 - eps) * (1.0 - 2.0 * eps * eps) / (81.0 - 17.0 * eps + 30.0 * eps * eps * (1.0 - eps));
    EXPECT_NEAR(-p / q, stationary, 1e-15);
    auto x_of = [&](double a2) { return d1 / q * a2 + (d0 * q - d1 * p) / (q * q) * std::log1p(q * a2 / p); };
    double worst = 0.0;
    for (std::size_t i = 0; i < c.time_s.size(); ++i) {
      const double x = std::log(r.initial_temperature_j / c.temperature_j[i]);
      double lo = 0.0;
      double hi = stationary;
      for (int k = 0; k < 200; ++k) {
        const double mid = 0.5 * (lo + hi);
        (x_of(mid) < x ? lo : hi) = mid;
      }
      worst = std::max(worst, std::abs(c.sonine_a2[i] - 0.5 * (lo + hi)));
    }
    // Measured 2e-12, 2e-12, 9e-11 of a2 (1e-13 absolute and below); the largest error is the stiff
    // transient at eps = 0.95 (with panels twice as wide it is 5e-8: cooling.cpp's kLargestStiffness).
    EXPECT_LT(worst, 5e-10 * std::abs(stationary)) << eps;
    // The moments' quadrature (1e-12 relative, above) sets how close the end comes to the fixed point.
    EXPECT_NEAR(c.sonine_a2.back(), stationary, 1e-11 * std::abs(stationary)) << eps;
  }
}

// Viscoelastic Hertz at small dissipation: the relaxation of a2 (rate ~ 1/J in x) is fast against the cooling
// (rate J), so a2 sits at the root of its equation. To first order in L = 1 - eps^2 = Lambda z^{1/10}, with
// the elastic part of mu4's a2 coefficient (4) alone: mu2 = Lambda G, mu4 = Lambda (7/2 G + Gamma(3.1)) = 5.6
// Lambda G (G = Gamma(2.1)), and 0 = 2 mu2 - (2/5) mu4 - (8/5) a2 gives a2 = -(3/20) J, J = mu2/sqrt(2 pi):
// a2 is negative and decays with J, as t^{-1/6} (for a constant eps van Noije & Ernst's a2 -> -(1 -
// eps^2)/8). The corrections are O(J): the lag of a2 behind its root, and L^2 terms.
TEST(GasSonineEvolving, ViscoelasticA2FollowsMinusThreeTwentiethsOfTheLossAndVanishes) {
  double previous_deviation = 0.0;
  for (const double eps : {0.99, 0.999}) {
    const CoolingRequest r = evolving_gas(
        impact_law_from_eps(LawKind::viscoelastic_hertz, eps, 2.0, CollisionEnd::delayed_recovery), 1e6);
    const CoolingCurve c = cooling_curve(r);
    double worst = 0.0;
    for (std::size_t i = 0; i < c.time_s.size(); ++i) {
      const double a2 = c.sonine_a2[i];
      const double e = c.effective_eps[i];
      const double mean_loss = (1.0 - e * e) * (1.0 + 3.0 * a2 / 16.0);  // J, from eps_eff's definition
      EXPECT_LT(a2, 0.0) << eps << " at t = " << c.time_s[i];
      if (c.time_s[i] < 100.0 * c.tau0_s) continue;
      EXPECT_LT(std::abs(a2), std::abs(c.sonine_a2[i - 1])) << eps << " at t = " << c.time_s[i];
      const double deviation = std::abs(a2 / mean_loss + 0.15);
      EXPECT_LT(deviation, 0.5 * mean_loss) << eps << " at t = " << c.time_s[i];  // measured <= 0.32 J
      worst = std::max(worst, deviation);
    }
    // Ten times less dissipation, ten times closer (measured 9.5-fold).
    if (previous_deviation > 0.0) EXPECT_LT(worst, 0.2 * previous_deviation);
    previous_deviation = worst;
    EXPECT_LT(std::abs(c.sonine_a2.back()), 0.2 * (1.0 - eps));
  }
}

// At large dissipation a2 changes sign as the gas cools (Brilliantov & Poeschel 2000): van Noije & Ernst's a2
// is positive below eps = 1/sqrt 2 and negative above, and eps_eff rises through it. Eps = 0.5 at 2 m/s
// starts at eps_eff = 0.52.
TEST(GasSonineEvolving, ViscoelasticA2ChangesSignWhereTheEffectiveEpsPassesOneOverRootTwo) {
  const CoolingRequest r = evolving_gas(
      impact_law_from_eps(LawKind::viscoelastic_hertz, 0.5, 2.0, CollisionEnd::delayed_recovery), 1e4);
  const CoolingCurve c = cooling_curve(r);
  std::size_t changes = 0;
  for (std::size_t i = 1; i < c.time_s.size(); ++i) {
    if (c.sonine_a2[i - 1] > 0.0 && c.sonine_a2[i] <= 0.0) {
      ++changes;
      // a2 lags its root a little: measured eps_eff = 0.6968 at 63 tau0.
      EXPECT_NEAR(c.effective_eps[i], 1.0 / std::numbers::sqrt2, 0.02);
    }
  }
  EXPECT_EQ(changes, 1U);
  EXPECT_GT(c.sonine_a2[c.time_s.size() / 3], 0.0);
  EXPECT_LT(c.sonine_a2.back(), 0.0);
}

// The cooling with the evolving a2 differs from the Maxwellian's by O(|a2|): for a constant eps the rate
// carries 1 + 3 a2/16, so late in Haff's law (T ~ (tau0/t)^2) T/T_Maxwell -> (1 + 3 a2/16)^{-2} with van
// Noije & Ernst's a2 (4.7e-3 at eps = 0.8), and the curve joins that of a2 held at that value.
TEST(GasSonineEvolving, CoolingCarriesTheSonineFactor) {
  const double eps = 0.8;
  CoolingRequest evolving = evolving_gas(constant_eps_law(eps), 1e4);
  CoolingRequest maxwellian = evolving;
  maxwellian.a2_evolving = false;
  const CoolingCurve e = cooling_curve(evolving);
  const CoolingCurve m = cooling_curve(maxwellian);
  ASSERT_EQ(e.time_s, m.time_s);  // one tau0 (a2 starts at 0), so the same times
  // A held a2 changes tau0 by its factor: the same times in seconds.
  CoolingRequest held = maxwellian;
  held.a2 =
      16.0 * (1.0 - eps) * (1.0 - 2.0 * eps * eps) / (81.0 - 17.0 * eps + 30.0 * eps * eps * (1.0 - eps));
  held.times_s = e.time_s;
  held.duration = e.duration_s;
  held.duration_in_haff_times = false;
  const CoolingCurve h = cooling_curve(held);
  const double factor = std::pow(1.0 + 3.0 * *held.a2 / 16.0, -2.0);
  EXPECT_GT(factor - 1.0, 4e-3);
  // Measured 1.1e-4 of the factor's excess off (the transient's shift of time, 1/t), and 6e-8 from the held
  // a2.
  EXPECT_NEAR(e.temperature_j.back() / m.temperature_j.back() - 1.0, factor - 1.0, 1e-3 * (factor - 1.0));
  EXPECT_NEAR(e.temperature_j.back() / h.temperature_j.back(), 1.0, 1e-6);
  // Early, before a2 has relaxed, the evolving curve is nearer the Maxwellian's than the held one.
  EXPECT_LT(std::abs(e.temperature_j[10] / m.temperature_j[10] - 1.0),
            std::abs(h.temperature_j[10] / m.temperature_j[10] - 1.0));
}

}  // namespace
}  // namespace restitution::gas
