// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Turns the user's accuracy request into CVODE settings: method, relative and absolute tolerances per
// form, time limit. The factors are measured (docs/accuracy.md); tests/test_tolerance_honesty.cpp checks
// that the resulting error stays below the requested tolerance.
#include <optional>

#include "cvode/cvode_engine.hpp"
#include "cvode/cvode_integrator.hpp"
#include "engine/solve_request.hpp"
#include "restitution/solve_types.hpp"

namespace restitution::detail {

struct SolvePlan {
  Method method = Method::bdf;
  // Takes over from `method` at the delayed-recovery end while the naive end is pending.
  std::optional<Method> tail_method;
  bool smooth_ends = false;  // phases in the compression form at both ends
  // One phase in the Sundman form from the impact to the delayed-recovery end (cvode_integrator.hpp).
  bool single_phase = false;
  // The logarithm the end phase takes out of τ (the overdamped tail of the naive end); none by default.
  TauLog tail;
  double relative_tolerance = 0.0;          // of the phases in τ and u
  double relative_tolerance_sundman = 0.0;  // of the single Sundman phase
  State absolute_tolerance_time{};          // (x, x', I)
  State absolute_tolerance_compression{};   // (τ, x', I)
  State absolute_tolerance_sundman{};       // (u, x', I, τ)
  double time_limit = 0.0;                  // law's own τ
  double start_phase_x = 0.0;               // largest x of the compression form of the start
  long max_steps = 0;                       // per phase
};

// The plan of a request CvodeEngine::check has accepted (the request is checked once per solve, there).
// `conditioning` (<= 1) tightens the local tolerances further, for an end found ill-conditioned by a first
// solve (ContactLaw::naive_end_conditioning).
SolvePlan plan_solve(const ContactLaw& law, const SolveOptions& options, double conditioning = 1.0);

// What rounding lets CVODE deliver (check_solve_request). Measured on the naive ends of the dash-pot and
// Tsuji near critical damping against their closed forms (tests/test_conditioning_grid_slow.cpp, 2775 points
// per member and method): an error above T occurs only where T < g κ DBL_EPSILON with g = 89 for BDF (Tsuji,
// ζ = 2.1985, T = 1e-11) and g = 2.1 for Adams (Tsuji, ζ = 2.2354, T = 1e-10); with the gains below the worst
// answer is 0.82 T (BDF) and 0.79 T (Adams). ε below 1e-140 is not resolved: the dissipation integral and the
// elastic energy carry ε², which nears the smallest normal double there (the dash-pot's solve misses the end
// from ε ~ 1e-152 on).
inline constexpr double kBdfRoundingGain = 150.0;
inline constexpr double kAdamsRoundingGain = 10.0;
inline constexpr double kCvodeSmallestEps = 1e-140;
// For the method `options` resolves to for this law (a BDF phase takes BDF's gain).
inline EngineRounding cvode_rounding(const ContactLaw& law, const SolveOptions& options) {
  const bool bdf = resolve_method(law, options.method, options.ends) == Method::bdf;
  return {method_name(options.method), bdf ? kBdfRoundingGain : kAdamsRoundingGain, kCvodeSmallestEps,
          "eps squared, carried by the energy balance, nears the smallest normal double"};
}

// Below this relative tolerance CVODE's steps drown in double rounding: a conditioning that asks for less
// cannot be delivered.
inline constexpr double kSmallestRelativeTolerance = 4e-15;

}  // namespace restitution::detail
