// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The phases of one collision on one CVODE integrator: u = x^{1/q} from the start, τ around maximal
// compression, u again down to x = 0 (docs/design.md §4), or τ throughout for laws smooth in τ; the ends are
// CVODE root events.
#include "cvode/cvode_integrator.hpp"
#include "cvode/tolerance_policy.hpp"
#include "restitution/solve_types.hpp"

namespace restitution::detail {

// Integrates `law` with the tolerances of `plan` on `integrator` and collects the ends `options` asks for;
// `tail` (the integrator of SolvePlan::tail_method, or null) takes over at the delayed-recovery end while the
// naive end is pending; `sundman` (4 components, Adams) runs SolvePlan::single_phase. Throws InvalidInput
// when the naive end turns out not to exist, NumericalFailure when CVODE fails.
CollisionResult run_collision(const ContactLaw& law, const SolveOptions& options, const SolvePlan& plan,
                              CvodeIntegrator& integrator, CvodeIntegrator* tail, CvodeIntegrator* sundman);

}  // namespace restitution::detail
