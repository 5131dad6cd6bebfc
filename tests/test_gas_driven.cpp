// SPDX-License-Identifier: BSD-3-Clause
// The driven granular gas (src/gas/driven.cpp, docs/gas.md): against closed forms (van Noije & Ernst's
// stationary a₂ of white-noise driving, the energy balance with Haff's rate, the drag's exp(−2t/τ_b) without
// loss) and, for viscoelastic Hertz, against an independent quadrature of the balance written here.
#include <gtest/gtest.h>

#include <boost/math/quadrature/exp_sinh.hpp>
#include <cmath>
#include <numbers>

#include "restitution/errors.hpp"
#include "restitution/fast.hpp"
#include "restitution_gas/driven.hpp"

namespace restitution::gas {
namespace {

// The spheres of the cooling gas's tests: ρ = 920 kg/m³, R = 5 mm, φ = 0.1, rms speed 1 m/s per direction.
DrivenRequest driven_gas(const ImpactLaw& law, const Thermostat& thermostat) {
  DrivenRequest r;
  r.gas.particles.diameter_m = 0.01;
  r.gas.particles.mass_kg = 4.0 / 3.0 * std::numbers::pi * 0.005 * 0.005 * 0.005 * 920.0;
  r.gas.particles.packing_fraction = 0.1;
  r.gas.initial_temperature_j = r.gas.particles.mass_kg * 1.0;
  r.gas.law = law;
  r.gas.duration = 10.0;
  r.thermostat = thermostat;
  return r;
}

Thermostat white_noise(double power_w) {
  return {ThermostatKind::white_noise, 0.0, 0.0, power_w};
}
Thermostat langevin(double bath_temperature_j, double bath_time_s) {
  return {ThermostatKind::langevin, bath_temperature_j, bath_time_s, 0.0};
}

// ζ(T) = c √T J: c = (4√π/3) n g₂ σ² /√m, written out from the definitions (docs/gas.md).
double rate_coefficient(const GasParticles& p) {
  const double phi = p.packing_fraction;
  const double g2 = (1.0 - phi / 2.0) / std::pow(1.0 - phi, 3);
  const double n = 6.0 * phi / (std::numbers::pi * std::pow(p.diameter_m, 3));
  return 4.0 * std::sqrt(std::numbers::pi) / 3.0 * n * g2 * p.diameter_m * p.diameter_m /
         std::sqrt(p.mass_kg);
}

// van Noije & Ernst, Granular Matter 1, 57 (1998), white noise in d = 3 (their a₂ of the heated state).
double van_noije_ernst_white_noise_a2(double eps) {
  return 16.0 * (1.0 - eps) * (1.0 - 2.0 * eps * eps) /
         (241.0 - 177.0 * eps + 30.0 * eps * eps * (1.0 - eps));
}

TEST(DrivenGasClosedForms, WhiteNoiseStationaryA2IsVanNoijeErnsts) {
  for (const double eps : {0.3, 0.5, 0.7, 0.8, 0.95}) {
    DrivenRequest r = driven_gas(constant_eps_law(eps), white_noise(1e-4));
    r.gas.a2_evolving = true;
    const SteadyState s = steady_state(r);
    EXPECT_NEAR(s.a2, van_noije_ernst_white_noise_a2(eps), 1e-10) << "eps " << eps;
    // The a₂ equation the curve integrates has it as its fixed point: a₂(t) ends there.
    r.gas.duration = 1e3 * s.relaxation_time_s;
    const DrivenCurve c = driven_curve(r);
    EXPECT_NEAR(c.curve.sonine_a2.back(), van_noije_ernst_white_noise_a2(eps), 1e-10) << "eps " << eps;
    EXPECT_NEAR(c.curve.temperature_j.back() / s.temperature_j, 1.0, 1e-12) << "eps " << eps;
  }
}

TEST(DrivenGasClosedForms, ConstantEpsSteadyTemperatureBalancesHaffsRate) {
  const double eps = 0.8;
  const double loss = 1.0 - eps * eps;
  for (const double a2 : {0.0, 0.02}) {
    // White noise: 2P/3 = c √T (1 − ε²)(1 + 3a₂/16) T.
    DrivenRequest r = driven_gas(constant_eps_law(eps), white_noise(3e-4));
    r.gas.a2 = a2;
    const double c = rate_coefficient(r.gas.particles) * loss * (1.0 + 3.0 * a2 / 16.0);
    const double expected = std::pow(2.0 * 3e-4 / 3.0 / c, 2.0 / 3.0);
    const SteadyState s = steady_state(r);
    EXPECT_NEAR(s.temperature_j / expected, 1.0, 1e-12) << "a2 " << a2;
    EXPECT_NEAR(s.driving_exponent, 2.0 / 3.0, 1e-9);
    EXPECT_NEAR(s.constant_eps_driving_exponent, 2.0 / 3.0, 1e-12);
    // Langevin: 2(T_b − T)/τ_b = c T^{3/2}, a cubic in x = √T solved here by Newton from x = √T_b.
    const double tb = 2.0 * r.gas.initial_temperature_j;
    const double tau = 0.05;
    r.thermostat = langevin(tb, tau);
    double x = std::sqrt(tb);
    for (int i = 0; i < 100; ++i)
      x -= (c * x * x * x + 2.0 * (x * x - tb) / tau) / (3.0 * c * x * x + 4.0 * x / tau);
    const SteadyState sl = steady_state(r);
    EXPECT_NEAR(sl.temperature_j / (x * x), 1.0, 1e-12) << "a2 " << a2;
    // The balance's own rate: dT/dt = −(2/τ_b + (3/2) c √T) (T − T_s) near T_s.
    EXPECT_NEAR(sl.relaxation_time_s * (2.0 / tau + 1.5 * c * x), 1.0, 1e-9);
  }
}

TEST(DrivenGasClosedForms, WithoutLossTheBathRelaxesTheTemperatureAsExpMinus2tOverTau) {
  const double tau = 0.02;
  for (const double tb_over_t0 : {0.01, 3.0}) {
    DrivenRequest r = driven_gas(constant_eps_law(1.0), langevin(0.0, tau));
    const double t0 = r.gas.initial_temperature_j;
    r.thermostat.bath_temperature_j = tb_over_t0 * t0;
    r.gas.duration = 2.0;  // 100 τ_b
    const DrivenCurve c = driven_curve(r);
    EXPECT_EQ(c.steady.temperature_j, r.thermostat.bath_temperature_j);
    EXPECT_DOUBLE_EQ(c.steady.relaxation_time_s, tau / 2.0);
    for (std::size_t i = 0; i < c.curve.time_s.size(); ++i) {
      const double tb = r.thermostat.bath_temperature_j;
      const double expected = tb + (t0 - tb) * std::exp(-2.0 * c.curve.time_s[i] / tau);
      EXPECT_NEAR(c.curve.temperature_j[i] / expected, 1.0, 1e-10) << "t = " << c.curve.time_s[i];
    }
  }
}

// The balance q − 2γT − ζ(T)T = 0 for viscoelastic Hertz, independently: J(T) = ∫₀^∞ z e^{−z} (1 − ε(u)²) dz
// with u = 2√(zT/m), ε from the fast table at ζ = ζ_ref (u/v_ref)^{1/5} (exp-sinh quadrature), T by
// bisection.
double independent_steady_temperature(const DrivenRequest& r) {
  const ImpactLaw& law = r.gas.law;
  const double m = r.gas.particles.mass_kg;
  auto mean_loss = [&](double temperature) {
    auto integrand = [&](double z) {
      const double u = 2.0 * std::sqrt(z * temperature / m);
      const double e = fast::eps(law.zeta_at_reference * std::pow(u / law.reference_speed_m_s, 0.2), law.end);
      return z * std::exp(-z) * (1.0 - e * e);
    };
    return boost::math::quadrature::exp_sinh<double>().integrate(integrand, 1e-14);
  };
  const double q = r.thermostat.heating_j_s();
  const double gamma = r.thermostat.drag_hz();
  const double c = rate_coefficient(r.gas.particles);
  auto balance = [&](double t) { return q - 2.0 * gamma * t - c * std::sqrt(t) * mean_loss(t) * t; };
  double lo = 1e-12;
  double hi = 1e3;
  for (int i = 0; i < 200; ++i) {
    const double mid = std::sqrt(lo * hi);
    (balance(mid) > 0.0 ? lo : hi) = mid;
  }
  return std::sqrt(lo * hi);
}

TEST(DrivenGasViscoelastic, SteadyTemperatureMatchesAnIndependentQuadratureOfTheBalance) {
  const ImpactLaw law =
      impact_law_from_eps(LawKind::viscoelastic_hertz, 0.8, 2.0, CollisionEnd::delayed_recovery);
  for (const Thermostat& t :
       {white_noise(1e-5), white_noise(1e-3), langevin(1e-3, 0.1), langevin(1e-4, 1.0)}) {
    const DrivenRequest r = driven_gas(law, t);
    const double expected = independent_steady_temperature(r);
    EXPECT_NEAR(steady_state(r).temperature_j / expected, 1.0, 1e-9) << t.driving();
  }
}

TEST(DrivenGasViscoelastic, DrivingExponentIsTheSlopeOfTheSteadyTemperature) {
  const ImpactLaw law =
      impact_law_from_eps(LawKind::viscoelastic_hertz, 0.8, 2.0, CollisionEnd::delayed_recovery);
  for (const double power : {1e-6, 1e-4, 1e-2}) {
    DrivenRequest r = driven_gas(law, white_noise(power));
    const SteadyState s = steady_state(r);
    const double h = 1e-3;
    r.thermostat.power_w = power * std::exp(h);
    const double up = std::log(steady_state(r).temperature_j);
    r.thermostat.power_w = power * std::exp(-h);
    const double down = std::log(steady_state(r).temperature_j);
    EXPECT_NEAR(s.driving_exponent, (up - down) / (2.0 * h), 1e-6) << power;
    // ε(v) rises as the gas cools: T_s grows more slowly with P than for a constant ε (2/3), towards the
    // elastic limit's 5/8 (J ∝ T^{1/10}).
    EXPECT_LT(s.driving_exponent, 2.0 / 3.0);
    EXPECT_GT(s.driving_exponent, 0.6);
    EXPECT_NEAR(s.constant_eps_driving_exponent, 2.0 / 3.0, 1e-12);
    EXPECT_NEAR(s.power_w, power, 1e-9 * power);  // what goes in is dissipated
  }
}

TEST(DrivenGasViscoelastic, RelaxationApproachesTheSteadyStateAtItsRate) {
  const ImpactLaw law =
      impact_law_from_eps(LawKind::viscoelastic_hertz, 0.8, 2.0, CollisionEnd::delayed_recovery);
  for (const double start : {0.01, 100.0}) {  // T₀/T_s: heated up and cooled down
    DrivenRequest r = driven_gas(law, langevin(1e-3, 0.5));
    r.gas.a2_evolving = true;
    const SteadyState s = steady_state(r);
    r.gas.initial_temperature_j = start * s.temperature_j;
    r.gas.duration = 60.0 * s.relaxation_time_s;
    r.gas.times_s = {20.0 * s.relaxation_time_s, 21.0 * s.relaxation_time_s, 60.0 * s.relaxation_time_s};
    const DrivenCurve c = driven_curve(r);
    const std::vector<double>& t = c.curve.temperature_j;
    // Linear regime: the distance from T_s shrinks by e per relaxation time (a₂'s faster mode has decayed).
    EXPECT_NEAR((t[1] - s.temperature_j) / (t[0] - s.temperature_j), std::exp(-1.0), 1e-3) << start;
    EXPECT_NEAR(t[2] / s.temperature_j, 1.0, 1e-12);
    EXPECT_NEAR(c.curve.sonine_a2[2], s.a2, 1e-12);
  }
}

TEST(DrivenGasBadInput, EachBadThermostatArgumentIsNamed) {
  const ImpactLaw law = constant_eps_law(0.8);
  auto message = [&](const Thermostat& t) {
    try {
      (void)steady_state(driven_gas(law, t));
    } catch (const InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message(langevin(-1.0, 1.0)).find("bath_temperature"), std::string::npos);
  EXPECT_NE(message(langevin(1.0, 0.0)).find("bath_time"), std::string::npos);
  EXPECT_NE(message(white_noise(std::nan(""))).find("power"), std::string::npos);
  EXPECT_NE(message(langevin(1e300, 1e-300)).find("heating"), std::string::npos);
  const DrivenRequest elastic = driven_gas(constant_eps_law(1.0), white_noise(1.0));
  EXPECT_THROW((void)steady_state(elastic), InvalidInput);
}

// gas_curve, the one path of the front ends: with a bath the gas settles at its steady temperature, without
// it the gas cools on; each the very curve of driven_curve or cooling_curve.
TEST(GasCurve, DrivenOnlyWithAThermostat) {
  DrivenRequest r = driven_gas(constant_eps_law(0.8), langevin(0.0, 0.5));
  r.thermostat.bath_temperature_j = 2.0 * r.gas.initial_temperature_j;
  const DrivenCurve free = gas_curve(r.gas, std::nullopt);
  EXPECT_EQ(free.curve.temperature_j, cooling_curve(r.gas).temperature_j);
  EXPECT_LT(free.curve.temperature_j.back(), free.curve.temperature_j.front());
  EXPECT_EQ(free.steady.temperature_j, 0.0);
  const DrivenCurve driven = gas_curve(r.gas, r.thermostat);
  EXPECT_EQ(driven.curve.temperature_j, driven_curve(r).curve.temperature_j);
  // Ten seconds are twenty bath times: the driven gas has settled at its steady state, far above the free
  // gas.
  EXPECT_NEAR(driven.curve.temperature_j.back() / driven.steady.temperature_j, 1.0, 1e-3);
  EXPECT_GT(driven.curve.temperature_j.back(), 10.0 * free.curve.temperature_j.back());
}

}  // namespace
}  // namespace restitution::gas
