// SPDX-License-Identifier: BSD-3-Clause
#include "scene/section_material.hpp"

#include <fmt/core.h>

#include "scene/toml_reader.hpp"

namespace restitution::scene::detail {

std::string read_section_material(TomlReader& r, const std::map<std::string, Material>& materials,
                                  std::string_view what) {
  const auto material = r.text("material");
  if (!material) r.fail("material", fmt::format("missing: the [materials.X] {}", what));
  if (!materials.contains(*material))
    r.fail("material", fmt::format("no [materials.{}] in this scene", *material));
  return *material;
}

}  // namespace restitution::scene::detail
