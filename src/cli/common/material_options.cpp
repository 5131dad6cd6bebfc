// SPDX-License-Identifier: BSD-3-Clause
#include "cli/common/material_options.hpp"

#include <array>
#include <utility>

#include "cli/common/parameter_options.hpp"
#include "restitution/parameter_rows.hpp"

#include "restitution/errors.hpp"

namespace restitution::cli {

bool MaterialOptions::any() const {
  return young_modulus || poisson_ratio || radius || radius2 || density || mass || mass2;
}

void add_material_options(CLI::App& command, MaterialOptions& o) {
  using M = MaterialOptions;
  for (const auto& [name, member] :
       {std::pair{"young_modulus", &M::young_modulus}, std::pair{"poisson_ratio", &M::poisson_ratio},
        std::pair{"radius", &M::radius}, std::pair{"radius2", &M::radius2}, std::pair{"density", &M::density},
        std::pair{"mass", &M::mass}, std::pair{"mass2", &M::mass2}}) {
    add_parameter_option(command, material_field(name, member), o);
  }
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
