// SPDX-License-Identifier: BSD-3-Clause
#include "scene/scene_adhesion_run.hpp"

#include <fmt/core.h>

#include "restitution/adhesive_contact.hpp"
#include "restitution/errors.hpp"
#include "restitution/material.hpp"

namespace restitution::scene {
namespace {

// The contact as `eps --adhesion` assembles it (cli/common/adhesion_options.cpp): the model's damping from A,
// γ or sjkr's k_c; the damping calibrated from eps at velocity when the section gives them.
void assemble_contact(const Scene& scene, const AdhesionTask& task, AdhesionOutcome& out) {
  const Material& m = scene.materials.at(task.material);
  const double gamma = task.surface_energy_j_per_m2.value_or(0.0);
  if (task.eps) {
    out.calibration =
        calibrate_adhesive_damping(task.model, m, gamma, *task.eps, *task.velocity_m_s, out.tolerance);
    out.dissipative_constant_s = out.calibration->dissipative_constant_s;
  } else {
    out.dissipative_constant_s = material_constants(m).dissipative_constant_s;
  }
  out.contact = adhesive_contact_of(task.model, m, gamma, out.dissipative_constant_s);
  out.contact.cohesion_energy_density_j_per_m3 = task.cohesion_energy_density_j_per_m3.value_or(0.0);
}

}  // namespace

AdhesionOutcome run_adhesion_section(const Scene& scene, const AdhesionTask& task) {
  AdhesionOutcome out;
  out.tolerance = task.tolerance.value_or(scene.tolerance);
  try {
    assemble_contact(scene, task, out);
    out.elastic_hysteresis_work_j = elastic_hysteresis_work_j(out.contact);
    out.break_overlap_m = break_overlap_m(out.contact);
    out.sticking = sticking_speed(out.contact, out.tolerance);
    for (const double v : task.speeds_m_s) {
      out.collisions.push_back(solve_adhesive(out.contact, v, out.tolerance));
      if (out.collisions.back().outcome == AdhesiveOutcome::stuck) ++out.stuck;
    }
  } catch (const InvalidInput& e) {
    throw InvalidInput(
        fmt::format("{}:{}: adhesion \"{}\": {}", scene.file_name, task.line, task.name, e.what()));
  }
  return out;
}

}  // namespace restitution::scene
