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

}  // namespace restitution::cli
