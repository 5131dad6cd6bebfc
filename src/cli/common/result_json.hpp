// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The JSON form of a CollisionResult (the `restitution eps --json` contract), reusable by other commands.
#include "cli/common/json_writer.hpp"
#include "restitution/collision_solver.hpp"

#include <string>

namespace restitution::cli {

// The JSON key of a law's labelled parameter: "zeta" | "damping_ratio" (law_parameter's name, '_' for '-').
std::string parameter_key(LawKind law);

// Writes the members of the eps contract into the currently open object:
// zeta|damping_ratio, law, tolerance, method, max_compression, naive, delayed_recovery, stats.
void write_collision_fields(JsonWriter& json, const CollisionResult& result);

}  // namespace restitution::cli
