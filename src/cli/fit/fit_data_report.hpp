// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The report of a fit of measured ε(v) (restitution/fit.hpp): one JSON object and the human-readable table,
// shared by `fit-data` and scenes' [[fit]] sections (docs/fit.md lists the keys).
#include <optional>
#include <string>

#include "cli/common/json_writer.hpp"
#include "restitution/fit.hpp"

namespace restitution::cli {

struct FitReportInput {
  std::string source;  // the data file, or "inline"
  const FitData* data = nullptr;
  const FitResult* result = nullptr;
  std::optional<double> k;  // ρ/m_eff of the material, when given
};

// An interval as a JSON [low, high] under `name` (null for a bound at the edge), and as text "[low, high]"
// ("edge" for such a bound).
void write_interval(JsonWriter& json, const char* name, const FitInterval& interval);
std::string interval_text(const FitInterval& interval);
// The residual tests' verdict for a table: "n/a (too few points)" when they could not run, never read as
// "none" (no systematic deviation).
std::string verdict_text(const ResidualTests& tests);

// The fields of the report into an open JSON object.
void write_fit_json(JsonWriter& json, const FitReportInput& in);
// The whole report as one JSON object (one line).
std::string fit_json(const FitReportInput& in);
// The table for a terminal.
std::string fit_table(const FitReportInput& in);

}  // namespace restitution::cli
