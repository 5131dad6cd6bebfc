// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What parsing a scene's text throws, for the tests that check a refusal's words.
#include <string>

#include "restitution/errors.hpp"
#include "scene/scene.hpp"

namespace restitution::scene_errors {

// The message of the InvalidInput that parsing `text` as `file_name` throws ("" when it parses).
inline std::string scene_error(const std::string& text, const std::string& file_name = "s.toml") {
  try {
    (void)scene::parse_scene(text, file_name);
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "";
}

}  // namespace restitution::scene_errors
