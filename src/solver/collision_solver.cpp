// SPDX-License-Identifier: BSD-3-Clause
#include "restitution/collision_solver.hpp"

#include <fmt/core.h>

#include <memory>
#include <string>

#include "restitution/errors.hpp"
#include "solver/engine_registry.hpp"

namespace restitution {

struct CollisionSolver::Impl {
  Engines engines;
};

CollisionSolver::CollisionSolver() : impl_(std::make_unique<Impl>()) {}
CollisionSolver::~CollisionSolver() = default;
CollisionSolver::CollisionSolver(CollisionSolver&&) noexcept = default;
CollisionSolver& CollisionSolver::operator=(CollisionSolver&&) noexcept = default;

void check_solvable(const ContactLaw& law, const SolveOptions& options) {
  check_solve_options(options);
  Engines engines;  // cheap: no engine allocates anything before its first solve
  engines(options.method).check(law, options);
}

CollisionResult CollisionSolver::solve(const ContactLaw& law, const SolveOptions& options) {
  // Every result is reported in natural units, and a law depends only on its ζ: integrate the natural
  // form, whose magnitudes are of order one, rather than the (β, v) form, whose lengths and velocities
  // (v^{4/5}) under- or overflow the absolute tolerances at extreme speeds (v = 1e-150 m/s).
  // Hand-made laws (ContactLaw::unchecked) are natural and integrated as given.
  const ContactLaw natural = law.is_natural() ? law : law.natural_form();
  check_solve_options(options);  // the engine's check() then checks what depends on the law
  return impl_->engines(options.method).solve(natural, options);
}

}  // namespace restitution
