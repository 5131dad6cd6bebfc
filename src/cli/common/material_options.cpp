// SPDX-License-Identifier: BSD-3-Clause
#include "cli/common/material_options.hpp"

#include <array>

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
  if (o.mass2 && !o.mass) throw InvalidInput("--mass2 needs --mass");
  MaterialFields f;
  f.young_modulus_pa = o.young_modulus;
  f.poisson_ratio = o.poisson_ratio;
  if (o.radius2) {
    f.radii_m = std::array<double, 2>{*o.radius, *o.radius2};
  } else {
    f.radius_m = o.radius;
  }
  f.density_kg_m3 = o.density;
  if (o.mass2) {
    f.masses_kg = std::array<double, 2>{*o.mass, *o.mass2};
  } else {
    f.mass_kg = o.mass;
  }
  return material_from_fields(f);
}

}  // namespace restitution::cli
