// SPDX-License-Identifier: BSD-3-Clause
#include "cli/common/range_option.hpp"

#include <fmt/core.h>

#include <cmath>
#include <cstdlib>

#include "cli/common/parse_errors.hpp"
#include "restitution/errors.hpp"

namespace restitution::cli {

RangeText parse_range(const std::string& text, const std::string& option, const std::string& what,
                      long long min_count, long long max_count) {
  const auto fail = [&](const std::string& why) {
    return InvalidInput(fmt::format("{} must be FROM:TO:N ({}), got '{}': {}", option, what, text, why));
  };
  const std::size_t first = text.find(':');
  const std::size_t second = first == std::string::npos ? first : text.find(':', first + 1);
  if (second == std::string::npos) throw fail("two colons expected");
  const auto number = [&](std::size_t begin, std::size_t end) {
    const std::string part = text.substr(begin, end - begin);
    char* stop = nullptr;
    const double value = std::strtod(part.c_str(), &stop);
    if (part.empty() || *stop != '\0') throw fail("not a number");
    if (const std::string problem = number_problem(part); !problem.empty()) throw fail(problem);
    if (!std::isfinite(value)) throw fail("not a finite number");
    return value;
  };
  RangeText range;
  range.from = number(0, first);
  range.to = number(first + 1, second);
  const double count = number(second + 1, text.size());
  if (!(count >= static_cast<double>(min_count) && count <= static_cast<double>(max_count) &&
        count == std::floor(count))) {
    throw fail(fmt::format("N must be a whole number in [{}, {}]", min_count, max_count));
  }
  range.count = static_cast<long long>(count);
  return range;
}

}  // namespace restitution::cli
