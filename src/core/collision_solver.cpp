// SPDX-License-Identifier: BSD-3-Clause
#include "restitution/collision_solver.hpp"

#include <fmt/core.h>

#include <memory>
#include <string>

#include "registry/engine_registry.hpp"
#include "restitution/errors.hpp"

namespace restitution {

const char* method_name(Method method) {
  switch (method) {
    case Method::bdf:
      return "bdf";
    case Method::adams:
      return "adams";
    case Method::automatic:
      return "auto";
    case Method::taylor:
      return "taylor";
  }
  return "?";
}

std::string alternatives(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    out += i == 0 ? "" : (i + 1 == names.size() ? " or " : ", ");
    out += names[i];
  }
  return out;
}

const std::vector<std::string>& method_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const Method method : kMethods) out.emplace_back(method_name(method));
    return out;
  }();
  return names;
}

Method method_from_name(const std::string& name) {
  for (const Method method : kMethods) {
    if (name == method_name(method)) return method;
  }
  throw InvalidInput(fmt::format("method must be {}, got '{}'", alternatives(method_names()), name));
}

const char* end_name(CollisionEnd end) {
  return end == CollisionEnd::naive ? "naive" : "delayed-recovery";
}

const std::vector<std::string>& end_names() {
  static const std::vector<std::string> names = {end_name(CollisionEnd::naive),
                                                 end_name(CollisionEnd::delayed_recovery)};
  return names;
}

const std::vector<std::string>& end_set_names() {
  static const std::vector<std::string> names = {end_name(CollisionEnd::naive),
                                                 end_name(CollisionEnd::delayed_recovery), kBothEnds};
  return names;
}

EndSet end_set_from_name(const std::string& name) {
  if (name == kBothEnds) return EndSet::both();
  for (const CollisionEnd end : kCollisionEnds) {
    if (name == end_name(end)) return EndSet{end};
  }
  throw InvalidInput(fmt::format("end must be {}, got '{}'", alternatives(end_set_names()), name));
}

const char* end_key(CollisionEnd end) {
  return end == CollisionEnd::naive ? "naive" : "delayed_recovery";
}

CollisionEnd end_from_name(const std::string& name) {
  for (const CollisionEnd end : kCollisionEnds) {
    if (name == end_name(end)) return end;
  }
  throw InvalidInput(fmt::format("end must be {}, got '{}'", alternatives(end_names()), name));
}

const EndResult& end_of(const CollisionResult& result, CollisionEnd end) {
  const auto& value = result[end];
  if (!value) throw NumericalFailure(fmt::format("no {} end at zeta={}", end_name(end), result.parameter));
  return *value;
}

SolverStats& operator+=(SolverStats& total, const SolverStats& more) {
  total.steps += more.steps;
  total.rhs_evaluations += more.rhs_evaluations;
  total.jacobian_evaluations += more.jacobian_evaluations;
  total.root_evaluations += more.root_evaluations;
  total.error_test_failures += more.error_test_failures;
  total.convergence_failures += more.convergence_failures;
  return total;
}

struct CollisionSolver::Impl {
  Engines engines;
};

CollisionSolver::CollisionSolver() : impl_(std::make_unique<Impl>()) {}
CollisionSolver::~CollisionSolver() = default;
CollisionSolver::CollisionSolver(CollisionSolver&&) noexcept = default;
CollisionSolver& CollisionSolver::operator=(CollisionSolver&&) noexcept = default;

void check_solvable(const ContactLaw& law, const SolveOptions& options) {
  Engines engines;  // cheap: no engine allocates anything before its first solve
  engines(options.method).check(law, options);
}

CollisionResult CollisionSolver::solve(const ContactLaw& law, const SolveOptions& options) {
  // Every result is reported in natural units, and a law depends only on its ζ: integrate the natural
  // form, whose magnitudes are of order one, rather than the (β, v) form, whose lengths and velocities
  // (v^{4/5}) under- or overflow the absolute tolerances at extreme speeds (v = 1e-150 m/s).
  // Hand-made laws (ContactLaw::unchecked) are natural and integrated as given.
  const ContactLaw natural = law.is_natural() ? law : law.natural_form();
  return impl_->engines(options.method).solve(natural, options);
}

}  // namespace restitution
