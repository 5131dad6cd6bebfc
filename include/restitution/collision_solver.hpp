// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The collision solver: shoots the equation of motion of a ContactLaw with the engine of the requested
// method (CVODE BDF/Adams or the Taylor method) and detects the end(s) of the collision. One solver holds
// its engines' integrators and reuses them across solves; use one solver per thread.
#include <memory>
#include <string>
#include <vector>

#include "restitution/contact_law.hpp"
#include "restitution/solve_types.hpp"

namespace restitution {

// The smallest tolerance the method accepts (kMinTolerance for CVODE, kMinTaylorTolerance for taylor).
double min_tolerance(Method method);
// The tolerances each engine accepts, one entry per engine of the registry: "[1e-11, 1e-2] for bdf, adams,
// auto", "[1e-13, 1e-2] for taylor". With name_engines, an engine that computes several methods is named
// after them ("... auto (CVODE)"). For --help and messages, so that a new engine appears in both.
std::vector<std::string> tolerance_ranges(bool name_engines = false);

// Throws InvalidInput naming the tolerance or the ends when the options cannot be honoured for any law.
void check_solve_options(const SolveOptions& options);
// Throws InvalidInput for everything CollisionSolver::solve would refuse for this law and these options
// (the checks above, an end that does not exist, an engine's limits) without integrating: callers with
// many points check them all before computing any.
void check_solvable(const ContactLaw& law, const SolveOptions& options);

class CollisionSolver {
 public:
  CollisionSolver();
  ~CollisionSolver();
  CollisionSolver(CollisionSolver&& other) noexcept;
  CollisionSolver& operator=(CollisionSolver&& other) noexcept;
  CollisionSolver(const CollisionSolver&) = delete;
  CollisionSolver& operator=(const CollisionSolver&) = delete;

  // Throws InvalidInput for options out of range or an end that does not exist (the naive end of an
  // overdamped dash-pot), NumericalFailure when the integration fails.
  CollisionResult solve(const ContactLaw& law, const SolveOptions& options);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The method `automatic` resolves to for this law (measured: see docs/accuracy.md).
Method resolve_method(const ContactLaw& law, Method requested, EndSet ends = EndSet::both());

}  // namespace restitution
