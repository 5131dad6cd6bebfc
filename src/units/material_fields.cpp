// SPDX-License-Identifier: BSD-3-Clause
// A Material from optional fields: the one assembly the scene parser, the command line and Python share.
#include <fmt/core.h>

#include "restitution/errors.hpp"
#include "restitution/material.hpp"

namespace restitution {

std::optional<MaterialFieldProblem> material_fields_problem(const MaterialFields& f) {
  if (!f.young_modulus_pa) return MaterialFieldProblem{"young_modulus", "missing (Pa)"};
  if (!f.poisson_ratio) return MaterialFieldProblem{"poisson_ratio", "missing"};
  if (f.radius_m.has_value() == f.radii_m.has_value())
    return MaterialFieldProblem{"radius", "give radius (both spheres) or radii = [R1, R2]"};
  if (f.mass_kg && f.masses_kg) return MaterialFieldProblem{"mass", "give mass or masses, not both"};
  return std::nullopt;
}

Material material_from_fields(const MaterialFields& f) {
  if (const auto problem = material_fields_problem(f)) {
    throw InvalidInput(fmt::format("material: {}: {}", problem->field, problem->message));
  }
  Material m;
  m.young_modulus_pa = *f.young_modulus_pa;
  m.poisson_ratio = *f.poisson_ratio;
  m.radius1_m = f.radius_m ? *f.radius_m : (*f.radii_m)[0];
  m.radius2_m = f.radius_m ? *f.radius_m : (*f.radii_m)[1];
  m.density_kg_m3 = f.density_kg_m3;
  if (f.mass_kg) m.mass1_kg = m.mass2_kg = *f.mass_kg;
  if (f.masses_kg) {
    m.mass1_kg = (*f.masses_kg)[0];
    m.mass2_kg = (*f.masses_kg)[1];
  }
  m.dissipative_constant_s = f.dissipative_constant_s;
  m.viscosities = f.viscosities;
  return m;
}

void check_material(const Material& material) {
  (void)elastic_constants(material);
  if (material.dissipative_constant_s || material.viscosities) (void)material_constants(material);
}

}  // namespace restitution
