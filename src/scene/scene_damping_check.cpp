// SPDX-License-Identifier: BSD-3-Clause
#include "scene/scene_damping_check.hpp"

#include "damping_check/check.hpp"
#include "restitution/errors.hpp"
#include "scene/parameter_keys.hpp"
#include "scene/section_keys.hpp"
#include "scene/toml_reader.hpp"

namespace restitution::scene {

damping_check::GridResult run_damping_check(const DampingCheckTask& task, double tolerance,
                                            CollisionSolver& solver) {
  damping_check::GridRequest request;
  for (const std::string& name : task.recipes)
    request.recipes.push_back(damping_check::recipe_from_name(name));
  request.eps = task.eps;
  request.reference_velocity_m_s = task.inputs.velocity_m_s;
  request.speeds_m_s = task.speeds;
  request.tolerance = tolerance;
  return damping_check::check_grid(request, solver);
}

namespace detail {

DampingCheckTask read_damping_check_task(TomlReader& r, std::string name) {
  using damping_check::damping_check_field;
  DampingCheckTask d;
  d.line = r.line();
  d.name = std::move(name);
  d.title = r.text("title").value_or(d.name);
  if (const auto recipes = r.words("recipes")) {
    if (recipes->empty()) r.fail("recipes", "empty: leave the key out for every recipe");
    for (const std::string& recipe : *recipes) {
      try {
        (void)damping_check::recipe_from_name(recipe);
      } catch (const InvalidInput& e) {
        r.fail("recipes", e.what());
      }
    }
    d.recipes = *recipes;
  } else {
    for (damping_check::Recipe recipe : damping_check::kRecipes) d.recipes.emplace_back(recipe_name(recipe));
  }
  d.eps = r.numbers("eps").value_or(damping_check::map_eps_grid());
  if (d.eps.empty()) r.fail("eps", "empty: leave the key out for 0.05 to 0.99");
  const FieldRange& eps = *damping_check_field("eps").range;  // the command's --eps, one at a time
  r.check_each(
      "eps", d.eps, [&](double e) { return eps.contains(e); }, eps.text);
  for (const damping_check::DampingCheckField& f : damping_check::damping_check_fields())
    read_parameter_key(r, f, d.inputs);  // velocity; the rest are the command's or the section's lists
  d.speeds = r.numbers("speeds").value_or(damping_check::speed_grid(0.1, 10.0, 9));
  if (d.speeds.empty()) r.fail("speeds", "empty: leave the key out for 0.1 to 10 m/s");
  check_positive(r, "speeds", d.speeds);
  return d;
}

}  // namespace detail
}  // namespace restitution::scene
