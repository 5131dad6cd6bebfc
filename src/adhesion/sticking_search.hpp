// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The sticking speed search behind restitution::sticking_speed, which also says when there is none: above a
// critical damping the spheres stick at every impact speed (ε(v) = 0 for all v), the damping taking all the
// energy. Private to the library.
#include <optional>

#include "restitution/adhesion.hpp"

namespace restitution::adhesion {

// The upward bracket stops here, in the model's speed unit (½V² = 5e11 adhesion energy units): a collision
// stuck at this speed and at every one tried below it means no sticking speed (docs/adhesion.md §5).
inline constexpr double kLargestScaledSpeed = 1e6;

struct StickingSearch {
  std::optional<double> speed_m_per_s;  // nullopt: stuck at every speed tried, up to largest_tried
  double largest_tried_m_per_s = 0.0;
  int solves = 0;
};

// Throws InvalidInput for a bad contact or tolerance (outside [1e-12, 1e-2]), NumericalFailure when a solve
// fails.
[[nodiscard]] StickingSearch search_sticking_speed(const AdhesiveContact& contact, double tolerance);

}  // namespace restitution::adhesion
