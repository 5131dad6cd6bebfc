// SPDX-License-Identifier: BSD-3-Clause
#include "damping_check/constant_eps_lines.hpp"

#include <fmt/core.h>

#include <stdexcept>

#include "damping_check/inverse.hpp"
#include "dem/deck_eps.hpp"
#include "dem/deck_lammps.hpp"
#include "dem/deck_notes.hpp"
#include "dem/dem_codes.hpp"
#include "restitution/errors.hpp"
#include "restitution/units.hpp"

namespace restitution::damping_check {

ConstantEpsLines constant_eps_lines(const dem::LinesResult& r, const dem::Pair& pair, double tolerance,
                                    CollisionSolver& solver) {
  if (dem::code_entry(r.deck.code).companion != dem::Companion::damping_tsuji) {
    throw InvalidInput(fmt::format(
        "--constant-eps: only --code {} has its companion line here (damping tsuji)",
        dem::code_list(
            " or ", [](const dem::CodeEntry& e) { return e.companion == dem::Companion::damping_tsuji; })));
  }
  const double k =
      hertz_stiffness(pair.effective_modulus_pa, pair.effective_radius_m) / pair.effective_mass_kg;
  ConstantEpsLines c;
  c.velocity_m_s = r.reference_velocity_m_s;
  c.eps = dem::eps_for(hertz_constants(k, r.dissipative_constant_s).beta, c.velocity_m_s, r.deck.end,
                       tolerance, solver);
  InverseRequest request;
  request.recipe = Recipe::lammps_tsuji;
  request.target_eps = c.eps;
  request.target_velocity_m_s = c.velocity_m_s;
  request.clamp = r.deck.end == CollisionEnd::delayed_recovery ? Clamp::on : Clamp::off;
  request.speeds_m_s = {c.velocity_m_s};
  request.tolerance = tolerance;
  c.eps_to_request = invert_recipe(request, solver).eps_to_request;
  const bool limit = r.deck.end == CollisionEnd::delayed_recovery;
  c.lines = {
      "pair_style granular",
      fmt::format("pair_coeff * * hertz/material {} {} {} tangential {} damping tsuji{}",
                  dem::num(pair.young_modulus_pa), dem::num(c.eps_to_request), dem::num(pair.poisson_ratio),
                  dem::granular_tangential_words(r.deck.granular_tangential.value()),
                  limit ? " limit_damping" : "")};
  return c;
}

}  // namespace restitution::damping_check
