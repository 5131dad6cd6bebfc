// SPDX-License-Identifier: BSD-3-Clause
#include "scene/scene_dem.hpp"

#include <string_view>

#include "damping_check/yade_version_lines.hpp"
#include "dem/code_runner.hpp"
#include "dem/deck.hpp"
#include "restitution/errors.hpp"
#include "scene/parameter_keys.hpp"
#include "scene/scene.hpp"
#include "scene/section_material.hpp"
#include "scene/toml_reader.hpp"

namespace restitution::scene {
namespace {

// The lines for the targeted YADE, as `dem --code yade` prints them: on a YADE that cannot express the law
// (no vn, e.g. Debian's 2023.02a) those are the constant-ε lines with the ε they really give.
DemYadeTarget target_installed_yade(const Material& material, const dem::DemInputs& in,
                                    dem::CodeComparison& c) {
  auto request = dem::request_of<dem::LinesRequest>(in);
  request.material = material;
  dem::LinesResult r = dem::check_lines(request);
  DemYadeTarget target{dem::installed_yade_or_newest(), std::nullopt};
  damping_check::target_yade_version(r, target.yade.version, in.tolerance);
  c.deck = r.deck;
  c.predicted_eps.clear();
  for (const dem::SpeedEps& e : r.eps) c.predicted_eps.push_back(e.eps);
  target.exact_deck = r.yade_exact_deck;
  return target;
}

}  // namespace

DemOutcome run_dem_section(const Scene& scene, const DemTask& task) {
  const dem::Code code = dem::code_from_name(task.inputs.code);
  const dem::CodeEntry& entry = dem::code_entry(code);
  const Material& material = scene.materials.at(task.material);
  DemOutcome out;
  std::string program;
  if (task.run_code && entry.scene_runs) {
    program = dem::dem_program(code);
    out.code_not_installed = program.empty();
  }
  dem::DemInputs in = task.inputs;
  in.tolerance = scene.tolerance;
  // Without a calibration the material's own A.
  if (!in.eps) in.dissipative_constant_s = material_constants(material).dissipative_constant_s;
  out.comparison = dem::compare_with_code(code, material, dem::damping_of(in), end_from_name(in.end),
                                          in.speeds_m_s, in.friction, scene.tolerance, scene.method, program);
  if (!std::string_view(entry.version_query).empty())
    out.yade = target_installed_yade(material, in, out.comparison);
  return out;
}

namespace detail {
namespace {

// The code (its absence said with the codes there are), then the material the lines are for.
void read_code_and_material(TomlReader& r, const dem::DemField& code, DemTask& d,
                            const std::map<std::string, Material>& materials) {
  if (!r.has(code.key())) r.fail(code.key(), "missing (" + dem::code_list(" or ") + ")");
  read_parameter_key(r, code, d.inputs);
  d.material = read_section_material(r, materials, "the lines are for");
}

// eps calibrates A at velocity; without it the lines take the material's A, which it must have.
void check_damping(const TomlReader& r, const DemTask& d, const std::map<std::string, Material>& materials) {
  if (d.inputs.eps && !d.inputs.velocity_m_s)
    r.fail("eps", "needs velocity, the impact speed it was measured at (m/s)");
  if (!d.inputs.eps) require_dissipation(r, materials, d.material, "a dem task without eps");
}

}  // namespace

DemTask read_dem_task(TomlReader& r, std::string name, const std::map<std::string, Material>& materials) {
  DemTask d;
  d.line = r.line();
  d.name = std::move(name);
  d.title = r.text("title").value_or(d.name);
  for (const dem::DemField& f : dem::dem_fields()) {
    if (f.word == &dem::DemInputs::code) {
      read_code_and_material(r, f, d, materials);
    } else if (f.from_material) {
      check_damping(r, d, materials);
    } else {
      read_parameter_key(r, f, d.inputs);  // the accuracy is no key: the scene's tolerance
    }
  }
  d.run_code = r.flag("run").value_or(true);
  return d;
}

}  // namespace detail
}  // namespace restitution::scene
