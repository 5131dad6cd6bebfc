// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The "sundials" field every JSON document of the program carries: which SUNDIALS build computed it.
#include <string>

#include "cli/common/json_writer.hpp"

namespace restitution::cli {

// Ends a command's JSON document: writes "sundials": {"version": "6.4.1", "optimized": true} into the
// outermost object, which must be the only one open, closes it and returns the text.
std::string finish_json_document(JsonWriter& json);

}  // namespace restitution::cli
