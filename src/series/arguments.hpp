// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Argument checks shared by the series evaluators.
#include <fmt/core.h>

#include <cmath>

#include "restitution/errors.hpp"

namespace restitution::series::detail {

// {} prints the shortest form that reads back (-1, not std::to_string's -1.000000), as every other message.
inline void check_zeta(double zeta) {
  if (!std::isfinite(zeta) || zeta < 0.0)
    throw InvalidInput(fmt::format("zeta must be finite and >= 0, got {}", zeta));
}

}  // namespace restitution::series::detail
