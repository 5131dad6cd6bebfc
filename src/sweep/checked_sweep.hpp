// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// run_sweep without its check_sweep, for a caller that ran check_sweep itself before touching anything
// (sweep_to_file: before its files): every point is checked once, not twice.
#include <vector>

#include "restitution/sweep.hpp"

namespace restitution {

// run_sweep for points and options that check_sweep accepted.
SweepSummary run_checked_sweep(const std::vector<double>& zetas, const SolveOptions& options,
                               const SweepControl& control, LawKind law);

}  // namespace restitution
