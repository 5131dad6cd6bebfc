// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The material options of `restitution dem`: those of `calibrate` (one pair of spheres), where --radius,
// --density, --young-modulus and --poisson-ratio also take comma-separated lists (one atom type per radius),
// and a size range binned into log-spaced classes (--radius-range RMIN:RMAX:N; until 0.5.0 also the old
// --radius-range RMIN,RMAX --classes N). docs/dem.md.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "cli/common/material_options.hpp"
#include "dem/polydisperse_lines.hpp"

namespace restitution::cli {

struct DemTypeOptions {
  std::string radius, density, young_modulus, poisson_ratio;  // one number or a comma-separated list
  std::optional<double> radius2, mass, mass2;
  std::string radius_range;    // RMIN:RMAX:N [m], or the old RMIN,RMAX
  std::optional<int> classes;  // of the old form
};

void add_dem_type_options(CLI::App& command, DemTypeOptions& o);

// More than one radius, or a size range: the polydisperse output (dem/polydisperse_lines.hpp).
bool several_types(const DemTypeOptions& o);

// One pair of spheres, as `calibrate` reads it. InvalidInput for a list of more than one value.
MaterialOptions one_pair_material(const DemTypeOptions& o);

// The types (and, for a range, its classes) of a polydisperse request; InvalidInput naming the option for a
// list of the wrong length, a bad number, or --radius2/--mass/--mass2 (a type's mass is its density's).
void set_types(const DemTypeOptions& o, dem::PolydisperseRequest& request);

}  // namespace restitution::cli
