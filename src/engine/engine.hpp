// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The interface of the engines that integrate one collision: CVODE with BDF or Adams (cvode/cvode_engine.hpp)
// and the double-precision Taylor method (taylor/taylor_engine.hpp). CollisionSolver picks one per Method
// and hands it the law in natural form; what is engine-independent stays in the solver. No engine includes
// another engine's headers (tests/engine_isolation.py checks that), so an engine is added or changed alone.
#include "engine/solve_request.hpp"
#include "restitution/solve_types.hpp"

namespace restitution {

class Engine {
 public:
  Engine() = default;
  virtual ~Engine() = default;
  // Engines own integrator memory (CVODE) that is reused across solves and never shared.
  Engine(const Engine&) = delete;
  Engine& operator=(const Engine&) = delete;
  Engine(Engine&&) = delete;
  Engine& operator=(Engine&&) = delete;

  // Throws InvalidInput for every request this engine refuses for this law (options out of its range, an
  // end that does not exist or that it does not compute), without integrating.
  virtual void check(const ContactLaw& law, const SolveOptions& options) const = 0;
  // Solves one collision of `law` for `options`, checks included: InvalidInput for a refused request,
  // NumericalFailure when the integration fails. Results in natural units, whatever form the law has.
  virtual CollisionResult solve(const ContactLaw& law, const SolveOptions& options) = 0;
};

}  // namespace restitution
