// SPDX-License-Identifier: BSD-3-Clause
#include "dem/adhesive_lines_lammps.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "restitution/errors.hpp"

namespace restitution::dem {
namespace {

// Rounds down to two significant digits: a number a user can read in the lines.
double round_down_2(double x) {
  const double scale = std::pow(10.0, std::floor(std::log10(x)) - 1.0);
  return std::floor(x / scale) * scale;
}

// Rounds up to two significant digits.
double round_up_2(double x) {
  const double scale = std::pow(10.0, std::floor(std::log10(x)) - 1.0);
  return std::ceil(x / scale) * scale;
}

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
  if (contact.model == AdhesiveModel::jkr) {
    throw InvalidInput(
        "LAMMPS codes JKR with its own break rule and damping: the lines are for jkr-lammps or dmt");
  }
  AdhesiveLammpsLines out;
  out.sticking = sticking_speed(contact, request.tolerance);
  if (contact.model == AdhesiveModel::jkr_lammps) {
    // The textbook model with the A behind LAMMPS's damp = 2AE*/m*.
    AdhesiveContact textbook = contact;
    textbook.model = AdhesiveModel::jkr;
    textbook.damping = contact.damping * contact.effective_mass_kg / (2.0 * contact.effective_modulus_pa);
    out.textbook_sticking = sticking_speed(textbook, request.tolerance);
  }
  out.speeds = request.speeds;
  if (out.speeds.empty()) {
    if (out.sticking.speed_m_per_s == 0.0) {
      throw InvalidInput("these spheres never stick (elastic DMT): give the speeds with --impact-velocity");
    }
    for (const double k : {0.97, 1.03, 1.05, 1.5, 3.0, 10.0, 100.0}) {
      out.speeds.push_back(k * out.sticking.speed_m_per_s);
    }
  }
  double shortest_contact_s = 0.0;
  double deepest_m = 0.0;
  for (const double v : out.speeds) {
    out.collisions.push_back(solve_adhesive(contact, v, request.tolerance));
    const auto& c = out.collisions.back();
    if (c.outcome == AdhesiveOutcome::bounced &&
        (shortest_contact_s == 0.0 || c.contact_time_s < shortest_contact_s)) {
      shortest_contact_s = c.contact_time_s;
    }
    deepest_m = std::max(deepest_m, c.max_compression_m);
  }
  if (shortest_contact_s == 0.0) {  // every speed sticks: resolve the approach to the first turn
    for (const auto& c : out.collisions) shortest_contact_s = std::max(shortest_contact_s, c.contact_time_s);
  }
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
      fmt::format("neighbor {} bin", out.skin_m),
      "neigh_modify delay 0 every 1 check yes",
      "fix integrate all nve/sphere",
      fmt::format("timestep {}", out.timestep_s),
  };
  return out;
}

}  // namespace restitution::dem
