// SPDX-License-Identifier: BSD-3-Clause
#include "oblique/oblique_inverse.hpp"

#include <fmt/core.h>

#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <vector>

#include "restitution/contact_law.hpp"
#include "restitution/errors.hpp"

namespace restitution::oblique {
namespace {

// The scan: 6 decades below the natural scale and 3 above, 10 points a decade. Above, a linear spring
// chatters between stick and slip (more than solve_oblique's 1000 switches at 1e6), and linear_nohistory's
// γ_t has long stopped the slip (e_t = 0 to 1e-12 from γ_t = 100 on a 1 mm steel wall at 20°), while from
// γ_t ~ 3000 the solve no longer finds the slip's end (docs/oblique.md, "The inverse").
constexpr int kDecadesBelow = 6;
constexpr int kDecadesAbove = 3;
constexpr int kPointsPerDecade = 10;

// The parameter's natural scale: κ = 1 in the natural units of the normal law (k_t T²/m*, and mindlin's
// k_t sqrt(R* v T) T²/m*); γ_t = 1 (a tangential damping as strong as the normal one).
double natural_scale(const TangentialInverseRequest& r) {
  if (r.tangential.kind == TangentialKind::linear_nohistory) return 1.0;
  const double mass = effective_mass_kg(r.geometry);
  const double time_s = physical_time_scale_s(r.normal.kind, r.normal.stiffness, mass, r.impact.normal_m_s);
  double scale = mass / (time_s * time_s);
  if (r.tangential.kind == TangentialKind::mindlin) {
    scale /= std::sqrt(effective_radius_m(r.geometry) * r.impact.normal_m_s * time_s);
  }
  return scale;
}

TangentialForce with_parameter(const TangentialInverseRequest& r, double parameter) {
  TangentialForce t = r.tangential;
  (t.kind == TangentialKind::linear_nohistory ? t.damping_factor : t.stiffness) = parameter;
  return t;
}

}  // namespace

TangentialInverseResult tangential_parameter_for(const TangentialInverseRequest& request) {
  require_oblique_tolerance(request.tolerance, "the inverse's tolerance");
  const double target = request.target_et;
  if (!std::isfinite(target))
    throw InvalidInput(fmt::format("the target e_t must be finite, got {}", target));
  if (!(request.tangential.friction > 0.0)) {
    throw InvalidInput("the target e_t needs friction: without it e_t = -1 whatever the tangential model");
  }
  const bool damping_sought = request.tangential.kind == TangentialKind::linear_nohistory;
  if (damping_sought && !(request.normal.damping > 0.0)) {
    throw InvalidInput(
        "linear_nohistory's only parameter, the tangential damping factor, multiplies the normal damping, "
        "which is 0 here: no e_t can be reached");
  }
  const double scale = natural_scale(request);
  // Each scan point at the contract's rtol for a tenth of T, each root-finding solve too.
  ObliqueOptions options = request.options;
  options.relative_tolerance = std::max(1e-14, 1e-4 * request.tolerance);
  const auto et_at = [&](double log_parameter) {
    const ObliqueResult r =
        solve_oblique(request.geometry, request.normal,
                      with_parameter(request, scale * std::exp(log_parameter)), request.impact, options);
    if (!std::isfinite(r.tangential_restitution)) {
      throw InvalidInput("the reference impact has no slip (s = 0): e_t is undefined there");
    }
    return r.tangential_restitution;
  };

  std::vector<double> logs;
  std::vector<double> ets;
  for (int i = -kDecadesBelow * kPointsPerDecade; i <= kDecadesAbove * kPointsPerDecade; ++i) {
    logs.push_back(std::log(10.0) * i / kPointsPerDecade);
    // A very stiff spring can chatter between stick and slip beyond solve_oblique's limit of switches:
    // such a point is left out of the scan.
    try {
      ets.push_back(et_at(logs.back()));
    } catch (const NumericalFailure&) {
      ets.push_back(std::nan(""));
    }
  }
  TangentialInverseResult result;
  result.parameter_name = damping_sought ? "tangential_damping_factor" : "tangential_stiffness";
  result.lowest_reachable_et = HUGE_VAL;
  result.highest_reachable_et = -HUGE_VAL;
  for (const double et : ets) {
    if (!std::isfinite(et)) continue;
    result.lowest_reachable_et = std::min(result.lowest_reachable_et, et);
    result.highest_reachable_et = std::max(result.highest_reachable_et, et);
  }
  if (!(target >= result.lowest_reachable_et && target <= result.highest_reachable_et)) {
    throw InvalidInput(fmt::format(
        "the target e_t = {} is out of reach of {} with these numbers: its {} from {:.3g} to {:.3g} gives "
        "e_t in "
        "[{:.6g}, {:.6g}]",
        target, tangential_name(request.tangential.kind), damping_sought ? "damping factor" : "stiffness",
        scale * std::pow(10.0, -kDecadesBelow), scale * std::pow(10.0, kDecadesAbove),
        result.lowest_reachable_et, result.highest_reachable_et));
  }
  // The sign change nearest the natural scale (log 0).
  std::size_t best = 0;
  for (std::size_t i = 0; i + 1 < ets.size(); ++i) {
    const bool brackets = (ets[i] - target) * (ets[i + 1] - target) <= 0.0;  // false with a NaN
    if (!brackets) continue;
    ++result.roots_in_scan;
    const auto distance = [&](std::size_t j) { return std::abs(logs[j] + logs[j + 1]); };
    if (result.roots_in_scan == 1 || distance(i) < distance(best)) best = i;
  }
  double log_root = logs[best];
  if (ets[best] != target) {
    if (ets[best + 1] == target) {
      log_root = logs[best + 1];
    } else {
      // Stops once e_t is within T/2 of E (each solve's own error is about T/200) or the bracket is at the
      // resolution of doubles.
      const double half = 0.5 * request.tolerance;
      std::uintmax_t iterations = 200;
      double closest = logs[best];
      double closest_error = std::abs(ets[best] - target);
      const auto [a, b] = boost::math::tools::toms748_solve(
          [&](double x) {
            const double error = et_at(x) - target;
            if (std::abs(error) < closest_error) {
              closest = x;
              closest_error = std::abs(error);
            }
            return std::abs(error) <= half ? 0.0 : error;
          },
          logs[best], logs[best + 1], ets[best] - target, ets[best + 1] - target,
          [](double x, double y) { return std::abs(x - y) <= 1e-15 * std::max(1.0, std::abs(x)); },
          iterations);
      (void)a;
      (void)b;
      log_root = closest;
    }
  }
  result.parameter = scale * std::exp(log_root);
  result.check =
      solve_oblique_within(request.geometry, request.normal, with_parameter(request, result.parameter),
                           request.impact, request.tolerance, request.options);
  // e_t can jump where the stick/slip sequence changes: a sign change there is no root.
  const double reached = result.check.result.tangential_restitution;
  if (!(std::abs(reached - target) <= request.tolerance)) {
    throw InvalidInput(
        fmt::format("e_t jumps across the target {} at {} = {:.6g} (a stick/slip boundary): it reaches "
                    "{:.10g} there, not "
                    "within {:g}",
                    target, result.parameter_name, result.parameter, reached, request.tolerance));
  }
  return result;
}

}  // namespace restitution::oblique
