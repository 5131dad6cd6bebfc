// SPDX-License-Identifier: BSD-3-Clause
#include "scene/section_material.hpp"

#include <fmt/core.h>

#include "scene/toml_reader.hpp"

namespace restitution::scene::detail {

std::string read_section_material(TomlReader& r, const std::map<std::string, Material>& materials,
                                  std::string_view what) {
  const auto material = read_optional_material(r, materials);
  if (!material) r.fail("material", fmt::format("missing: the [materials.X] {}", what));
  return *material;
}

std::optional<std::string> read_optional_material(TomlReader& r,
                                                  const std::map<std::string, Material>& materials) {
  auto name = r.text("material");
  if (name && !materials.contains(*name))
    r.fail("material", fmt::format("no [materials.{}] in this scene", *name));
  return name;
}

bool has_dissipation(const Material& m) {
  return m.dissipative_constant_s.has_value() || m.viscosities.has_value();
}

void require_dissipation(const TomlReader& r, const std::map<std::string, Material>& materials,
                         const std::optional<std::string>& name, std::string_view task) {
  if (name && !has_dissipation(materials.at(*name))) {
    r.fail("material",
           fmt::format("[materials.{}] has neither dissipative_constant nor viscosities, which {} needs "
                       "(only a calibration can do without: it computes them)",
                       *name, task));
  }
}

}  // namespace restitution::scene::detail
