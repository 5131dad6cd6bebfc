#pragma once
// Turns the user's accuracy request into CVODE settings: method, relative and absolute tolerances per
// form, time limit. The factors are measured (docs/accuracy.md); tests/test_tolerance_honesty.cpp checks
// that the resulting error stays below the requested tolerance.
#include "core/cvode_integrator.hpp"
#include "restitution/collision_solver.hpp"

namespace restitution::detail {

struct SolvePlan {
  Method method = Method::bdf;
  bool smooth_ends = false;  // phases in the compression form at both ends
  double relative_tolerance = 0.0;
  State absolute_tolerance_time{};         // (x, x', I)
  State absolute_tolerance_compression{};  // (τ, x', I)
  double time_limit = 0.0;                 // law's own τ
  double start_phase_x = 0.0;              // largest x of the compression form of the start
  long max_steps = 0;                      // per phase
};

// Throws InvalidInput for a tolerance outside [kMinTolerance, kMaxTolerance], no end requested, or an end
// that does not exist for this law.
SolvePlan plan_solve(const ContactLaw& law, const SolveOptions& options);

}  // namespace restitution::detail
