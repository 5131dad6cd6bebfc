#pragma once
// Turns the user's accuracy request into CVODE settings: method, relative and absolute tolerances per
// form, time limit. The factors are measured (docs/accuracy.md); tests/test_tolerance_honesty.cpp checks
// that the resulting error stays below the requested tolerance.
#include <optional>

#include "core/cvode_integrator.hpp"
#include "restitution/collision_solver.hpp"

namespace restitution::detail {

struct SolvePlan {
  Method method = Method::bdf;
  // Takes over from `method` at the delayed-recovery end while the naive end is pending.
  std::optional<Method> tail_method;
  bool smooth_ends = false;  // phases in the compression form at both ends
  // The logarithm the end phase takes out of τ (the overdamped tail of the naive end); none by default.
  TauLog tail;
  double relative_tolerance = 0.0;
  State absolute_tolerance_time{};         // (x, x', I)
  State absolute_tolerance_compression{};  // (τ, x', I)
  double time_limit = 0.0;                 // law's own τ
  double start_phase_x = 0.0;              // largest x of the compression form of the start
  long max_steps = 0;                      // per phase
};

// Throws InvalidInput for a tolerance outside [kMinTolerance, kMaxTolerance], no end requested, or an end
// that does not exist for this law. `conditioning` (<= 1) tightens the local tolerances further, for an end
// found ill-conditioned by a first solve (ContactLaw::naive_end_conditioning).
SolvePlan plan_solve(const ContactLaw& law, const SolveOptions& options, double conditioning = 1.0);

// Below this relative tolerance CVODE's steps drown in double rounding: a conditioning that asks for less
// cannot be delivered.
inline constexpr double kSmallestRelativeTolerance = 4e-15;

}  // namespace restitution::detail
