// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `restitution sweep --adhesion MODEL --surface-energy γ` with a material and --velocity-range: ε(v) of an
// adhesive collision (docs/adhesion.md) into a CSV file, one row per impact speed, stuck rows saying so.
#include <string>

#include "cli/sweep/sweep_grid.hpp"
#include "restitution/adhesion.hpp"

namespace restitution::cli {

// The table's header line and one row (17 significant digits), shared with a scene's [[adhesion]] section.
std::string adhesive_table_header();
std::string adhesive_table_row(double speed_m_per_s, const AdhesiveCollision& c,
                               double sticking_speed_m_per_s);

// o after with_ranges. The rows are solved on one thread and written whole at the end (an adhesive solve
// takes ~0.1 ms: 10^4 speeds in about a second), so --resume and --threads are refused, as are the ζ and β
// forms. Throws InvalidInput naming what does not go with --adhesion or is missing.
int run_adhesive_sweep(const SweepOptions& o);

}  // namespace restitution::cli
