// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The CSV of measured coefficients of restitution that `fit-data` and scenes' [[fit]] read (docs/fit.md):
// a header naming the columns v, eps and optionally sigma (any order), then one measurement per line;
// lines starting with '#' and blank lines are skipped.
#include <filesystem>
#include <string>

#include "restitution/fit.hpp"

namespace restitution {

// Throws InvalidInput naming the file, the line and the column of the first bad field (not a number, NaN,
// v <= 0, eps outside (0, 1), sigma <= 0, a missing or extra field), an unknown or repeated column name, a
// file that cannot be read or has no measurements.
FitData read_fit_csv(const std::filesystem::path& path);
// The same for text already in memory; `name` is the file name the messages give.
FitData parse_fit_csv(const std::string& text, const std::string& name);

}  // namespace restitution
