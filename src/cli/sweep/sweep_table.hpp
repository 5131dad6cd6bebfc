// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The CSV table of `restitution sweep`: the header and the rows in ζ order. (Its partial file, which holds
// the same rows as they finish: sweep_partial.hpp.)
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "restitution/collision_solver.hpp"
#include "restitution/sweep.hpp"
#include "restitution/units.hpp"

namespace restitution::cli {

// The impact speeds of an ε(v) sweep: viscoelastic Hertz with β (ζ_i = β v_i^{1/5}) or a material, or any
// member of the family in physical units (ContactLaw::physical). With a material or physical units the
// table also holds SI times and lengths, from the natural scales of each speed.
struct VelocityAxis {
  std::vector<double> velocity_m_s;   // parallel to the sweep's ζ values
  std::optional<double> beta;         // s^{1/5} m^{-1/5}: the column after velocity_m_s, when given
  std::vector<NaturalScales> scales;  // parallel to velocity_m_s, or empty: no SI columns
};

// The CSV columns for the requested ends: zeta, (for a velocity axis: velocity_m_s, beta), per end eps,
// one_minus_eps, tau, x, then the maximal compression's tau and x, (for a material: duration_s per end,
// max_compression_time_s, max_compression_m), steps, status ("ok" | "failed") and error.
std::string sweep_header(EndSet ends, const VelocityAxis* velocity = nullptr);
// One CSV row (no newline); a failed point has empty numbers, status "failed" and the quoted message.
std::string sweep_row(const SweepPoint& point, EndSet ends, const VelocityAxis* velocity = nullptr);

}  // namespace restitution::cli
