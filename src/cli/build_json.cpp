// SPDX-License-Identifier: BSD-3-Clause
#include "cli/build_json.hpp"

#include "restitution/build_info.hpp"

namespace restitution::cli {

void write_sundials_build(JsonWriter& json) {
  const SundialsBuild build = sundials_build();
  json.key("sundials").begin_object().field("version", build.version).field("optimized", build.optimized);
  json.end_object();
}

}  // namespace restitution::cli
