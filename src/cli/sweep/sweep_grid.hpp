// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The options of `restitution sweep` and the grid they describe: ζ values, or impact speeds with β or a
// material (ζ = β v^{1/5}), checked before anything is computed or written.
#include <optional>
#include <string>
#include <vector>

#include "cli/common/adhesion_options.hpp"
#include "cli/common/head_on_options.hpp"
#include "cli/common/options.hpp"
#include "restitution/sweep.hpp"

namespace restitution::cli {

struct SweepOptions {
  HeadOnInputs inputs;  // the law, end, tolerance, method and material (restitution/head_on_parameters.hpp)
  std::string zeta_range;  // FROM:TO:N; the old form is zeta_min, zeta_max and points
  std::optional<double> zeta_min, zeta_max;
  // The ε(v) forms: impact speeds with β, or with a material and its dissipative constant (viscoelastic
  // Hertz), or with the physical coefficients of ContactLaw::physical (every law).
  std::string velocity_range;  // FROM:TO:N in m/s; the old form is velocity_min, velocity_max and points
  std::optional<double> velocity_min, velocity_max, beta, dissipative_constant;
  std::optional<double> stiffness, damping_coefficient, effective_mass;
  AdhesionOptions adhesion;  // ε(v) of an adhesive collision instead (sweep_adhesion.hpp)
  long long points = 0;      // 0: not given
  bool log = false;
  std::optional<long long> threads;  // default: all cores
  std::string out;
  bool resume = false;
};

// What the sweep runs over: the ζ values and, for the ε(v) forms, the impact speeds they come from.
struct SweepGrid {
  LawKind law = LawKind::viscoelastic_hertz;
  std::vector<double> zetas;  // of the law's natural form
  std::optional<SweepColumns> velocity;
};

// The options with --zeta-range or --velocity-range read into the old form's fields (zeta_min, zeta_max or
// velocity_min, velocity_max, and points), which the rest reads (and the settings line of a resumable file
// writes, the same for either form); throws InvalidInput naming the range option.
SweepOptions with_ranges(SweepOptions o);

// The grid of the form the options give (exactly one of the ζ range, beta with velocity-min/max, a material
// with velocity-min/max, the physical coefficients with velocity-min/max); throws InvalidInput naming what
// is missing, mixed or outside the checked range.
SweepGrid sweep_grid(const SweepOptions& o);

}  // namespace restitution::cli
