// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The header of a fit CSV: which column holds the speed, eps and sigma, under the names people give them
// (docs/fit.md lists them): case-insensitive, blanks, '-' and '.' read as '_', a unit in brackets or as a
// suffix only where it is m/s for the speed (none, '-' or '1' for eps and sigma), and a leading unnamed index
// column as pandas writes it.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace restitution::fit_detail {

struct HeaderField {
  std::string text;  // as read, unquoted
  int column = 0;    // 1-based byte column of its start in the header line
};

struct FitColumns {
  std::size_t speed = 0;
  std::size_t eps = 0;
  std::optional<std::size_t> sigma;
  std::optional<std::size_t> index;  // ignored
  std::size_t width = 0;             // fields per line
};

// Throws InvalidInput "WHERE:COLUMN: ..." for an unknown name, a speed in another unit than m/s, two columns
// for one quantity or a missing speed or eps column, naming the columns found and the names accepted.
FitColumns fit_columns(const std::vector<HeaderField>& header, const std::string& where);

}  // namespace restitution::fit_detail
