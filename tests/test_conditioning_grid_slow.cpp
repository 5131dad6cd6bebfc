// SPDX-License-Identifier: BSD-3-Clause
// The grid of test_conditioning_grid at ten times its density in the distance to critical damping (label
// slow).
#include "conditioning_grid.hpp"

TEST(ConditioningGrid, DenseNaiveEndNearCriticalIsRefusedOrWithinTolerance) {
  restitution::conditioning_grid::expect_refused_or_within_tolerance(10);
}
