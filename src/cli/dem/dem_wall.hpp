// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `restitution dem --wall`: the wall lines of a sphere hitting a flat wall (dem/wall_lines.hpp), as text or
// JSON, and with --deck FILE the wall check deck. docs/dem.md, "Walls".
#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cli/dem/dem_oblique.hpp"
#include "dem/wall_lines.hpp"

namespace restitution::cli {

struct WallOptions {
  bool wall = false;
  std::optional<double> young_modulus, poisson_ratio;  // the wall's material; none: rigid
};

// --wall (described by wall_help, the command's meaning of it), --wall-young-modulus, --wall-poisson-ratio:
// one wall in every command, rigid unless given a material.
void add_wall_options(CLI::App& command, WallOptions& o, const std::string& wall_help);

// The wall's material from --wall-young-modulus and --wall-poisson-ratio (both or neither: InvalidInput).
std::optional<dem::WallMaterial> wall_material(const WallOptions& o);

// Prints the wall lines (and writes the deck to `deck` when given, complete or not at all).
// With `oblique`, what the wall lines give oblique impacts (dem/oblique_lines.hpp).
void print_wall(const dem::WallResult& r, bool json, const std::optional<std::string>& deck,
                const std::optional<DemOblique>& oblique = std::nullopt);

}  // namespace restitution::cli
