// SPDX-License-Identifier: BSD-3-Clause
#include "dem/adhesive_lines_liggghts.hpp"

#include <fmt/format.h>

#include <utility>

#include "dem/adhesive_lines_common.hpp"
#include "dem/deck_liggghts.hpp"
#include "restitution/errors.hpp"
#include "restitution/units.hpp"

namespace restitution::dem {
namespace {

// sjkr's cohesion and Hertz's force vanish at δ = 0, but the damping gamman·m*·sqrt(Rδ)·δ̇ rises as sqrt(δ)
// at first touch, which LIGGGHTS starts inside a step: the ε error is O(dt). Measured against LIGGGHTS
// (tests/dem/adhesion_liggghts.cpp, strong damping): 8.0e-6 at t_c/2e4, 3.3e-6 at t_c/5e4 (docs/adhesion.md
// §10).
constexpr double kSjkrStepsPerContact = 5e4;

}  // namespace

AdhesiveLiggghtsLines adhesive_liggghts_lines(const AdhesiveLiggghtsRequest& request) {
  const AdhesiveContact& contact = request.contact;
  if (contact.model != AdhesiveModel::sjkr) {
    throw InvalidInput("LIGGGHTS's cohesive pair lines are for --adhesion sjkr (its `cohesion sjkr`)");
  }
  auto solves = solve_listed_speeds(contact, request.speeds, request.tolerance);
  AdhesiveLiggghtsLines out;
  out.sticking = solves.sticking;
  out.speeds = std::move(solves.speeds);
  out.collisions = std::move(solves.collisions);
  out.skin_m = round_up_2(solves.deepest_m);
  out.timestep_s = round_down_2(solves.shortest_contact_s / kSjkrStepsPerContact);
  out.lines = {
      "units si",
      "atom_style granular",
      "newton off",
      "communicate single vel yes",
      liggghts_one_type_line("kn", hertz_modulus_pa(contact.effective_modulus_pa)),
      liggghts_one_type_line("kt", 0.0),
      liggghts_one_type_line("gamman", contact.damping),
      liggghts_one_type_line("gammat", 0.0),
      liggghts_one_type_line("coefficientFriction", 0.0),
      liggghts_one_type_line("cohesionEnergyDensity", contact.cohesion_energy_density_j_per_m3),
      "pair_style gran model hertz/stiffness tangential no_history cohesion sjkr limitForce off",
      "pair_coeff * *",
  };
  for (auto& line : integration_lines(out.skin_m, out.timestep_s)) out.lines.push_back(std::move(line));
  return out;
}

}  // namespace restitution::dem
