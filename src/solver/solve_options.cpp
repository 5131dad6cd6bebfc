// SPDX-License-Identifier: BSD-3-Clause
// The options of a solve, checked by the solver against the engine table before an engine sees them.
#include <fmt/core.h>

#include <cmath>
#include <string>

#include "restitution/collision_solver.hpp"
#include "restitution/errors.hpp"
#include "solver/engine_registry.hpp"

namespace restitution {

void check_solve_options(const SolveOptions& options) {
  const double tol = options.tolerance;
  if (!std::isfinite(tol) || tol < kSmallestTolerance || tol > kMaxTolerance) {
    // The per-engine ranges, as --help and docs/cli.md state them: no method accepts kSmallestTolerance.
    throw InvalidInput(
        fmt::format("tolerance must lie in {}, got {}", alternatives(tolerance_ranges(true)), tol));
  }
  const double smallest = min_tolerance(options.method);
  if (tol < smallest) {
    throw InvalidInput(fmt::format(
        "tolerance {:g} is below what the {} engine can deliver ({:g}): double-precision round-off in its "
        "steps limits the accuracy of eps; ask for a tolerance >= {:g}",
        tol, engine_of(options.method).name, smallest, smallest));
  }
  if (options.max_steps_per_phase < 1) {
    throw InvalidInput(fmt::format("max_steps_per_phase must be >= 1, got {}", options.max_steps_per_phase));
  }
  if (!options.ends.contains(CollisionEnd::naive) && !options.ends.contains(CollisionEnd::delayed_recovery)) {
    throw InvalidInput("no end of the collision requested: ask for naive, delayed-recovery or both");
  }
}

}  // namespace restitution
