// SPDX-License-Identifier: BSD-3-Clause
#include "oblique/oblique_accuracy.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "restitution/errors.hpp"

namespace restitution::oblique {
namespace {

// The spin a slip of the impact speed gives a sphere of this radius: the floor of the spins' relative bound.
double spin_scale(double spin_rad_s, double speed_m_s, double radius_m) {
  return std::max(std::abs(spin_rad_s), speed_m_s / radius_m);
}

// The largest difference of the contract's outputs between a and b, each over its bound T·scale.
double contract_ratio(const ObliqueResult& a, const ObliqueResult& b, const ObliqueGeometry& geometry,
                      const ImpactVelocity& impact, double tolerance) {
  const double speed = std::hypot(impact.normal_m_s, impact.tangential_m_s);
  double ratio = std::abs(a.normal_restitution - b.normal_restitution);
  // e_t is NaN for both without slip at impact: nothing to compare.
  if (std::isfinite(a.tangential_restitution) || std::isfinite(b.tangential_restitution)) {
    ratio = std::max(ratio, std::abs(a.tangential_restitution - b.tangential_restitution));
  }
  ratio = std::max(ratio, std::abs(a.rebound_angle_rad - b.rebound_angle_rad));
  ratio = std::max(ratio, std::abs(a.spin_first_rad_s - b.spin_first_rad_s) /
                              spin_scale(a.spin_first_rad_s, speed, geometry.first.radius_m));
  if (geometry.second) {
    ratio = std::max(ratio, std::abs(a.spin_second_rad_s - b.spin_second_rad_s) /
                                spin_scale(a.spin_second_rad_s, speed, geometry.second->radius_m));
  }
  return std::isfinite(ratio) ? ratio / tolerance : HUGE_VAL;
}

std::string sequence_of(const ObliqueResult& r) {
  std::string out;
  for (const ModeSwitch& s : r.switches)
    out += fmt::format("{}{}", out.empty() ? "" : ",", mode_name(s.mode));
  return out;
}

// The check at 10x the rtol can itself miss T where the outputs are well conditioned (near rtol 1e-12 its
// error no longer falls with the rtol: mindlin at T = 1e-10 differed by 1.0-1.4 T on smooth sweeps); then a
// solve at a tenth of the rtol decides: the same modes and the outputs within T of it show the contract.
bool finer_solve_agrees(const ContractedOblique& out, const ObliqueGeometry& geometry,
                        const NormalForce& normal, const TangentialForce& tangential,
                        const ImpactVelocity& impact, const ObliqueOptions& options) {
  ObliqueOptions finer = options;
  finer.relative_tolerance = 0.1 * out.relative_tolerance;
  try {
    const ObliqueResult r = solve_oblique(geometry, normal, tangential, impact, finer);
    return sequence_of(r) == sequence_of(out.result) &&
           contract_ratio(out.result, r, geometry, impact, out.tolerance) <= 1.0;
  } catch (const NumericalFailure&) {
    return false;  // no evidence either way: the impact stays flagged
  }
}

// Whether the solve needs its check. Where its stick/slip sequence is far from changing
// (ObliqueResult::switch_margin beyond kCheckMargin) and e_t is not the quotient of a small slip at impact
// (beyond kCheckSlip of the velocity scale), the solve at T·kObliqueRtolFactor alone is within T with a wide
// margin and the check would only repeat it: of 48384 impacts (three LAMMPS models, wall and pair, spins 0
// and ±300 rad/s, 0.2°-89.7° every 0.1°, T = 1e-4, 1e-6, 1e-8) 91 % skip it, the worst of them 0.074 T off a
// solve at rtol 1e-13, and none of them is one the check flags (docs/oblique.md, "Accuracy and cost").
bool needs_check(const ObliqueResult& r, const ObliqueGeometry& geometry, const TangentialForce& tangential,
                 const ImpactVelocity& impact) {
  if (r.slides_on_cap || !(r.switch_margin > kCheckMargin)) return true;
  // LAMMPS's _rescale variants: their solve's error falls unevenly with the rtol (oblique_contact.cpp takes
  // CVODE's default step control for them) and reaches 0.67 T at T·kObliqueRtolFactor, too close to T to
  // skip the check (tests/test_oblique_check_skip.cpp).
  if (tangential_model(tangential.kind).rule.rescales_on_unloading) return true;
  double slip = impact.tangential_m_s + geometry.first.radius_m * impact.spin_first_rad_s;
  if (geometry.second) slip += geometry.second->radius_m * impact.spin_second_rad_s;
  const double scale = std::max({impact.normal_m_s, std::abs(impact.tangential_m_s), std::abs(slip)});
  return std::abs(slip) < kCheckSlip * scale;
}

}  // namespace

void require_oblique_tolerance(double tolerance, const char* name) {
  if (!(tolerance >= kSmallestObliqueTolerance && tolerance < kLargestObliqueTolerance)) {
    throw InvalidInput(fmt::format(
        "{} must be in [{:g}, {:g}) for the oblique outputs, got {:g}: below, the independent reference "
        "cannot check them; from {:g} on, the short stick phases are not resolved",
        name, kSmallestObliqueTolerance, kLargestObliqueTolerance, tolerance, kLargestObliqueTolerance));
  }
}

ContractedOblique solve_oblique_within(const ObliqueGeometry& geometry, const NormalForce& normal,
                                       const TangentialForce& tangential, const ImpactVelocity& impact,
                                       double tolerance, const ObliqueOptions& options,
                                       ObliqueCheck check_policy) {
  require_oblique_tolerance(tolerance, "the oblique tolerance");
  ContractedOblique out;
  out.tolerance = tolerance;
  out.relative_tolerance = tolerance * kObliqueRtolFactor;
  ObliqueOptions fine = options;
  fine.relative_tolerance = out.relative_tolerance;
  ObliqueOptions check = options;
  check.relative_tolerance = 10.0 * out.relative_tolerance;
  out.result = solve_oblique(geometry, normal, tangential, impact, fine);
  if (check_policy == ObliqueCheck::where_needed && !needs_check(out.result, geometry, tangential, impact)) {
    out.conditioning = "well-conditioned";
    return out;
  }
  out.checked = true;
  const ObliqueResult coarse = solve_oblique(geometry, normal, tangential, impact, check);
  out.check_ratio = contract_ratio(out.result, coarse, geometry, impact, tolerance);
  const std::string modes = sequence_of(out.result);
  const std::string coarse_modes = sequence_of(coarse);
  if (out.result.slides_on_cap || coarse.slides_on_cap) {
    // Before the mode comparison: such impacts often also find different modes, for this reason.
    const ObliqueResult& sliding = out.result.slides_on_cap ? out.result : coarse;
    out.ill_conditioned = true;
    out.conditioning = fmt::format(
        "not modelled: at t = {:.6g} s the contact slides on the Coulomb cap (the damping is added below the "
        "cap only, so the sticking force drives it straight back onto the cap; the code then alternates "
        "capped and uncapped steps), which the stick/slip solve does not follow: the outputs can be off the "
        "code's by 1e-2 or more",
        sliding.cap_sliding_time_s);
  } else if (modes != coarse_modes) {
    out.ill_conditioned = true;
    out.conditioning = fmt::format(
        "ill-conditioned: near the stick/slip boundary, the solves at rtol {:g} and {:g} find different "
        "modes ({} against {})",
        out.relative_tolerance, check.relative_tolerance, modes, coarse_modes);
  } else if (out.result.closest_switch_approach < kNearSwitch) {
    out.ill_conditioned = true;
    out.conditioning = fmt::format(
        "ill-conditioned: near the stick/slip boundary, a switch function came within {:.2g} of 0 (relative "
        "to "
        "its terms) without crossing it: a slightly different impact switches there",
        out.result.closest_switch_approach);
  } else if (out.check_ratio > 1.0 &&
             !finer_solve_agrees(out, geometry, normal, tangential, impact, options)) {
    out.ill_conditioned = true;
    out.conditioning = fmt::format(
        "ill-conditioned: the outputs at rtol {:g} and {:g} differ by {:.3g} times the tolerance {:g}",
        out.relative_tolerance, check.relative_tolerance, out.check_ratio, tolerance);
  } else {
    out.conditioning = "well-conditioned";
  }
  return out;
}

}  // namespace restitution::oblique
