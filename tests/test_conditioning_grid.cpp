// SPDX-License-Identifier: BSD-3-Clause
// The conditioning check at the dash-pot's and Tsuji's critical damping, every engine
// (conditioning_grid.hpp).
#include "conditioning_grid.hpp"

TEST(ConditioningGrid, NaiveEndNearCriticalIsRefusedOrWithinTolerance) {
  restitution::conditioning_grid::expect_refused_or_within_tolerance(1);
}
