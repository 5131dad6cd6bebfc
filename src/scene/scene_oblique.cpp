// SPDX-License-Identifier: BSD-3-Clause
#include "scene/scene_oblique.hpp"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

#include "restitution/errors.hpp"
#include "restitution_oblique/oblique_parameters.hpp"
#include "restitution_oblique/oblique_study.hpp"
#include "scene/parameter_keys.hpp"
#include "scene/section_material.hpp"
#include "scene/toml_reader.hpp"

namespace restitution::scene::detail {

namespace {

// `impact_velocity`, or its old name `speed` (as --speed was of --impact-velocity), read for one more
// release.
void read_impact_velocity(TomlReader& r, ObliqueTask& t, std::vector<std::string>& warnings) {
  const auto old_speed = r.number("speed");
  const auto speed = r.number("impact_velocity");
  if (old_speed && speed) r.fail("speed", "give impact_velocity alone (speed is its old name)");
  if (old_speed) {
    warnings.push_back(
        fmt::format("[[oblique]] \"{}\": the key speed is deprecated and will be removed in 0.5.0; "
                    "use impact_velocity",
                    t.name));
  }
  t.inputs.speed_m_s = speed.value_or(old_speed.value_or(1.0));
  r.check_each(
      old_speed ? "speed" : "impact_velocity", {t.inputs.speed_m_s},
      [](double v) { return v > 0.0 && std::isfinite(v); }, "a speed > 0 (m/s)");
}

}  // namespace

ObliqueTask read_oblique_task(TomlReader& r, std::string name,
                              const std::map<std::string, Material>& materials,
                              std::vector<std::string>& warnings) {
  ObliqueTask t;
  t.line = r.line();
  t.name = std::move(name);
  t.title = r.text("title").value_or(t.name);
  t.material = read_section_material(r, materials, "whose spheres collide");
  t.models = r.words("model").value_or(std::vector<std::string>{oblique::ObliqueInputs{}.tangential});
  if (t.models.empty()) r.fail("model", "empty: leave the key out for mindlin");
  const std::vector<std::string>& runs = oblique::oblique_tangential_names();
  for (const std::string& model : t.models) {
    if (std::find(runs.begin(), runs.end(), model) == runs.end()) {
      r.fail("model", fmt::format("unknown or not run here: '{}' (choose {})", model, fmt::join(runs, ", ")));
    }
  }
  for (const oblique::ObliqueField& f : oblique::oblique_fields()) {
    if (!read_parameter_key(r, f, t.inputs) && f.number == &oblique::ObliqueInputs::speed_m_s) {
      read_impact_velocity(r, t, warnings);
    }
  }
  t.mindlin_stiffness = r.number("mindlin_stiffness");
  if (t.mindlin_stiffness) {
    r.check_each(
        "mindlin_stiffness", {*t.mindlin_stiffness}, [](double v) { return v > 0.0 && std::isfinite(v); },
        "a value > 0 (N/m^2)");
  }
  const oblique::ObliqueInputs& in = t.inputs;
  if (in.wall_young_modulus_pa.has_value() != in.wall_poisson_ratio.has_value()) {
    r.fail(in.wall_young_modulus_pa ? "wall_poisson_ratio" : "wall_young_modulus",
           "give wall_young_modulus and wall_poisson_ratio together, or neither (a rigid wall)");
  }
  if (in.wall_young_modulus_pa && !in.wall) r.fail("wall_young_modulus", "needs wall = true");
  t.plot = r.flag("plot").value_or(true);
  const Material& m = materials.at(t.material);
  if (!m.dissipative_constant_s && !m.viscosities) {
    r.fail("material",
           fmt::format("[materials.{}] has no dissipation: give it dissipative_constant (0 for an "
                       "elastic contact) or the viscosities",
                       t.material));
  }
  if (t.inputs.wall && (m.radius1_m != m.radius2_m || m.mass1_kg != m.mass2_kg)) {
    r.fail("wall", fmt::format("a wall takes one sphere: [materials.{}] has two", t.material));
  }
  return t;
}

}  // namespace restitution::scene::detail
