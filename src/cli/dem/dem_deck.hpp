// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `restitution dem --deck FILE`: the check deck (dem/check_deck.hpp) for the lines the command prints,
// written complete or not at all.
#include <cstddef>
#include <optional>
#include <string>

#include "cli/dem/dem_oblique.hpp"
#include "dem/check_deck.hpp"
#include "dem/lines_check.hpp"
#include "restitution/material.hpp"

namespace restitution::cli {

// Before any work: InvalidInput (exit 2) for an empty path, a code without a runnable deck or a name the code
// will not run (YADE's must end in .py), IoError (exit
// 3) naming the file when it cannot be written.
void check_deck_target(const std::string& path, dem::Code code);

// Before any work: InvalidInput (exit 2) naming the bound when the deck of `type_count` atom types (every
// pair I <= J) at `speed_count` speeds (0: the default v/10, v, 10 v) would exceed dem::max_deck_collisions.
void check_deck_size(dem::Code code, std::size_t type_count, std::size_t speed_count);

// Writes the deck `request` describes to `path` (complete or not at all) and returns the command that runs
// it. A set of several atom types fills `request` itself: type_count and one CheckPair per type pair I <= J.
std::string write_check_deck(const std::string& path, const dem::CheckDeckRequest& request);
// The one-pair deck: `r`'s lines on `material`'s pair (type 1 for both spheres) at `r`'s speeds against `r`'s
// ε.
// With `oblique`, the deck also collides the pair at its angles (dem/oblique_check_deck.hpp).
std::string write_check_deck(const std::string& path, const dem::LinesResult& r, const Material& material,
                             const std::optional<DemOblique>& oblique = std::nullopt);

}  // namespace restitution::cli
