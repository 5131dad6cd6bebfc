// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The file-writing parts of `restitution series`: the validation report and the certified coefficients.
#include <string>
#include <vector>

namespace restitution::cli {

// Writes series_validation.csv, series_validation.json and the figure series_validation.png (through
// scripts/plots/series_validation.py; .pdf, .svg as `formats` asks) into the folder, prints a summary.
// Returns the exit status.
int run_series_validation(const std::string& folder, const std::vector<std::string>& formats);

// Prints (or writes to `file` atomically) the CSV of certified coefficients up to ζ^order and the check of
// every published digit. Returns the exit status.
int run_series_certify(int order, const std::string& file);

}  // namespace restitution::cli
