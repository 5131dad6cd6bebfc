// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `restitution dem --wall`: the wall lines of a sphere hitting a flat wall (dem/wall_lines.hpp), as text or
// JSON, and with --deck FILE the wall check deck. docs/dem.md, "Walls".
#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "dem/wall_lines.hpp"

namespace restitution::cli {

struct WallOptions {
  bool wall = false;
  std::optional<double> young_modulus, poisson_ratio;  // the wall's material; none: rigid
};

void add_wall_options(CLI::App& command, WallOptions& o);

// The wall's material from --wall-young-modulus and --wall-poisson-ratio (both or neither: InvalidInput).
std::optional<dem::WallMaterial> wall_material(const WallOptions& o);

// Prints the wall lines (and writes the deck to `deck` when given, complete or not at all).
void print_wall(const dem::WallResult& r, bool json, const std::optional<std::string>& deck);

}  // namespace restitution::cli
