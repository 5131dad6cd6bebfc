// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// One adhesive contact studied over impact speeds (`eps --adhesion`, `sweep --adhesion`): the elastic closed
// forms, each speed's collision and the sticking speed, at one tolerance. Typed values; the front ends write
// the table, the JSON and the CSV.
#include <cstddef>
#include <vector>

#include "restitution/adhesion.hpp"

namespace restitution {

struct AdhesiveStudy {
  double elastic_hysteresis_work_j = 0.0;  // W of the break rule, undamped (0 for dmt and sjkr)
  double break_overlap_m = 0.0;
  std::vector<AdhesiveCollision> collisions;  // parallel to the speeds
  std::size_t stuck = 0;                      // collisions whose spheres stayed bound
  StickingSpeed sticking;
};

// The collisions are solved in the order of `speeds_m_s`, before the sticking speed. Throws as solve_adhesive
// and sticking_speed do.
AdhesiveStudy study_adhesive_contact(const AdhesiveContact& contact, const std::vector<double>& speeds_m_s,
                                     double tolerance);

}  // namespace restitution
