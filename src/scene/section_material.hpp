// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The `material` key of a section whose spheres are one of the scene's [[materials.X]], and the check that
// such a material carries the damping a section computes with.
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "restitution/material.hpp"

namespace restitution::scene::detail {

class TomlReader;

// The name the key gives; fails through `r` naming the key when it is missing ("missing: the [materials.X]
// " + `what`) or names no material of the scene.
std::string read_section_material(TomlReader& r, const std::map<std::string, Material>& materials,
                                  std::string_view what);

// The name the key gives, if any; fails through `r` when it names no material of the scene.
std::optional<std::string> read_optional_material(TomlReader& r,
                                                  const std::map<std::string, Material>& materials);

bool has_dissipation(const Material& m);

// For the tasks that compute with the material's damping (not calibrations, which compute it): fails
// through `r` naming `task` when the material `name` has neither A nor viscosities.
void require_dissipation(const TomlReader& r, const std::map<std::string, Material>& materials,
                         const std::optional<std::string>& name, std::string_view task);

}  // namespace restitution::scene::detail
