// SPDX-License-Identifier: BSD-3-Clause
#include "scene/scene_inputs.hpp"

#include <fmt/core.h>

#include <system_error>

#include "files/printable_name.hpp"
#include "files/resolved_path.hpp"
#include "scene/toml_reader.hpp"

namespace restitution::scene::detail {
namespace fs = std::filesystem;

fs::path contained_input(TomlReader& r, const std::string& key, const std::string& written) {
  const std::string shown = files::printable_name(written);
  if (written.empty()) r.fail(key, "empty: give the file, relative to the scene file's folder");
  const fs::path name(written);
  if (name.is_absolute() || name.has_root_name() || name.has_root_directory()) {
    r.fail(key,
           fmt::format("\"{}\" is absolute: a scene's {} is a file relative to the scene file, in its folder",
                       shown, key));
  }
  for (const fs::path& part : name) {
    if (part == "..") {
      r.fail(key, fmt::format("\"{}\" climbs out with '..': a scene reads files in its own folder only "
                              "(put the file beside the scene, or in a folder below it)",
                              shown));
    }
  }
  fs::path folder = fs::path(std::string(r.file_name())).parent_path();
  if (folder.empty()) folder = ".";
  fs::path path = files::resolved_path(folder / name);
  if (!files::resolves_within(path, folder)) {
    r.fail(key, fmt::format("\"{}\" is a link that leads outside the scene's folder: a scene reads files in "
                            "its own folder only",
                            shown));
  }
  return path;
}

}  // namespace restitution::scene::detail
