// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The adhesive collision integrated in its Sundman form (docs/adhesion.md §4) on the event driver
// (src/cvode/event_driver.hpp), from first touch to the break or to the point where the spheres are certainly
// bound. Private to the library.
#include "adhesion/adhesive_scales.hpp"
#include "restitution/solve_types.hpp"

namespace restitution::adhesion {

struct ScaledEnd {
  AdhesiveOutcome outcome = AdhesiveOutcome::bounced;
  double velocity = 0.0;      // dδ/dt at the end (negative when bounced)
  double position = 0.0;      // s (JKR) or u (DMT) at the end
  double time = 0.0;          // contact time
  double viscous_work = 0.0;  // work of the damping force
  double max_position = 0.0;  // s or u at maximal compression
  // Energy left at the end above the break's: ½p² + U − U_b; ≥ 0 when bounced, < 0 when stuck (continuous
  // in the impact speed through the sticking speed, where it vanishes).
  double energy_margin = 0.0;
  SolverStats stats;
};

// Integrates from δ = 0, dδ/dt = V (scaled) to relative tolerance T. Throws NumericalFailure on a CVODE
// failure or when neither end is reached within the step limit.
[[nodiscard]] ScaledEnd integrate_adhesive(const ScaledAdhesion& scaled, double impact_speed,
                                           double tolerance);

}  // namespace restitution::adhesion
