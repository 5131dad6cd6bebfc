// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The "sundials" field every JSON document of the program carries: which SUNDIALS build computed it.
#include "cli/json_writer.hpp"

namespace restitution::cli {

// Writes "sundials": {"version": "6.4.1", "optimized": true} into the innermost open object.
void write_sundials_build(JsonWriter& json);

}  // namespace restitution::cli
