// SPDX-License-Identifier: BSD-3-Clause
#include "gas_deck/gas_comparison.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "dem/deck_eps.hpp"
#include "restitution/errors.hpp"
#include "restitution/units.hpp"

namespace restitution::gas_deck {
namespace {

constexpr std::size_t kFewestPoints = 4;

gas::CoolingRequest request_for(const GasSetup& setup, const gas::ImpactLaw& law, double t0_j,
                                const std::vector<double>& times_s, double factor) {
  gas::CoolingRequest r;
  r.particles = setup.particles;
  r.law = law;
  r.initial_temperature_j = t0_j;
  r.duration = times_s.back();
  r.times_s = times_s;
  r.collision_rate_factor = factor;
  return r;
}

// The curve's points at t > 0 and its T at t = 0.
struct Split {
  double t0_j = 0.0;
  std::vector<double> time_s, temperature_j;
};
Split split(const CoolingCurve& c) {
  if (c.time_s.empty() || c.time_s.front() != 0.0)
    throw InvalidInput(fmt::format("the {} run has no temperature at t = 0", c.law));
  Split s;
  s.t0_j = c.temperature_j.front();
  for (std::size_t i = 1; i < c.time_s.size(); ++i) {
    if (!(c.time_s[i] > (s.time_s.empty() ? 0.0 : s.time_s.back()))) continue;  // repeated prints
    s.time_s.push_back(c.time_s[i]);
    s.temperature_j.push_back(c.temperature_j[i]);
  }
  if (s.time_s.size() < kFewestPoints)
    throw InvalidInput(fmt::format("the {} run has {} times after t = 0, at least {} needed", c.law,
                                   s.time_s.size(), kFewestPoints));
  return s;
}

}  // namespace

GasSetup gas_setup(const GasDeckRequest& request) {
  CollisionSolver solver;
  const double a = dem::dissipative_constant(request.material, request.damping, request.end,
                                             request.tolerance, Method::automatic, solver);
  const dem::Pair pair = dem::pair_of(request.material);
  const double k = elastic_constants(request.material).k;
  GasSetup s;
  s.particles = {pair.mass1_kg, 2.0 * pair.radius1_m, request.packing_fraction};
  s.law = gas::hertz_impact_law(hertz_constants(k, a).beta, request.end);
  // The companion's ε: the law's at the calibration speed (1 m/s when A is given), as the deck's.
  const double v = request.damping.velocity_m_s.value_or(1.0);
  s.constant_eps = dem::eps_for(hertz_constants(k, a).beta, v, request.end, request.tolerance, solver);
  s.log = gas_log_setup(request, a, "");
  return s;
}

double late_exponent(const std::vector<double>& time_s, const std::vector<double>& temperature_j) {
  const double from = time_s.back() / kLateSpan;
  double sx = 0.0;
  double sy = 0.0;
  double sxx = 0.0;
  double sxy = 0.0;
  double count = 0;
  for (std::size_t i = 0; i < time_s.size(); ++i) {
    if (time_s[i] < from * (1.0 - 1e-12)) continue;
    const double x = std::log(time_s[i]);
    const double y = std::log(temperature_j[i]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
    count += 1;
  }
  if (count < 2) return NAN;
  return (count * sxy - sx * sy) / (count * sxx - sx * sx);
}

GasComparison compare_with_theory(const GasSetup& setup, const std::vector<CoolingCurve>& curves) {
  for (const auto& c : curves) {
    if (c.law != "viscoelastic" && c.law != "constant-eps")
      throw InvalidInput(fmt::format("a run of law '{}': neither viscoelastic nor constant-eps", c.law));
  }
  GasComparison g;
  const gas::ImpactLaw constant = gas::constant_eps_law(setup.constant_eps);
  const auto companion = std::find_if(curves.begin(), curves.end(),
                                      [](const CoolingCurve& c) { return c.law == "constant-eps"; });
  if (companion != curves.end()) {
    const Split s = split(*companion);
    const double tau0 = gas::haff_reference(request_for(setup, constant, s.t0_j, s.time_s, 1.0)).tau0_s;
    double xy = 0.0;
    double xx = 0.0;
    for (std::size_t i = 0; i < s.time_s.size(); ++i) {
      const double x = s.time_s[i] / tau0;
      xy += x * (std::sqrt(s.t0_j / s.temperature_j[i]) - 1.0);
      xx += x * x;
    }
    g.collision_rate_factor = xy / xx;
    g.collision_rate_factor_measured = true;
  }
  for (const auto& c : curves) {
    const Split s = split(c);
    const gas::ImpactLaw& law = c.law == "viscoelastic" ? setup.law : constant;
    const auto request = request_for(setup, law, s.t0_j, s.time_s, g.collision_rate_factor);
    const gas::CoolingCurve theory = gas::cooling_curve(request);
    RunComparison r;
    r.run = c.source.empty() ? c.law : c.source + " " + c.law;
    r.law = c.law;
    r.time_s = s.time_s;
    r.temperature_j = s.temperature_j;
    r.theory_temperature_j = theory.temperature_j;
    for (std::size_t i = 0; i < s.time_s.size(); ++i) {
      r.max_relative_deviation =
          std::max(r.max_relative_deviation, std::abs(s.temperature_j[i] / theory.temperature_j[i] - 1.0));
    }
    std::vector<double> t{0.0};
    std::vector<double> temperature{s.t0_j};
    std::vector<double> theory_temperature{s.t0_j};
    t.insert(t.end(), s.time_s.begin(), s.time_s.end());
    temperature.insert(temperature.end(), s.temperature_j.begin(), s.temperature_j.end());
    theory_temperature.insert(theory_temperature.end(), theory.temperature_j.begin(),
                              theory.temperature_j.end());
    r.exponent = local_exponent(t, temperature);
    r.theory_exponent = local_exponent(t, theory_temperature);
    r.late_exponent = late_exponent(s.time_s, s.temperature_j);
    r.theory_late_exponent = late_exponent(s.time_s, theory.temperature_j);
    r.haff_times = s.time_s.back() / theory.tau0_s;
    g.runs.push_back(std::move(r));
  }
  return g;
}

}  // namespace restitution::gas_deck
