// SPDX-License-Identifier: BSD-3-Clause
#include "scene/scene_oblique.hpp"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "restitution/errors.hpp"
#include "restitution_oblique/oblique_study.hpp"
#include "scene/section_material.hpp"
#include "scene/toml_reader.hpp"

namespace restitution::scene::detail {

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
  const auto friction = r.number("friction");
  if (!friction)
    r.fail("friction", "missing: the Coulomb friction coefficient (0 for a frictionless contact)");
  r.check_each(
      "friction", {*friction}, [](double v) { return v >= 0.0 && std::isfinite(v); }, "a value >= 0");
  t.friction = *friction;
  t.tangential_stiffness = r.number("tangential_stiffness");
  t.mindlin_stiffness = r.number("mindlin_stiffness");
  for (const auto& [key, value, unit] : {std::tuple{"tangential_stiffness", t.tangential_stiffness, "N/m"},
                                         std::tuple{"mindlin_stiffness", t.mindlin_stiffness, "N/m^2"}}) {
    if (value)
      r.check_each(
          key, {*value}, [](double v) { return v > 0.0 && std::isfinite(v); },
          fmt::format("a value > 0 ({})", unit));
  }
  t.tangential_damping = r.number("tangential_damping").value_or(0.0);
  r.check_each(
      "tangential_damping", {t.tangential_damping}, [](double v) { return v >= 0.0; }, "a value >= 0");
  const auto angles = r.numbers("angles");
  if (!angles || angles->empty()) r.fail("angles", "missing: the impact angles from the normal (degrees)");
  r.check_each(
      "angles", *angles, [](double a) { return a >= 0.0 && a < 90.0; }, "angles in [0, 90) degrees");
  t.angles_deg = *angles;
  if (const auto spins = r.numbers("spins")) {
    if (spins->empty()) r.fail("spins", "empty: leave the key out for no initial spin");
    r.check_each(
        "spins", *spins, [](double w) { return std::isfinite(w); }, "finite spins in rad/s");
    t.spins_rad_s = *spins;
  }
  // `speed` is the old name of the key, as --speed was of --impact-velocity: read for one more release.
  const auto old_speed = r.number("speed");
  const auto speed = r.number("impact_velocity");
  if (old_speed && speed) r.fail("speed", "give impact_velocity alone (speed is its old name)");
  if (old_speed) {
    warnings.push_back(
        fmt::format("[[oblique]] \"{}\": the key speed is deprecated and will be removed in 0.5.0; "
                    "use impact_velocity",
                    t.name));
  }
  t.speed_m_s = speed.value_or(old_speed.value_or(1.0));
  r.check_each(
      old_speed ? "speed" : "impact_velocity", {t.speed_m_s},
      [](double v) { return v > 0.0 && std::isfinite(v); }, "a speed > 0 (m/s)");
  t.wall = r.flag("wall").value_or(false);
  t.wall_young_modulus_pa = r.number("wall_young_modulus");
  t.wall_poisson_ratio = r.number("wall_poisson_ratio");
  if (t.wall_young_modulus_pa.has_value() != t.wall_poisson_ratio.has_value()) {
    r.fail(t.wall_young_modulus_pa ? "wall_poisson_ratio" : "wall_young_modulus",
           "give wall_young_modulus and wall_poisson_ratio together, or neither (a rigid wall)");
  }
  if (t.wall_young_modulus_pa && !t.wall) r.fail("wall_young_modulus", "needs wall = true");
  t.fixed_normal = r.flag("fixed_normal").value_or(false);
  t.end = r.text("end").value_or(t.end);
  t.torque_arm = r.text("torque_arm").value_or(t.torque_arm);
  t.tolerance = r.number("tolerance").value_or(t.tolerance);
  r.check_each(
      "tolerance", {t.tolerance},
      [](double v) {
        return v >= oblique::kSmallestObliqueTolerance && v < oblique::kLargestObliqueTolerance;
      },
      fmt::format("a value in [{:g}, {:g}) (the accuracy contract, docs/oblique.md)",
                  oblique::kSmallestObliqueTolerance, oblique::kLargestObliqueTolerance));
  t.plot = r.flag("plot").value_or(true);
  const Material& m = materials.at(t.material);
  if (!m.dissipative_constant_s && !m.viscosities) {
    r.fail("material",
           fmt::format("[materials.{}] has no dissipation: give it dissipative_constant (0 for an "
                       "elastic contact) or the viscosities",
                       t.material));
  }
  if (t.wall && (m.radius1_m != m.radius2_m || m.mass1_kg != m.mass2_kg)) {
    r.fail("wall", fmt::format("a wall takes one sphere: [materials.{}] has two", t.material));
  }
  return t;
}

}  // namespace restitution::scene::detail
