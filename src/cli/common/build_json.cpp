// SPDX-License-Identifier: BSD-3-Clause
#include "cli/common/build_json.hpp"

#include "restitution/restitution.hpp"

namespace restitution::cli {

std::string finish_json_document(JsonWriter& json) {
  const SundialsBuild build = sundials_build();
  json.key("sundials").begin_object().field("version", build.version).field("optimized", build.optimized);
  json.end_object();
  json.end_object();
  return json.str();
}

}  // namespace restitution::cli
