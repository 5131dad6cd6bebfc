// SPDX-License-Identifier: BSD-3-Clause
#include "sweep/number_text.hpp"

#include <fmt/format.h>

#include <cmath>

namespace restitution {

std::string number17(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return fmt::format("{:.17g}", value);
}

}  // namespace restitution
