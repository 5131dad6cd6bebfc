// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `restitution dem --code lammps|liggghts|yade --friction MU`: the options of the oblique outputs, and what
// the printed lines give oblique impacts (dem/oblique_lines.hpp computes it) as text and JSON.
#include <CLI/CLI.hpp>
#include <vector>

#include "cli/common/json_writer.hpp"
#include "dem/oblique_lines.hpp"

namespace restitution::cli {

using DemObliqueOptions = dem::ObliqueLinesRequest;
using DemOblique = dem::ObliqueLines;

void add_dem_oblique_options(CLI::App& command, DemObliqueOptions& o);

// The impacts whose tolerance cannot be shown (ill-conditioned), each a warning on stderr: never silently.
void warn_oblique(const DemOblique& r);
void print_oblique_text(const DemOblique& r, const char* comment);
// "oblique": {...}
void write_oblique_json(JsonWriter& json, const DemOblique& r);

}  // namespace restitution::cli
