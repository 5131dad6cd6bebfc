// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Which code and which SUNDIALS build computed an output: the fields every JSON document of the program
// carries, and the same in words for the reports (docs/release.md).
#include <string>

#include "cli/common/json_writer.hpp"

namespace restitution::cli {

// Ends a command's JSON document: writes "restitution": {"version": "0.4.0.dev252+gf916007b96cf", "commit":
// "f916007b..."} and "sundials": {"version": "6.4.1", "optimized": true} into the outermost object, which
// must be the only one open, closes it and returns the text.
std::string finish_json_document(JsonWriter& json);

// "restitution 0.4.0.dev252+gf916007b96cf (commit f916007b...), SUNDIALS 6.4.1 (optimized, ...)"
std::string build_description();

}  // namespace restitution::cli
