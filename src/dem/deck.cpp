// SPDX-License-Identifier: BSD-3-Clause
// What every code's deck shares; each code's writer and reader are in deck_<code>.cpp, behind the table
// (dem/dem_codes.hpp).
#include "dem/deck.hpp"

#include <fmt/core.h>

#include <cmath>
#include <stdexcept>

#include "restitution/errors.hpp"
#include "restitution/units.hpp"

namespace restitution::dem {

Pair pair_of(const Material& material) {
  const ElasticConstants e = elastic_constants(material);
  Pair p;
  p.young_modulus_pa = material.young_modulus_pa;
  p.poisson_ratio = material.poisson_ratio;
  p.radius1_m = material.radius1_m;
  p.radius2_m = material.radius2_m;
  // elastic_constants validated the masses; recover them from m_eff's inputs.
  if (material.mass1_kg) {
    p.mass1_kg = *material.mass1_kg;
    p.mass2_kg = *material.mass2_kg;
  } else {
    p.mass1_kg = sphere_mass_kg(material.radius1_m, *material.density_kg_m3);
    p.mass2_kg = sphere_mass_kg(material.radius2_m, *material.density_kg_m3);
  }
  p.effective_modulus_pa = effective_modulus_pa(material.young_modulus_pa, material.poisson_ratio);
  p.effective_radius_m = e.effective_radius_m;
  p.effective_mass_kg = e.effective_mass_kg;
  return p;
}

Pair scaled(const Pair& pair, double factor) {
  Pair p = pair;
  const double cube = factor * factor * factor;
  p.radius1_m *= factor;
  p.radius2_m *= factor;
  p.effective_radius_m *= factor;
  p.mass1_kg *= cube;
  p.mass2_kg *= cube;
  p.effective_mass_kg *= cube;
  return p;
}

double Deck::parameter(std::string_view name) const {
  for (const Parameter& p : parameters) {
    if (p.name == name) return p.value;
  }
  throw std::out_of_range(fmt::format("deck has no parameter {}", std::string(name)));
}

void check_friction(double mu) {
  if (!std::isfinite(mu) || mu < 0.0) {
    throw InvalidInput(
        fmt::format("friction (--friction, the Coulomb mu) must be finite and >= 0, got {}", mu));
  }
}

Deck make_deck(Code code, CollisionEnd end, const Pair& pair, double dissipative_constant_s,
               double reference_velocity_m_s, double friction) {
  check_friction(friction);
  if (always_clamps(code) && end == CollisionEnd::naive) {
    throw InvalidInput(
        fmt::format("{} always clamps the normal force at zero, so it ends collisions at the "
                    "delayed-recovery end; --end naive cannot be expressed",
                    code_name(code)));
  }
  if (!std::isfinite(dissipative_constant_s) || dissipative_constant_s < 0.0) {
    throw InvalidInput(
        fmt::format("dissipative_constant must be finite and >= 0, got {}", dissipative_constant_s));
  }
  Deck d;
  d.code = code;
  d.end = end;
  code_entry(code).write(d, pair, dissipative_constant_s, reference_velocity_m_s, friction);
  return d;
}

double deck_beta(const Deck& deck, const Pair& other) {
  const Coefficients c = code_entry(deck.code).read(deck, other);
  return beta_of_coefficients(c.elastic, c.damping, other.effective_mass_kg);
}

}  // namespace restitution::dem
