// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The CSV table of a sweep written to a file (sweep_to_file, `restitution sweep`): the header and the rows
// in ζ order. (Its partial file, which holds the same rows as they finish: sweep_partial.hpp.)
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "restitution/collision_solver.hpp"
#include "restitution/sweep.hpp"
#include "restitution/units.hpp"

namespace restitution {

// The CSV columns for the requested ends: zeta, (for a velocity axis: velocity_m_s, beta), per end eps,
// one_minus_eps, tau, x, then the maximal compression's tau and x, (for a material: duration_s per end,
// max_compression_time_s, max_compression_m), steps, status ("ok" | "failed") and error.
std::string sweep_header(EndSet ends, const SweepColumns* velocity = nullptr);
// One CSV row (no newline); a failed point has empty numbers, status "failed" and the quoted message.
std::string sweep_row(const SweepPoint& point, EndSet ends, const SweepColumns* velocity = nullptr);

}  // namespace restitution
