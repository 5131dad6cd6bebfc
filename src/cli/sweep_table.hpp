// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The CSV table of `restitution sweep` and its partial file. The partial file (FILE.partial) holds a line
// naming the sweep's settings, the CSV header, then one line per finished point in completion order,
// prefixed by the point's index; the final file holds the header and the rows in ζ order.
#include <cstddef>
#include <filesystem>
#include <map>
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

// The finished rows of an interrupted sweep, read back from its partial file.
struct PartialSweep {
  std::map<std::size_t, std::string> rows;  // index -> row
  std::size_t failed = 0;
  std::size_t valid_bytes = 0;  // length of the file up to its last complete line
};

// Reads a partial file written for the same settings line and header; throws InvalidInput naming the file
// when it belongs to another sweep or is damaged. An incomplete last line (the program was killed while
// writing it) is ignored. Rows whose index or ζ does not match `zetas` are refused.
PartialSweep read_partial_sweep(const std::filesystem::path& path, const std::string& settings,
                                const std::string& header, const std::vector<double>& zetas);
// The same on the file's text; `path` names the file in messages.
PartialSweep parse_partial_sweep(const std::string& text, const std::filesystem::path& path,
                                 const std::string& settings, const std::string& header,
                                 const std::vector<double>& zetas);

}  // namespace restitution::cli
