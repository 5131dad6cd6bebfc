// SPDX-License-Identifier: BSD-3-Clause
// The public adhesive collision (restitution/adhesion.hpp): names, one collision, the closed forms.
#include "restitution/adhesion.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "adhesion/adhesive_integration.hpp"
#include "adhesion/adhesive_scales.hpp"
#include "adhesion/jkr_branch.hpp"
#include "restitution/errors.hpp"

namespace restitution {

const std::vector<std::string>& adhesive_model_names() {
  static const std::vector<std::string> names{"jkr-lammps", "jkr", "dmt", "sjkr"};  // AdhesiveModel's order
  return names;
}

AdhesiveModel adhesive_model_from_name(const std::string& name) {
  const auto& names = adhesive_model_names();
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) return static_cast<AdhesiveModel>(i);
  }
  throw InvalidInput(
      fmt::format("unknown adhesive model '{}' (choose one of {})", name, fmt::join(names, ", ")));
}

const std::string& adhesive_model_name(AdhesiveModel model) {
  return adhesive_model_names().at(static_cast<std::size_t>(model));
}

const char* adhesive_outcome_name(AdhesiveOutcome outcome) {
  return outcome == AdhesiveOutcome::stuck ? "stuck" : "bounced";
}

namespace {

void check_tolerance(double tolerance) {
  if (!(tolerance >= 1e-12 && tolerance <= 1e-2)) {
    throw InvalidInput(
        fmt::format("the tolerance of an adhesive solve must lie in [1e-12, 1e-2] (got {})", tolerance));
  }
}

}  // namespace

AdhesiveCollision solve_adhesive(const AdhesiveContact& contact, double impact_speed_m_per_s,
                                 double tolerance) {
  const auto scaled = adhesion::scale_adhesion(contact);
  check_tolerance(tolerance);
  if (!std::isfinite(impact_speed_m_per_s) || impact_speed_m_per_s <= 0.0) {
    throw InvalidInput(
        fmt::format("the impact speed must be finite and positive (got {} m/s)", impact_speed_m_per_s));
  }
  const double speed = impact_speed_m_per_s / scaled.speed_m_per_s();
  const double kinetic = 0.5 * speed * speed;
  const auto end = adhesion::integrate_adhesive(scaled, speed, tolerance);

  AdhesiveCollision result;
  result.outcome = end.outcome;
  result.kinetic_to_adhesion_energy = kinetic;
  result.contact_time_s = end.time * scaled.time_s;
  result.max_compression_m = adhesion::scaled_overlap(contact.model, end.max_position) * scaled.length_m;
  result.viscous_work_j = end.viscous_work * scaled.energy_j;
  result.stats = end.stats;
  if (end.outcome == AdhesiveOutcome::stuck) {
    result.eps = 0.0;
    result.one_minus_eps = 1.0;
    result.hysteresis_work_j = (kinetic - end.viscous_work) * scaled.energy_j;
    return result;
  }
  // 1 − ε² is the fraction of the kinetic energy lost: the break's (closed form) and the viscous work.
  const double lost = (scaled.break_energy + end.viscous_work) / kinetic;
  const double eps_from_energy = std::sqrt(std::max(0.0, 1.0 - lost));
  // Elastic, the balance is exact. Damped, the viscous work carries the integration's relative error, which
  // the difference 1 − lost amplifies by 1/ε²: near ε = 0 the velocity at the break is the better measure.
  const bool from_energy = end.viscous_work == 0.0 || eps_from_energy >= 0.1;
  result.eps = from_energy ? eps_from_energy : std::abs(end.velocity) / speed;
  result.one_minus_eps = from_energy ? lost / (1.0 + eps_from_energy) : 1.0 - result.eps;
  result.hysteresis_work_j = scaled.break_energy * scaled.energy_j;
  return result;
}

double elastic_hysteresis_work_j(const AdhesiveContact& contact) {
  const auto scaled = adhesion::scale_adhesion(contact);
  return scaled.break_energy * scaled.energy_j;
}

double break_overlap_m(const AdhesiveContact& contact) {
  const auto scaled = adhesion::scale_adhesion(contact);
  if (contact.model == AdhesiveModel::dmt || contact.model == AdhesiveModel::sjkr) return 0.0;
  return adhesion::jkr_overlap(scaled.break_radius) * scaled.length_m;
}

double jkr_pull_off_force_n(const AdhesiveContact& contact) {
  adhesion::check_contact(contact);
  return 3.0 * std::numbers::pi * contact.surface_energy_j_per_m2 * contact.effective_radius_m;
}

}  // namespace restitution
