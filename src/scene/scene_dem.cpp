// SPDX-License-Identifier: BSD-3-Clause
#include "scene/scene_dem.hpp"

#include <string_view>

#include "damping_check/yade_version_lines.hpp"
#include "dem/code_runner.hpp"
#include "dem/deck.hpp"
#include "restitution/errors.hpp"
#include "scene/scene.hpp"
#include "scene/section_keys.hpp"
#include "scene/section_material.hpp"
#include "scene/toml_reader.hpp"

namespace restitution::scene {
namespace {

// The lines for the targeted YADE, as `dem --code yade` prints them: on a YADE that cannot express the law
// (no vn, e.g. Debian's 2023.02a) those are the constant-ε lines with the ε they really give.
DemYadeTarget target_installed_yade(const Material& material, const dem::DampingSource& damping,
                                    const DemTask& task, double tolerance, dem::CodeComparison& c) {
  dem::LinesRequest request;
  request.code = task.code;
  request.end = task.end;
  request.material = material;
  request.damping = damping;
  request.speeds_m_s = task.speeds;
  request.tolerance = tolerance;
  request.friction = task.friction;
  dem::LinesResult r = dem::check_lines(request);
  DemYadeTarget target{dem::installed_yade_or_newest(), std::nullopt};
  damping_check::target_yade_version(r, target.yade.version, tolerance);
  c.deck = r.deck;
  c.predicted_eps.clear();
  for (const dem::SpeedEps& e : r.eps) c.predicted_eps.push_back(e.eps);
  target.exact_deck = r.yade_exact_deck;
  return target;
}

}  // namespace

DemOutcome run_dem_section(const Scene& scene, const DemTask& task) {
  const dem::CodeEntry& entry = dem::code_entry(task.code);
  const Material& material = scene.materials.at(task.material);
  DemOutcome out;
  std::string program;
  if (task.run_code && entry.scene_runs) {
    program = dem::dem_program(task.code);
    out.code_not_installed = program.empty();
  }
  // Without a calibration the material's own A.
  const dem::DampingSource damping{
      task.eps ? std::nullopt : std::optional<double>(material_constants(material).dissipative_constant_s),
      task.eps, task.velocity_m_s};
  out.comparison = dem::compare_with_code(task.code, material, damping, task.end, task.speeds, task.friction,
                                          scene.tolerance, scene.method, program);
  if (!std::string_view(entry.version_query).empty())
    out.yade = target_installed_yade(material, damping, task, scene.tolerance, out.comparison);
  return out;
}

namespace detail {

DemTask read_dem_task(TomlReader& r, std::string name, const std::map<std::string, Material>& materials) {
  DemTask d;
  d.line = r.line();
  d.name = std::move(name);
  d.title = r.text("title").value_or(d.name);
  const auto code = r.text("code");
  if (!code) r.fail("code", "missing (" + dem::code_list(" or ") + ")");
  try {
    d.code = dem::code_from_name(*code);
  } catch (const InvalidInput& e) {
    r.fail("code", e.what());
  }
  const auto material = read_optional_material(r, materials);
  if (!material) r.fail("material", "missing: the [materials.X] the lines are for");
  d.material = *material;
  d.eps = r.number("eps");
  d.velocity_m_s = r.number("velocity");
  if (d.eps) check_eps(r, "eps", {*d.eps});
  if (d.eps && !d.velocity_m_s) r.fail("eps", "needs velocity, the impact speed it was measured at (m/s)");
  if (!d.eps) require_dissipation(r, materials, d.material, "a dem task without eps");
  if (d.velocity_m_s) check_positive(r, "velocity", {*d.velocity_m_s});
  d.end = read_end(r);
  const auto speeds = r.numbers("speeds");
  if (!speeds || speeds->empty()) r.fail("speeds", "missing: the impact speeds to compare at (m/s)");
  check_positive(r, "speeds", *speeds);
  d.speeds = *speeds;
  d.run_code = r.flag("run").value_or(true);
  d.friction = r.number("friction").value_or(0.0);
  try {
    dem::check_friction(d.friction);
  } catch (const InvalidInput& e) {
    r.fail("friction", e.what());
  }
  return d;
}

}  // namespace detail
}  // namespace restitution::scene
