// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: the scene parser (TOML text -> validated Scene) and the planner. Every input must end in
// a Scene with its plan, or InvalidInput with a non-empty message naming file and line; anything else (a
// crash, another exception, a sanitizer report, a hang) is a finding. Nothing is solved or written.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "restitution/errors.hpp"
#include "scene/scene.hpp"
#include "scene/scene_plan.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 16384) return -1;  // scene files are small
  using namespace restitution;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const scene::Scene parsed = scene::parse_scene(text, "fuzz.toml");
    scene::plan_scene(parsed);
  } catch (const InvalidInput& e) {
    if (std::string(e.what()).rfind("fuzz.toml", 0) != 0) std::abort();  // must name the file
  }
  return 0;
}
