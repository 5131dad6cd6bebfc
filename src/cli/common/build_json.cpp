// SPDX-License-Identifier: BSD-3-Clause
#include "cli/common/build_json.hpp"

#include "restitution/restitution.hpp"

namespace restitution::cli {

std::string finish_json_document(JsonWriter& json) {
  const LibraryVersion code = library_version();
  json.key("restitution").begin_object().field("version", code.version).field("commit", code.commit);
  json.end_object();
  const SundialsBuild build = sundials_build();
  json.key("sundials").begin_object().field("version", build.version).field("optimized", build.optimized);
  json.end_object();
  json.end_object();
  return json.str();
}

std::string build_description() {
  const LibraryVersion code = library_version();
  return std::string("restitution ") + code.version + " (commit " + code.commit + "), SUNDIALS " +
         sundials_build_description();
}

}  // namespace restitution::cli
