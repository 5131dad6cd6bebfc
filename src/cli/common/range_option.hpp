// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The one range syntax of the command line, FROM:TO:N (`oblique --angle-range`, `sweep --zeta-range`,
// `dem --radius-range`): the two ends and the number of points, read as typed; each option spaces them its
// way.
#include <string>

namespace restitution::cli {

struct RangeText {
  double from = 0.0;
  double to = 0.0;
  long long count = 0;
};

// Reads "FROM:TO:N" given to `option`, N a whole number in [min_count, max_count]; throws InvalidInput
// "OPTION must be FROM:TO:N (WHAT), got 'TEXT': why".
RangeText parse_range(const std::string& text, const std::string& option, const std::string& what,
                      long long min_count, long long max_count);

}  // namespace restitution::cli
