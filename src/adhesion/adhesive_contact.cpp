// SPDX-License-Identifier: BSD-3-Clause
#include "restitution/adhesive_contact.hpp"

#include <fmt/format.h>

#include <cmath>

#include "restitution/errors.hpp"
#include "restitution/units.hpp"

namespace restitution {

AdhesiveContact adhesive_contact_of(AdhesiveModel model, const Material& material,
                                    double surface_energy_j_per_m2, double dissipative_constant_s) {
  const double a = dissipative_constant_s;
  if (!(a >= 0.0) || !std::isfinite(a)) {
    throw InvalidInput(fmt::format("the dissipative constant A must be finite and not negative (got {})", a));
  }
  const ElasticConstants elastic = elastic_constants(material);
  AdhesiveContact contact;
  contact.model = model;
  contact.effective_modulus_pa = effective_modulus_pa(material.young_modulus_pa, material.poisson_ratio);
  contact.effective_radius_m = elastic.effective_radius_m;
  contact.effective_mass_kg = elastic.effective_mass_kg;
  contact.surface_energy_j_per_m2 = surface_energy_j_per_m2;
  // sjkr's lens needs both radii when they differ (equal spheres: 0, 0, the radius 2R).
  if (model == AdhesiveModel::sjkr && material.radius1_m != material.radius2_m) {
    contact.sphere_radius_1_m = material.radius1_m;
    contact.sphere_radius_2_m = material.radius2_m;
  }
  contact.damping = model == AdhesiveModel::jkr
                        ? a
                        : damping_per_mass(a, contact.effective_modulus_pa, contact.effective_mass_kg);
  return contact;
}

}  // namespace restitution
