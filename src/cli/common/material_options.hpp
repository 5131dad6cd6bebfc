// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The material options shared by `calibrate` and `dem`: --young-modulus, --poisson-ratio, --radius
// [--radius2],
// --density or --mass [--mass2], as given on the command line.
#include <CLI/CLI.hpp>
#include <optional>

#include "restitution/material.hpp"

namespace restitution::cli {

struct MaterialOptions {
  std::optional<double> young_modulus, poisson_ratio, radius, radius2, density, mass, mass2;
  [[nodiscard]] bool any() const;
};

void add_material_options(CLI::App& command, MaterialOptions& o);
// The material (without dissipation); throws InvalidInput naming what is missing.
Material material_from(const MaterialOptions& o);

// The material options of a study's inputs, whose rows name the one material the same way (young_modulus_pa,
// poisson_ratio, radius_m, density_kg_m3, mass_kg); the second sphere's are given apart, as not every study's
// inputs hold them.
template <typename Inputs>
MaterialOptions material_options_of(const Inputs& in, std::optional<double> radius2_m,
                                    std::optional<double> mass2_kg) {
  return MaterialOptions{.young_modulus = in.young_modulus_pa,
                         .poisson_ratio = in.poisson_ratio,
                         .radius = in.radius_m,
                         .radius2 = radius2_m,
                         .density = in.density_kg_m3,
                         .mass = in.mass_kg,
                         .mass2 = mass2_kg};
}

}  // namespace restitution::cli
