// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The accuracy contract's measure of a difference in ε: relative to min(ε*, 1 - ε*), so that it reads ε where
// ε is small and 1 - ε where ε is near 1. One home for the formula the scene checks, the DEM lines and their
// check report; the arithmetic order is fixed (difference first, then one division) so their outputs do not
// move.
#include <algorithm>
#include <cmath>

namespace restitution::analysis {

// (value - exact) / min(exact, 1 - exact), with its sign: positive when value is above exact.
inline double contract_difference(double value, double exact) {
  return (value - exact) / std::min(exact, 1.0 - exact);
}

// |value - exact| / min(exact, 1 - exact).
inline double contract_error(double value, double exact) {
  return std::abs(value - exact) / std::min(exact, 1.0 - exact);
}

}  // namespace restitution::analysis
