// SPDX-License-Identifier: BSD-3-Clause
// One [[gas]] section read: the section's own keys (title, material) around the gas study's table keys.
#include "restitution/contact_law.hpp"
#include "scene/scene_gas.hpp"
#include "scene/section_material.hpp"
#include "scene/toml_reader.hpp"

namespace restitution::scene::detail {

GasTask read_gas_task(TomlReader& r, std::string name, const std::map<std::string, Material>& materials) {
  GasTask g;
  g.line = r.line();
  g.name = std::move(name);
  g.title = r.text("title").value_or(g.name);
  const auto material = read_optional_material(r, materials);
  if (!material) r.fail("material", "missing: the [materials.X] whose spheres make the gas");
  g.material = *material;
  g.own_tolerance = r.has("tolerance");
  read_gas_keys(r, g.inputs);
  if (!g.inputs.eps) {
    require_dissipation(r, materials, g.material, "a gas without eps");
    if (!has_dissipative_constant(law_from_name(g.inputs.law)))
      r.fail("law", "without eps only viscoelastic-hertz takes A");
  }
  return g;
}

}  // namespace restitution::scene::detail
