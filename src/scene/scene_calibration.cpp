// SPDX-License-Identifier: BSD-3-Clause
// [[calibration]]: β (and A for a material) from a measured ε at one impact speed, by root finding with the
// run step's solver; its solves are counted with the shared plan's collisions.
#include <fmt/core.h>

#include <string>
#include <string_view>

#include "restitution/errors.hpp"
#include "restitution/material.hpp"
#include "scene/scene_planned_sections.hpp"
#include "scene/section_material.hpp"
#include "scene/toml_reader.hpp"

namespace restitution::scene {

CalibrationTask detail::read_calibration(TomlReader& r, const SectionContext& context) {
  CalibrationTask c;
  c.line = r.line();
  c.name = context.name;
  c.path = r.path();
  c.law = read_law(r);
  const auto eps = r.number("eps");
  const auto velocity = r.number("velocity");
  if (!eps) r.fail("eps", "missing");
  if (!velocity) r.fail("velocity", "missing (m/s)");
  check_eps(r, "eps", {*eps});
  check_positive(r, "velocity", {*velocity});
  c.eps = *eps;
  c.eps_line = r.line_of("eps");
  c.velocity_m_s = *velocity;
  c.end = read_end(r);
  c.material = read_optional_material(r, context.materials);
  if (c.material && !has_dissipative_constant(c.law))
    r.fail("material", "a material gives the dissipative constant A of law \"viscoelastic-hertz\" only");
  return c;
}

CalibrationOutcome run_calibration_section(const SectionRunContext& context, const CalibrationTask& task) {
  const Scene& scene = context.scene;
  CalibrationRequest request;
  request.law = task.law;
  request.eps = task.eps;
  request.velocity_m_s = task.velocity_m_s;
  request.end = task.end;
  request.tolerance = scene.tolerance;
  request.method = scene.method;
  // Only the elastic part: the material's damping, if it has any, is what the calibration computes.
  if (task.material) request.k = elastic_constants(scene.materials.at(*task.material)).k;
  CalibrationOutcome outcome;
  // ε is range-checked only here (the ε at the largest checked ζ is a solve): the refusal names the file,
  // line and key as the parser's do, "FILE:LINE: calibration[i].eps: ...".
  try {
    outcome.calibration = calibrate(request, context.solver);
  } catch (const InvalidInput& e) {
    const std::string_view message = e.what();
    const bool about_eps = message.rfind("eps ", 0) == 0;
    throw InvalidInput(fmt::format("{}:{}: {}{}: {}", scene.file_name, about_eps ? task.eps_line : task.line,
                                   task.path, about_eps ? ".eps" : "", message));
  }
  context.counted_solves += static_cast<std::size_t>(outcome.calibration.solves);
  return outcome;
}

}  // namespace restitution::scene
