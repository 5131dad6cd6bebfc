// SPDX-License-Identifier: BSD-3-Clause
// γ and the damping together from ε at one impact speed plus the sticking speed (docs/adhesion.md §7a).
//
// Why one 1-D root suffices: in the scaled variables of docs/adhesion.md §4 a JKR or DMT collision depends
// on the scaled impact speed and the dimensionless damping c alone, so ε at v = r·v_s (r = v/v_s) is a
// function of c and r only. At a reference γ0 the damping A0 is varied until ε(r·v_s(A0)) = eps; the
// measured v_s then fixes the speed unit, hence γ (v_s ∝ γ^{5/6} at fixed c), and A follows at the same c
// (A ∝ γ^{−1/6}: c = A/t0, t0 ∝ γ^{−1/6}, for every model; docs/adhesion.md §7a derives both).
#include <fmt/format.h>

#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <optional>
#include <utility>

#include "adhesion/sticking_search.hpp"
#include "restitution/adhesive_calibration.hpp"
#include "restitution/adhesive_contact.hpp"
#include "restitution/errors.hpp"

namespace restitution {
namespace {

constexpr int kMaxBracketSteps = 40;

void check_sticking_request(AdhesiveModel model, double eps, double speed, double sticking) {
  if (model == AdhesiveModel::sjkr) {
    throw InvalidInput(
        "sjkr is not calibrated from the sticking speed: its scaled collision has a second group (the lens "
        "size R/L), so v_s and eps do not reduce to one damping number");
  }
  if (!(eps > 0.0 && eps < 1.0)) {
    throw InvalidInput(fmt::format("the measured eps must lie in (0, 1), got {}", eps));
  }
  if (!std::isfinite(speed) || speed <= 0.0) {
    throw InvalidInput(fmt::format("the impact speed must be finite and positive (got {} m/s)", speed));
  }
  if (!std::isfinite(sticking) || sticking <= 0.0) {
    throw InvalidInput(fmt::format("the sticking speed must be finite and positive (got {} m/s)", sticking));
  }
  if (!(sticking < speed)) {
    throw InvalidInput(fmt::format(
        "the sticking speed {} m/s is not below the impact speed {} m/s: at or below v_s the spheres stick "
        "(eps = 0), so no measured eps > 0 belongs to that speed",
        sticking, speed));
  }
  const double ratio = sticking / speed;
  const double undamped = std::sqrt((1.0 - ratio) * (1.0 + ratio));
  if (!(eps < undamped)) {
    throw InvalidInput(fmt::format(
        "eps = {} at {} m/s is not below sqrt(1 - (v_s/v)^2) = {}, the undamped {} model's eps for the "
        "surface energy that gives v_s = {} m/s: damping only lowers eps",
        eps, speed, undamped, adhesive_model_name(model), sticking));
  }
}

// The reference surface energy: the one whose undamped textbook JKR sticks at v_s (any γ0 would do; this one
// keeps the reference collision's numbers near the answer's).
double reference_surface_energy(const Material& material, double sticking_speed_m_per_s) {
  const AdhesiveContact unit = adhesive_contact_of(AdhesiveModel::jkr, material, 1.0, 0.0);
  const double unit_speed = std::sqrt(2.0 * elastic_hysteresis_work_j(unit) / unit.effective_mass_kg);
  return std::pow(sticking_speed_m_per_s / unit_speed, 1.2);
}

}  // namespace

AdhesiveStickingCalibration calibrate_adhesive_sticking(AdhesiveModel model, const Material& material,
                                                        double eps, double impact_speed_m_per_s,
                                                        double sticking_speed_m_per_s, double tolerance) {
  check_sticking_request(model, eps, impact_speed_m_per_s, sticking_speed_m_per_s);
  const double ratio = impact_speed_m_per_s / sticking_speed_m_per_s;
  AdhesiveStickingCalibration out;
  out.undamped_eps = std::sqrt((1.0 - 1.0 / ratio) * (1.0 + 1.0 / ratio));
  const double gamma0 = reference_surface_energy(material, sticking_speed_m_per_s);

  // Bracket by factors of 4 from a thousandth of the elastic contact time at v.
  const AdhesiveContact elastic = adhesive_contact_of(model, material, gamma0, 0.0);
  const double contact_time = solve_adhesive(elastic, impact_speed_m_per_s, tolerance).contact_time_s;
  ++out.solves;
  // The reference contact's sticking speed; nullopt above the critical damping, where they stick at every
  // speed (ε = 0 at any r·v_s: too much damping).
  auto reference_sticking = [&](double log_a) {
    const AdhesiveContact contact = adhesive_contact_of(model, material, gamma0, std::exp(log_a));
    const adhesion::StickingSearch vs = adhesion::search_sticking_speed(contact, tolerance);
    out.solves += vs.solves;
    return std::pair{contact, vs.speed_m_per_s};
  };
  // g(ln A0) = ε at r·v_s(A0) − eps, at γ0: positive as A0 → 0 (the undamped limit), falling with A0.
  auto margin = [&](double log_a) {
    try {
      const auto [contact, vs] = reference_sticking(log_a);
      if (!vs) return -eps;
      ++out.solves;
      return solve_adhesive(contact, ratio * *vs, tolerance).eps - eps;
    } catch (const NumericalFailure& e) {
      throw NumericalFailure(fmt::format(
          "calibrate_adhesive_sticking: at a trial damping of {:g} times the reference collision's time "
          "the solve failed ({}): eps = {} needs a stronger damping than the solver reaches",
          std::exp(log_a) / contact_time, e.what(), eps));
    }
  };
  const double step = std::log(4.0);
  double low = std::log(1e-3 * contact_time), high = low;
  double f_low = margin(low), f_high = f_low;
  for (int k = 0; f_high > 0.0; ++k) {  // too little damping: upwards
    if (k == kMaxBracketSteps)
      throw NumericalFailure("calibrate_adhesive_sticking: no damping brings eps down to the target");
    low = high, f_low = f_high;
    high += step;
    f_high = margin(high);
  }
  for (int k = 0; f_low <= 0.0; ++k) {  // too much: downwards (eps just below the undamped limit)
    if (k == kMaxBracketSteps) {
      throw InvalidInput(
          fmt::format("eps = {} is too close to the undamped limit {} to resolve the damping at tolerance {}",
                      eps, out.undamped_eps, tolerance));
    }
    high = low, f_high = f_low;
    low -= step;
    f_low = margin(low);
  }
  std::uintmax_t iterations = 100;
  const auto [a, b] = boost::math::tools::toms748_solve(
      margin, low, high, f_low, f_high,
      [tolerance](double x, double y) { return std::abs(x - y) <= tolerance; }, iterations);
  const double log_a0 = 0.5 * (a + b);

  // Scale to the measured v_s at the same dimensionless damping.
  const std::optional<double> root_sticking = reference_sticking(log_a0).second;
  if (!root_sticking) {
    throw NumericalFailure(
        "calibrate_adhesive_sticking: the root lies at the critical damping, above which there is no "
        "sticking speed");
  }
  const double gamma_ratio = std::pow(sticking_speed_m_per_s / *root_sticking, 1.2);
  out.surface_energy_j_per_m2 = gamma0 * gamma_ratio;
  out.dissipative_constant_s = std::exp(log_a0) * std::pow(gamma_ratio, -1.0 / 6.0);
  out.contact = adhesive_contact_of(model, material, out.surface_energy_j_per_m2, out.dissipative_constant_s);
  const StickingSpeed vs = sticking_speed(out.contact, tolerance);
  out.sticking_speed_m_per_s = vs.speed_m_per_s;
  out.eps_at_velocity = solve_adhesive(out.contact, impact_speed_m_per_s, tolerance).eps;
  out.solves += vs.solves + 1;
  return out;
}

}  // namespace restitution
