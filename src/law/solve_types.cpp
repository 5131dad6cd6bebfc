// SPDX-License-Identifier: BSD-3-Clause
// The vocabulary of a solve (restitution/solve_types.hpp): names of methods and ends, results, statistics.
#include "restitution/solve_types.hpp"

#include <fmt/core.h>

#include <string>
#include <vector>

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

}  // namespace restitution
