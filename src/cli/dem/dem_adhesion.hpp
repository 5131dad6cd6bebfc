// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `restitution dem --code lammps --adhesion jkr|dmt --surface-energy γ`: LAMMPS 20220106's lines for an
// adhesive pair and the ε and sticking speed they give (dem/adhesive_lines_lammps.hpp), as text or JSON;
// `dem --code liggghts --adhesion sjkr --cohesion-energy-density k_c`: LIGGGHTS 3.8.0's
// (dem/adhesive_lines_liggghts.hpp).
#include <optional>
#include <string>

#include "cli/common/adhesion_options.hpp"
#include "dem/dem_parameters.hpp"
#include "restitution/material.hpp"

namespace restitution::cli {

struct AdhesiveDemRequest {
  AdhesionOptions adhesion;  // --adhesion jkr (LAMMPS's, our jkr-lammps), dmt or sjkr (LIGGGHTS's)
  Material material;
  dem::DemInputs inputs;  // A (none: 0), the impact speeds and the accuracy; the adhesive lines take no eps
  bool json = false;
  // --deck FILE: the check deck (dem/adhesive_check_deck.hpp), for one radius and --density.
  std::optional<std::string> deck;
};

int run_adhesive_dem(const AdhesiveDemRequest& request);

}  // namespace restitution::cli
