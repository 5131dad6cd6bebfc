// SPDX-License-Identifier: BSD-3-Clause
#include "cli/common/result_json.hpp"

namespace restitution::cli {
namespace {

void write_end(JsonWriter& json, const char* name, const EndResult& end) {
  json.key(name).begin_object();
  json.field("eps", end.eps)
      .field("one_minus_eps", end.one_minus_eps)
      .field("tau", end.tau)
      .field("x", end.x);
  json.end_object();
}

}  // namespace

std::string parameter_key(LawKind law) {
  std::string key = law_parameter(law).name;
  for (char& c : key) {
    if (c == '-') c = '_';
  }
  return key;
}

void write_collision_fields(JsonWriter& json, const CollisionResult& result) {
  json.field(parameter_key(result.law), result.parameter);
  json.field("law", law_name(result.law));
  json.field("speed_independent", result.speed_independent);
  json.field("tolerance", result.tolerance);
  json.field("method", method_name(result.method));
  json.key("max_compression").begin_object();
  json.field("tau", result.max_compression.tau).field("x", result.max_compression.x);
  json.end_object();
  for (const CollisionEnd end : kCollisionEnds) {
    if (result[end]) write_end(json, end_key(end), *result[end]);
  }
  const SolverStats& s = result.stats;
  json.key("stats").begin_object();
  json.field("steps", s.steps)
      .field("rhs_evaluations", s.rhs_evaluations)
      .field("jacobian_evaluations", s.jacobian_evaluations)
      .field("root_evaluations", s.root_evaluations)
      .field("error_test_failures", s.error_test_failures)
      .field("convergence_failures", s.convergence_failures);
  json.end_object();
}

}  // namespace restitution::cli
