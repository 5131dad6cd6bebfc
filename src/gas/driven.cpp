// SPDX-License-Identifier: BSD-3-Clause
#include "restitution_gas/driven.hpp"

#include <fmt/core.h>

#include <array>
#include <boost/math/tools/roots.hpp>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <limits>

#include "gas/collision_integral.hpp"
#include "gas/cooling_checks.hpp"
#include "restitution/errors.hpp"

namespace restitution::gas {

double Thermostat::heating_j_s() const {
  return kind == ThermostatKind::langevin ? 2.0 * bath_temperature_j / bath_time_s : 2.0 * power_w / 3.0;
}
double Thermostat::drag_hz() const {
  return kind == ThermostatKind::langevin ? 1.0 / bath_time_s : 0.0;
}
double Thermostat::driving() const {
  return kind == ThermostatKind::langevin ? bath_temperature_j : power_w;
}

namespace {

constexpr double kBracketFactor = 4.0;  // the search for T_s steps by this factor in T
constexpr int kBracketSteps = 1100;     // 4^±1100 spans every normal double
constexpr double kExponentStep = 0.01;  // in ln T, for d ln(ζT)/d ln T (Richardson: error ~h⁴)
constexpr double kOdeTolerance = 1e-12;
// T(t) is steady to rounding after this many relaxation times (e^{−80}) once T and a₂ sit within
// kSettled of T_s and the stationary a₂; beyond kAlwaysSettled relaxation times in any case.
constexpr double kSettledTime = 80.0;
constexpr double kAlwaysSettled = 400.0;
constexpr double kSettled = 1e-13;

void check(const DrivenRequest& r) {
  check_cooling_request(r.gas);
  const Thermostat& t = r.thermostat;
  if (t.kind == ThermostatKind::langevin) {
    require_positive(t.bath_temperature_j, "bath_temperature", " J");
    require_positive(t.bath_time_s, "bath_time", " s");
  } else {
    require_positive(t.power_w, "power", " W");
  }
  if (!std::isfinite(t.heating_j_s()) || !(t.heating_j_s() > 0.0)) {
    throw InvalidInput(fmt::format("the thermostat's heating 2 T_b/tau_b = {} J/s is no finite number > 0",
                                   t.heating_j_s()));
  }
}

// The rates of the driven gas at (T, a₂): dT/dt, da₂/dt (linearised in a₂, driven.hpp), the collisional
// cooling rate ζ, the collision frequency ω and the mean loss J.
struct Rates {
  double temperature = 0.0, a2 = 0.0, cooling = 0.0, collisions = 0.0, mean_loss = 0.0;
};

class DrivenGas {
 public:
  explicit DrivenGas(const DrivenRequest& r)
      : r_(r),
        dissipation_(r.gas.law, r.gas.tolerance),
        integral_(dissipation_, r.gas.particles.mass_kg, 0.0),
        heating_(r.thermostat.heating_j_s()),
        drag_(r.thermostat.drag_hz()) {}

  [[nodiscard]] double heating() const { return heating_; }
  [[nodiscard]] double drag() const { return drag_; }
  [[nodiscard]] bool evolving() const { return r_.gas.a2_evolving; }
  [[nodiscard]] double held_a2() const { return r_.gas.a2.value_or(0.0); }

  // ν(T) [1/s] with ζ = ν J: (4√π/3) n g₂ σ² √(T/m), the Maxwellian ω/3, times the collision-rate factor.
  [[nodiscard]] double rate_unit(double temperature_j) const {
    return collision_frequency(temperature_j, 0.0) / 3.0;
  }
  [[nodiscard]] double collision_frequency(double temperature_j, double a2) const {
    const GasParticles& p = r_.gas.particles;
    return r_.gas.collision_rate_factor *
           collision_frequency_hz(p.packing_fraction, p.diameter_m, p.mass_kg, temperature_j, a2);
  }
  SonineMoments moments(double temperature_j) { return integral_.moments(temperature_j); }

  // The root of da₂/dt = 0 at dT/dt = 0: ν[2(μ₂ + a₂μ₂') − (2/5)(μ₄ + a₂μ₄')] = 4γ a₂.
  [[nodiscard]] double stationary_a2(const SonineMoments& m, double nu) const {
    return nu * (2.0 * m.mu2 - 0.4 * m.mu4) / (4.0 * drag_ - nu * (2.0 * m.mu2_a2 - 0.4 * m.mu4_a2));
  }
  // The a₂ of the steady state at T: held, or (evolving) stationary.
  double steady_a2_at(double temperature_j, const SonineMoments& m) {
    return evolving() ? stationary_a2(m, rate_unit(temperature_j)) : held_a2();
  }
  // ζ(T) T [J/s], the collisions' loss of temperature at T with the steady state's a₂.
  double collisional_loss(double temperature_j) {
    const SonineMoments m = moments(temperature_j);
    return rate_unit(temperature_j) * m.mean_loss(steady_a2_at(temperature_j, m)) * temperature_j;
  }

  Rates rates(double temperature_j, double a2) {
    const SonineMoments m = moments(temperature_j);
    const double nu = rate_unit(temperature_j);
    Rates out;
    out.mean_loss = m.mean_loss(a2);
    out.cooling = nu * out.mean_loss;
    out.temperature = heating_ - (2.0 * drag_ + out.cooling) * temperature_j;
    out.collisions = collision_frequency(temperature_j, a2);
    if (evolving()) {
      out.a2 = nu * (2.0 * out.mean_loss - 0.4 * (m.mu4 + a2 * m.mu4_a2)) -
               (4.0 * drag_ + 2.0 * out.temperature / temperature_j) * a2;
    }
    return out;
  }

 private:
  const DrivenRequest& r_;
  ImpactDissipation dissipation_;
  CollisionIntegral integral_;
  double heating_ = 0.0, drag_ = 0.0;
};

// T_s, the root of q − 2γT − ζ(T)T: bracketed by steps of kBracketFactor from T_b (Langevin, where the
// excess is >= 0) or T₀, then TOMS 748 in T to rounding.
double steady_temperature(DrivenGas& gas, const DrivenRequest& r) {
  auto excess = [&](double t) {
    return (2.0 * gas.drag() * t + gas.collisional_loss(t)) / gas.heating() - 1.0;
  };
  const bool langevin = r.thermostat.kind == ThermostatKind::langevin;
  double a = langevin ? r.thermostat.bath_temperature_j : r.gas.initial_temperature_j;
  double fa = excess(a);
  if (fa == 0.0) return a;
  const double factor = fa > 0.0 ? 1.0 / kBracketFactor : kBracketFactor;
  for (int step = 0; step < kBracketSteps; ++step) {
    const double b = a * factor;
    if (!std::isnormal(b)) break;
    const double fb = excess(b);
    if (fb == 0.0) return b;
    if ((fa > 0.0) != (fb > 0.0)) {
      std::uintmax_t iterations = 200;
      const auto [lo, hi] = boost::math::tools::toms748_solve(
          excess, std::min(a, b), std::max(a, b), fa > 0.0 ? fb : fa, fa > 0.0 ? fa : fb,
          boost::math::tools::eps_tolerance<double>(53), iterations);
      return 0.5 * (lo + hi);
    }
    a = b;
    fa = fb;
  }
  throw InvalidInput(
      "the thermostat and the law have no steady state: the collisions lose too little energy to balance "
      "the heating at any temperature (a law without loss under white noise heats the gas without bound)");
}

}  // namespace

SteadyState steady_state(const DrivenRequest& request) {
  check(request);
  DrivenGas gas(request);
  SteadyState s;
  s.temperature_j = steady_temperature(gas, request);
  const double t = s.temperature_j;
  const SonineMoments m = gas.moments(t);
  const double nu = gas.rate_unit(t);
  const double curve_a2 = gas.steady_a2_at(t, m);
  s.a2 = gas.stationary_a2(m, nu);
  const double loss = gas.collisional_loss(t);
  // d ln(ζT)/d ln T by central differences with one Richardson step.
  double slope = 1.5;
  if (loss > 0.0) {
    auto difference = [&](double h) {
      return (std::log(gas.collisional_loss(t * std::exp(h))) -
              std::log(gas.collisional_loss(t * std::exp(-h)))) /
             (2.0 * h);
    };
    slope = (4.0 * difference(0.5 * kExponentStep) - difference(kExponentStep)) / 3.0;
  }
  const double drag_part = 2.0 * gas.drag() * t;
  s.relaxation_time_s = t / (drag_part + loss * slope);
  s.driving_exponent = gas.heating() / (drag_part + loss * slope);
  s.constant_eps_driving_exponent = gas.heating() / (drag_part + 1.5 * loss);
  s.effective_eps = effective_eps_of(m.mean_loss(curve_a2), curve_a2);
  s.collision_frequency_hz = gas.collision_frequency(t, curve_a2);
  s.power_w = 1.5 * loss;
  return s;
}

namespace {

using State = std::array<double, 3>;  // T/T_s, a₂, collisions per sphere; time in relaxation times

// Haff's tangent of the same gas without the thermostat, for reference: infinite τ₀ without loss.
void set_haff_reference(DrivenGas& gas, const DrivenRequest& r, CoolingCurve& c) {
  if (gas.moments(r.gas.initial_temperature_j).mu2 > 0.0) {
    const HaffReference haff = haff_reference(r.gas);
    c.tau0_s = haff.tau0_s;
    c.haff_eps = haff.eps;
  } else {
    c.tau0_s = std::numeric_limits<double>::infinity();
    c.haff_eps = 1.0;
  }
}

// Appends the columns at time t [s] for the state (T, a₂, collisions).
void append_point(DrivenGas& gas, const DrivenRequest& r, CoolingCurve& c, double t, double temperature,
                  double a2, double collisions) {
  const Rates k = gas.rates(temperature, a2);
  c.time_s.push_back(t);
  c.temperature_j.push_back(temperature);
  const double haff_factor = 1.0 + t / c.tau0_s;
  c.haff_temperature_j.push_back(r.gas.initial_temperature_j / (haff_factor * haff_factor));
  c.cooling_rate_hz.push_back(k.cooling);
  c.local_exponent.push_back(t * k.temperature / temperature);
  c.collision_frequency_hz.push_back(k.collisions);
  c.collisions_per_particle.push_back(collisions);
  c.effective_eps.push_back(effective_eps_of(k.mean_loss, a2));
  if (r.gas.a2_evolving) c.sonine_a2.push_back(a2);
}

// The relaxation from T₀ (and a₂(0)) by Dormand–Prince 5(4) with dense output, in units of T_s and of the
// relaxation time; once settled on the steady state the rest of the curve is the steady state itself.
void integrate_relaxation(DrivenGas& gas, const DrivenRequest& r, const SteadyState& s,
                          const std::vector<double>& times, CoolingCurve& c) {
  namespace ode = boost::numeric::odeint;
  const double unit = s.relaxation_time_s;
  const double steady_a2 = r.gas.a2_evolving ? s.a2 : gas.held_a2();
  auto system = [&](const State& y, State& dy, double /*time*/) {
    const double temperature = y[0] * s.temperature_j;
    const Rates k = gas.rates(temperature, y[1]);
    dy = {k.temperature * unit / s.temperature_j, k.a2 * unit, k.collisions * unit};
  };
  auto stepper = ode::make_dense_output(kOdeTolerance, kOdeTolerance, ode::runge_kutta_dopri5<State>());
  const State start{r.gas.initial_temperature_j / s.temperature_j, r.gas.a2.value_or(0.0), 0.0};
  stepper.initialize(start, 0.0, std::min(1e-3, 0.1 * times.front() / unit));
  bool settled = false;
  for (const double t : times) {
    const double target = t / unit;
    while (!settled && stepper.current_time() < target) {
      stepper.do_step(system);
      const State& y = stepper.current_state();
      const double now = stepper.current_time();
      settled = now > kAlwaysSettled || (now > kSettledTime && std::abs(y[0] - 1.0) <= kSettled &&
                                         std::abs(y[1] - steady_a2) <= kSettled);
    }
    State y{};
    if (target <= stepper.current_time()) {
      stepper.calc_state(target, y);
    } else {  // settled: the steady state, its collisions counted on
      y = {1.0, steady_a2,
           stepper.current_state()[2] + s.collision_frequency_hz * unit * (target - stepper.current_time())};
    }
    append_point(gas, r, c, t, y[0] * s.temperature_j, r.gas.a2_evolving ? y[1] : gas.held_a2(), y[2]);
  }
}

}  // namespace

DrivenCurve driven_curve(const DrivenRequest& request) {
  DrivenCurve out;
  out.steady = steady_state(request);
  DrivenGas gas(request);
  CoolingCurve& c = out.curve;
  const GasParticles& p = request.gas.particles;
  c.contact_correlation = contact_correlation(p.packing_fraction);
  c.number_density_m3 = number_density_m3(p.packing_fraction, p.diameter_m);
  c.a2 = request.gas.a2.value_or(0.0);
  c.a2_evolving = request.gas.a2_evolving;
  set_haff_reference(gas, request, c);
  c.duration_s = duration_in_seconds(request.gas, c.tau0_s);
  integrate_relaxation(gas, request, out.steady, output_times(request.gas, c.duration_s), c);
  return out;
}

DrivenCurve gas_curve(const CoolingRequest& request, const std::optional<Thermostat>& thermostat) {
  if (thermostat) return driven_curve({request, *thermostat});
  DrivenCurve free;
  free.curve = cooling_curve(request);
  return free;
}

}  // namespace restitution::gas
