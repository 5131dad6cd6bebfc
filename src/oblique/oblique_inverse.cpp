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
// γ_t has long stopped the slip (e_t = 0 to 1e-12 from γ_t = 100 on a 1 mm steel wall at 20°).
constexpr int kDecadesBelow = 6;
constexpr int kDecadesAbove = 3;
constexpr int kPointsPerDecade = 10;
// |e_t| <= 1 up to what a pair's turning line of centres exchanges with the normal motion.
constexpr double kSlack = 1e-3;

// The parameter's natural scale: κ = 1 in the natural units of the normal law (k_t T²/m*, and mindlin's
// k_t sqrt(R* v T) T²/m*); γ_t = 1 (a tangential damping as strong as the normal one).
double natural_scale(const TangentialInverseRequest& r) {
  const TangentialModel& model = tangential_model(r.tangential.kind);
  if (!model.has_stiffness()) return 1.0;
  const double mass = effective_mass_kg(r.geometry);
  const double time_s = physical_time_scale_s(r.normal.kind, r.normal.stiffness, mass, r.impact.normal_m_s);
  double scale = mass / (time_s * time_s);
  // mindlin's k_t (and its variants') and LIGGGHTS's kt are per sqrt(R* δ), YADE's kso per sqrt(δ).
  if (model.rule.growth == StiffnessGrowth::contact_radius) {
    scale /= std::sqrt(effective_radius_m(r.geometry) * r.impact.normal_m_s * time_s);
  } else if (model.rule.growth == StiffnessGrowth::overlap) {
    scale /= std::sqrt(r.impact.normal_m_s * time_s);
  }
  return scale;
}

// The root of e_t(log p) - E in [lo, hi], where f_lo and f_hi differ in sign: TOMS 748, stopped once e_t is
// within T/2 of E (each solve's own error is about T/200) or the bracket is at the resolution of doubles; the
// closest point seen.
template <class Et>
double root_in(const Et& et_at, double lo, double hi, double f_lo, double f_hi, double target,
               double tolerance) {
  if (f_lo == 0.0) return lo;
  if (f_hi == 0.0) return hi;
  const double half = 0.5 * tolerance;
  std::uintmax_t iterations = 200;
  double closest = std::abs(f_lo) < std::abs(f_hi) ? lo : hi;
  double closest_error = std::min(std::abs(f_lo), std::abs(f_hi));
  boost::math::tools::toms748_solve(
      [&](double x) {
        const double error = et_at(x) - target;
        if (std::abs(error) < closest_error) {
          closest = x;
          closest_error = std::abs(error);
        }
        return std::abs(error) <= half ? 0.0 : error;
      },
      lo, hi, f_lo, f_hi,
      [](double x, double y) { return std::abs(x - y) <= 1e-15 * std::max(1.0, std::abs(x)); }, iterations);
  return closest;
}

TangentialForce with_parameter(const TangentialInverseRequest& r, double parameter) {
  TangentialForce t = r.tangential;
  (tangential_model(t.kind).has_stiffness() ? t.stiffness : t.damping_factor) = parameter;
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
  const bool damping_sought = !tangential_model(request.tangential.kind).has_stiffness();
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
    // So is a point whose |e_t| exceeds 1: a passive contact cannot return more slip than it met, and a
    // solve that says so has failed.
    try {
      const double et = et_at(logs.back());
      ets.push_back(std::abs(et) <= 1.0 + kSlack ? et : std::nan(""));
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
  // The sign changes, nearest the natural scale (log 0) first; the first that holds a root within T.
  std::vector<std::size_t> brackets;
  for (std::size_t i = 0; i + 1 < ets.size(); ++i) {
    if ((ets[i] - target) * (ets[i + 1] - target) <= 0.0) brackets.push_back(i);  // false with a NaN
  }
  result.roots_in_scan = static_cast<int>(brackets.size());
  std::stable_sort(brackets.begin(), brackets.end(), [&](std::size_t i, std::size_t j) {
    return std::abs(logs[i] + logs[i + 1]) < std::abs(logs[j] + logs[j + 1]);
  });
  double jump_at = 0.0;
  double jump_reaches = 0.0;
  for (const std::size_t i : brackets) {
    const double log_root =
        root_in(et_at, logs[i], logs[i + 1], ets[i] - target, ets[i + 1] - target, target, request.tolerance);
    result.parameter = scale * std::exp(log_root);
    result.check =
        solve_oblique_within(request.geometry, request.normal, with_parameter(request, result.parameter),
                             request.impact, request.tolerance, request.options);
    const double reached = result.check.result.tangential_restitution;
    if (std::abs(reached - target) <= request.tolerance) return result;
    // e_t jumps across the target here (where the stick/slip sequence changes): no root.
    if (jump_at == 0.0) {
      jump_at = result.parameter;
      jump_reaches = reached;
    }
  }
  throw InvalidInput(
      fmt::format("e_t jumps across the target {} (at a stick/slip boundary) wherever it crosses it: at {} = "
                  "{:.6g} it reaches "
                  "{:.10g}, not within {:g}",
                  target, result.parameter_name, jump_at, jump_reaches, request.tolerance));
}

}  // namespace restitution::oblique
