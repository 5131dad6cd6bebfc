// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `restitution sweep --adhesion MODEL --surface-energy γ` with a material and --velocity-range: ε(v) of an
// adhesive collision (docs/adhesion.md) into a CSV file, one row per impact speed, stuck rows saying so.
#include "cli/sweep/sweep_grid.hpp"

namespace restitution::cli {

// o after with_ranges. The rows are solved on one thread and written whole at the end (an adhesive solve
// takes ~0.1 ms: 10^4 speeds in about a second), so --resume and --threads are refused, as are the ζ and β
// forms. Throws InvalidInput naming what does not go with --adhesion or is missing.
int run_adhesive_sweep(const SweepOptions& o);

}  // namespace restitution::cli
