// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The Taylor-series engine (`--method taylor`): a double-precision Taylor method of adaptive order on the
// smooth formulation of the collision (u = sqrt(x) near x = 0, τ around maximal compression; docs/design.md
// §4). Same results and accuracy contract as the CVODE engine; reached through CollisionSolver::solve with
// Method::taylor, or directly here (it holds no state).
#include "engine/engine.hpp"
#include "restitution/solve_types.hpp"

namespace restitution {

// The tolerance range the Taylor engine accepts (relative accuracy of ε, as for CVODE): measured against
// the reference solutions (docs/accuracy.md).
inline constexpr double kMinTaylorTolerance = 1e-13;

// Largest ζ for which the Taylor engine computes the naive end: beyond it the overdamped naive tail is
// stiff (relaxation rate ζ sqrt(x) against a duration ~ ζ ln ζ), which an explicit method pays for with
// ~ζ^{5/3} steps; CVODE's BDF is the engine there.
inline constexpr double kTaylorNaiveZetaMax = 100.0;

// What rounding lets the Taylor engine deliver (check_solve_request): near the dash-pot's critical damping an
// error above T occurs only where T < 1.4 κ DBL_EPSILON (r = 0.9894, T = 3.2e-13; measured,
// tests/test_conditioning_grid_slow.cpp); with the gain below the worst answer is 0.27 T.
inline constexpr double kTaylorRoundingGain = 4.0;

class TaylorEngine final : public Engine {
 public:
  // Refuses options outside the engine's range: the tolerance, trajectories, laws other than
  // viscoelastic Hertz and the dash-pot, the naive end beyond kTaylorNaiveZetaMax.
  void check(const ContactLaw& law, const SolveOptions& options) const override;
  // Integrates `law` as given: the caller (CollisionSolver) passes the natural form.
  CollisionResult solve(const ContactLaw& law, const SolveOptions& options) override;
};

}  // namespace restitution
