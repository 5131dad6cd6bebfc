// SPDX-License-Identifier: BSD-3-Clause
#include "dem/adhesive_lines_lammps.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "dem/adhesive_lines_common.hpp"
#include "restitution/errors.hpp"

namespace restitution::dem {
namespace {

// LAMMPS's step starts and drops the contact inside a step: the force there (|F_touch| at first touch,
// |F_break| at the break) acts for up to one step too long or too short, an energy error up to |F| v dt at
// each end, so |Δε| ≤ (|F_touch| + |F_break|) dt / (m* v ε). The lines ask dt for kTargetEpsError at the
// slowest bounce, and at least kStepsPerContact steps per contact (measured on µm ice, docs/adhesion.md §9:
// t_c/2e5 alone left 1.5e-5 at 1.03 v_s, where ε = 0.24).
constexpr double kTargetEpsError = 1e-5;
constexpr double kStepsPerContact = 2e5;

// |F_touch| + |F_break| [N] of LAMMPS's jkr (−(8/9)F_c at snap-in, −F_c and its damping at the break) or dmt
// (−4πγR at both).
double end_forces_n(const AdhesiveContact& c, double break_speed_m_per_s) {
  const double gamma = c.surface_energy_j_per_m2, radius = c.effective_radius_m;
  if (c.model == AdhesiveModel::dmt) return 8.0 * std::numbers::pi * gamma * radius;
  const double pull_off = jkr_pull_off_force_n(c);
  const double break_radius =
      std::cbrt(9.0 * std::numbers::pi * gamma * radius * radius / (4.0 * c.effective_modulus_pa));
  return (17.0 / 9.0) * pull_off + c.damping * c.effective_mass_kg * break_radius * break_speed_m_per_s;
}

}  // namespace

AdhesiveLammpsLines adhesive_lammps_lines(const AdhesiveLammpsRequest& request) {
  const AdhesiveContact& contact = request.contact;
  if (contact.model == AdhesiveModel::jkr || contact.model == AdhesiveModel::sjkr) {
    throw InvalidInput(
        "LAMMPS codes JKR with its own break rule and damping, and has no sjkr: the lines are for jkr-lammps "
        "or dmt");
  }
  AdhesiveLammpsLines out;
  auto solves = solve_listed_speeds(contact, request.speeds, request.tolerance);
  out.sticking = solves.sticking;
  if (contact.model == AdhesiveModel::jkr_lammps) {
    // The textbook model with the A behind LAMMPS's damp = 2AE*/m*.
    AdhesiveContact textbook = contact;
    textbook.model = AdhesiveModel::jkr;
    textbook.damping = contact.damping * contact.effective_mass_kg / (2.0 * contact.effective_modulus_pa);
    out.textbook_sticking = sticking_speed(textbook, request.tolerance);
  }
  out.speeds = std::move(solves.speeds);
  out.collisions = std::move(solves.collisions);
  const double shortest_contact_s = solves.shortest_contact_s;
  const double deepest_m = solves.deepest_m;
  out.break_overlap_m = break_overlap_m(contact);
  const bool jkr = contact.model == AdhesiveModel::jkr_lammps;
  out.skin_m = round_up_2(jkr ? 3.0 * std::abs(out.break_overlap_m) : deepest_m);
  double timestep_s = shortest_contact_s / kStepsPerContact;
  for (std::size_t i = 0; i < out.speeds.size(); ++i) {
    const auto& c = out.collisions[i];
    if (c.outcome != AdhesiveOutcome::bounced || c.eps == 0.0) continue;
    const double v = out.speeds[i];
    timestep_s = std::min(timestep_s, kTargetEpsError * contact.effective_mass_kg * v * c.eps /
                                          end_forces_n(contact, c.eps * v));
  }
  out.timestep_s = round_down_2(timestep_s);
  out.lines = {
      "units si",
      "atom_style sphere",
      "comm_modify vel yes",
      "pair_style granular",
      fmt::format("pair_coeff * * {} {} {} {} {} tangential linear_history 0 0 0 damping viscoelastic",
                  jkr ? "jkr" : "dmt", request.young_modulus_pa, contact.damping, request.poisson_ratio,
                  contact.surface_energy_j_per_m2),
  };
  for (auto& line : integration_lines(out.skin_m, out.timestep_s)) out.lines.push_back(std::move(line));
  return out;
}

}  // namespace restitution::dem
