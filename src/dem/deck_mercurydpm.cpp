// SPDX-License-Identifier: BSD-3-Clause
// MercuryDPM's lines: a HertzianBSHPViscoelasticNormalSpecies (C++).
#include "dem/deck_mercurydpm.hpp"

#include <fmt/core.h>

#include <cmath>

#include "dem/deck_notes.hpp"
#include "restitution/units.hpp"

namespace restitution::dem {

void write_mercurydpm(Deck& d, const Pair& p, double a, double /*vn*/, double mu) {
  d.parameters = {
      {"effective_elastic_modulus", p.effective_modulus_pa, "E* = Y / (2 (1 - nu^2)) [Pa]"},
      {"dissipation", a, "the dissipative constant A [s]"},
      {"sliding_friction_coefficient", mu, "Coulomb friction coefficient [1]"},
  };
  if (mu > 0.0) {
    d.lines = {"Species<HertzianBSHPViscoelasticNormalSpecies, SlidingFrictionSpecies> species;",
               fmt::format("species.setEffectiveElasticModulus({});", num(p.effective_modulus_pa)),
               fmt::format("species.setDissipation({});", num(a)),
               fmt::format("species.setSlidingFrictionCoefficient({});", num(mu)),
               "speciesHandler.copyAndAddObject(species);"};
  } else {
    d.lines = {"Species<HertzianBSHPViscoelasticNormalSpecies> species;",
               fmt::format("species.setEffectiveElasticModulus({});", num(p.effective_modulus_pa)),
               fmt::format("species.setDissipation({});", num(a)),
               "speciesHandler.copyAndAddObject(species);"};
  }
  d.notes = {mu > 0.0 ? "SlidingFrictionSpecies: its spring is linear [N/m], not Mindlin's; set "
                        "setSlidingStiffness and setSlidingDissipation for your particle size"
                      : "no friction species: frictionless",
             friction_note(mu), clamp_note(d.code, d.end),
             "A and E* do not depend on size or mass: exact for every pair of this material"};
}

Coefficients read_mercurydpm(const Deck& d, const Pair& other) {
  return {hertz_stiffness(d.parameter("effective_elastic_modulus"), other.effective_radius_m),
          2.0 * d.parameter("dissipation") * d.parameter("effective_elastic_modulus") *
              std::sqrt(other.effective_radius_m)};
}

}  // namespace restitution::dem
