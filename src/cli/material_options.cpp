// SPDX-License-Identifier: BSD-3-Clause
#include "cli/material_options.hpp"

#include "restitution/errors.hpp"

namespace restitution::cli {

bool MaterialOptions::any() const {
  return young_modulus || poisson_ratio || radius || radius2 || density || mass || mass2;
}

void add_material_options(CLI::App& command, MaterialOptions& o) {
  command.add_option("--young-modulus", o.young_modulus, "material: Young's modulus Y in Pa");
  command.add_option("--poisson-ratio", o.poisson_ratio, "material: Poisson ratio in (-1, 0.5)");
  command.add_option("--radius", o.radius, "material: sphere radius in m (both spheres unless --radius2)");
  command.add_option("--radius2", o.radius2, "material: radius of the second sphere in m");
  command.add_option("--density", o.density, "material: density in kg/m^3 (gives the masses)");
  command.add_option("--mass", o.mass, "material: sphere mass in kg (instead of --density)");
  command.add_option("--mass2", o.mass2, "material: mass of the second sphere in kg");
}

Material material_from(const MaterialOptions& o) {
  if (!o.young_modulus || !o.poisson_ratio || !o.radius) {
    throw InvalidInput(
        "a material needs --young-modulus, --poisson-ratio and --radius (and --density or --mass)");
  }
  Material m;
  m.young_modulus_pa = *o.young_modulus;
  m.poisson_ratio = *o.poisson_ratio;
  m.radius1_m = *o.radius;
  m.radius2_m = o.radius2.value_or(*o.radius);
  m.density_kg_m3 = o.density;
  if (o.mass) {
    m.mass1_kg = o.mass;
    m.mass2_kg = o.mass2.value_or(*o.mass);
  } else if (o.mass2) {
    throw InvalidInput("--mass2 needs --mass");
  }
  return m;
}

}  // namespace restitution::cli
