// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Numerical stability of the solver over ζ: for each point and end, the production solve (method auto),
// its self-convergence (relative change when the tolerance is tightened 100×) and its agreement with
// every other engine, with a verdict. Differences are relative to min(ε, 1 - ε), like the accuracy contract.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "analysis/power_law_fit.hpp"
#include "restitution/collision_solver.hpp"

namespace restitution {

// The engines cross-checked against each other; a new engine is one more entry here.
inline constexpr Method kCrossCheckedMethods[] = {Method::bdf, Method::adams};

struct StabilityOptions {
  double tolerance = 1e-9;  // production tolerance T; the self-convergence check uses T/100
  // Work bound of the cross-check solves: Adams on the stiff large-ζ problem runs out of it, which the
  // report records as a finding instead of waiting minutes.
  long max_steps_per_phase = 200000;
  // Called with (zetas done, zetas) after each ζ; may throw to stop the report (the command line does on
  // Ctrl-C). Empty: none.
  std::function<void(std::size_t, std::size_t)> progress;
};

// Why a cross-check engine has no result.
enum class EngineFailure {
  none,
  too_much_work,  // the step bound (max_steps_per_phase) was reached: the problem is stiff for this engine
  other,          // any other numerical failure; EngineCheck::failure_message says which
};

struct EngineCheck {
  Method method = Method::bdf;
  bool solved = false;
  double relative_difference = 0.0;  // against the production result (0 when it is the production method)
  long steps = 0;
  EngineFailure failure = EngineFailure::none;
  std::string failure_message;  // the solver's error message, for EngineFailure::other
};

// A check that exceeded the tolerance: the self-convergence, or the difference of a cross-check engine.
enum class StabilityFlagKind { self_convergence, engine_difference };
struct StabilityFlag {
  StabilityFlagKind kind = StabilityFlagKind::self_convergence;
  Method method = Method::bdf;  // the engine, for engine_difference
  double value = 0.0;           // the relative difference that exceeded the tolerance
};

struct StabilityPoint {
  double zeta = 0.0;
  CollisionEnd end = CollisionEnd::naive;
  Method method = Method::bdf;  // the method `auto` chose
  EndResult result;
  long steps = 0;
  long rhs_evaluations = 0;
  double self_convergence = 0.0;  // |Δ min(ε, 1-ε)| / min(ε, 1-ε) between T and T/100
  std::vector<EngineCheck> engines;
  std::vector<StabilityFlag> flags;  // empty: every check within the tolerance
};

struct DecadeSummary {
  double decade = 0.0;  // 10^k for ζ in [10^k, 10^{k+1}); 0 for ζ = 0
  CollisionEnd end = CollisionEnd::naive;
  double worst_self_convergence = 0.0;
  double worst_engine_difference = 0.0;  // over the engines that produced a result
  int engine_failures = 0;
};

struct StabilityReport {
  double tolerance = 0.0;
  std::vector<StabilityPoint> points;
  std::vector<DecadeSummary> decades;
  [[nodiscard]] int flagged() const;
};

// The default grid: 0, then 10^-12 ... 10^6, points_per_decade per decade (1, 2 or 3 give 1, 3, 10 / 1, 2,
// 5 / ... chosen log-evenly).
// points_per_decade lies in [1, kMaxStabilityPointsPerDecade]: 100 per decade is about a minute of solves.
inline constexpr int kMaxStabilityPointsPerDecade = 100;
std::vector<double> stability_grid(int points_per_decade);

// Relative difference of the small one of ε and 1 - ε (0 when both are exactly equal, as at ζ = 0).
double relative_difference(const EndResult& value, const EndResult& reference);

// Throws InvalidInput for tolerances outside [100 kMinTolerance, kMaxTolerance] or negative ζ; a production
// solve that fails throws NumericalFailure (a point out of reach), a cross-check failure is recorded.
StabilityReport stability_report(const std::vector<double>& zetas, const StabilityOptions& options);

}  // namespace restitution
