// SPDX-License-Identifier: BSD-3-Clause
#include "scene/scene_oblique_run.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "restitution/errors.hpp"
#include "restitution/material.hpp"

namespace restitution::scene {
namespace {

using namespace restitution::oblique;

// The section as the study's inputs for one model, so that the scene and the command take one path.
ObliqueInputs inputs_of(const Scene& scene, const ObliqueTask& task, const std::string& model) {
  const Material& m = scene.materials.at(task.material);
  ObliqueInputs in = task.inputs;
  in.material = m;
  // The material's dissipation (A, or the viscosities' A; the section's reader requires one).
  in.dissipative_constant_s = material_constants(m).dissipative_constant_s;
  in.tangential = model;
  // A k_t per contact radius, in N/m² (the mindlin family, liggghts_history), is mindlin_stiffness; one in
  // N/m tangential_stiffness.
  const TangentialModel* row = find_tangential_model(model);
  const bool per_contact_radius = row != nullptr && row->rule.growth == StiffnessGrowth::contact_radius;
  if (per_contact_radius) in.tangential_stiffness = task.mindlin_stiffness;
  return in;
}

ObliqueModelRun model_run(const Scene& scene, const ObliqueTask& task, const std::string& model,
                          bool plotted) {
  ObliqueModelRun run;
  run.setup = oblique_setup(inputs_of(scene, task, model), ArgumentStyle::keyword);
  run.impacts = oblique_sweep(run.setup);
  run.sticking = plotted ? sticking_limit_restitution(run.setup) : StickingLimit{std::nan(""), ""};
  run.lowest_et = std::numeric_limits<double>::infinity();
  run.highest_et = -std::numeric_limits<double>::infinity();
  for (const ObliqueImpact& i : run.impacts) {
    const double e = i.result.tangential_restitution;
    if (std::isfinite(e)) {
      run.lowest_et = std::min(run.lowest_et, e);
      run.highest_et = std::max(run.highest_et, e);
    }
    if (i.solved() && i.result.slip_time_s >= 0.99 * i.result.contact_time_s) ++run.sliding;
  }
  run.failed = failed_count(run.impacts);
  return run;
}

}  // namespace

ObliqueOutcome run_oblique_section(const Scene& scene, const ObliqueTask& task) {
  ObliqueOutcome out;
  out.plotted = task.plot && *task.inputs.friction > 0.0;
  try {
    for (const std::string& model : task.models)
      out.runs.push_back(model_run(scene, task, model, out.plotted));
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("{}: oblique \"{}\": {}", scene.file_name, task.name, e.what()));
  }
  const ObliqueModelRun& first = out.runs.front();
  out.eps_low = HUGE_VAL;
  out.eps_high = -HUGE_VAL;
  out.first_eps = std::nan("");
  bool first_found = false;
  for (const ObliqueImpact& i : first.impacts) {
    if (!i.solved()) continue;
    if (!first_found) out.first_eps = i.result.normal_restitution;
    first_found = true;
    out.eps_low = std::min(out.eps_low, i.result.normal_restitution);
    out.eps_high = std::max(out.eps_high, i.result.normal_restitution);
  }
  out.maw_chi = maw_chi(first.setup);
  return out;
}

}  // namespace restitution::scene
