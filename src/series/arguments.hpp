#pragma once
// Argument checks shared by the series evaluators.
#include <cmath>
#include <string>

#include "restitution/errors.hpp"

namespace restitution::series::detail {

inline void check_zeta(double zeta) {
  if (!std::isfinite(zeta) || zeta < 0.0)
    throw InvalidInput("zeta must be finite and >= 0, got " + std::to_string(zeta));
}

}  // namespace restitution::series::detail
