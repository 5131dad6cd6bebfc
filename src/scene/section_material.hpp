// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The `material` key of a section whose spheres are one of the scene's [[materials.X]] ([[oblique]],
// [[adhesion]]).
#include <map>
#include <string>
#include <string_view>

#include "restitution/material.hpp"

namespace restitution::scene::detail {

class TomlReader;

// The name the key gives; fails through `r` naming the key when it is missing ("missing: the [materials.X]
// " + `what`) or names no material of the scene.
std::string read_section_material(TomlReader& r, const std::map<std::string, Material>& materials,
                                  std::string_view what);

}  // namespace restitution::scene::detail
