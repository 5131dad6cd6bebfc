// SPDX-License-Identifier: BSD-3-Clause
#include "cli/scene/scene_section_writers.hpp"

#include "cli/scene/scene_adhesion.hpp"
#include "cli/scene/scene_damping.hpp"
#include "cli/scene/scene_dem.hpp"
#include "cli/scene/scene_fit_section.hpp"
#include "cli/scene/scene_gas.hpp"
#include "cli/scene/scene_oblique.hpp"
#include "cli/scene/scene_planned_sections.hpp"
#include "cli/scene/scene_studies.hpp"

namespace restitution::cli {
namespace {

// The row's function takes the kind's task and outcome types out of their std::any.
template <class Task, class Outcome, auto write>
SectionWriter row(const char* name) {
  return {name,
          [](const scene::Scene& scene, const scene::SectionTask& section, const std::any& outcome,
             SectionOutput& out) {
            write(scene, std::any_cast<const Task&>(section.task), std::any_cast<const Outcome&>(outcome),
                  out);
          },
          nullptr};
}

}  // namespace

const std::vector<SectionWriter>& section_writers() {
  static const std::vector<SectionWriter> writers = {
      row<scene::Sweep, scene::SweepOutcome, write_sweep_section>("sweep"),
      row<scene::Trajectory, scene::TrajectoryOutcome, write_trajectory_section>("trajectory"),
      {"calibration", nullptr, write_calibrations},
      row<scene::DashpotCheck, scene::DashpotOutcome, write_dashpot_section>("dashpot"),
      row<scene::DemTask, scene::DemOutcome, write_dem_section>("dem"),
      row<scene::DampingCheckTask, damping_check::GridResult, write_damping_check_section>("damping_check"),
      row<scene::GasTask, scene::GasOutcome, write_gas_section>("gas"),
      row<scene::ObliqueTask, scene::ObliqueOutcome, write_oblique_section>("oblique"),
      row<scene::AdhesionTask, scene::AdhesionOutcome, write_adhesion_section>("adhesion"),
      row<scene::FitTask, scene::FitOutcome, write_fit_section>("fit"),
      {"work_precision", nullptr, write_studies},
      {"stability", nullptr, write_studies},
  };
  return writers;
}

const SectionWriter* find_section_writer(std::string_view name) {
  for (const SectionWriter& writer : section_writers()) {
    if (name == writer.name) return &writer;
  }
  return nullptr;
}

}  // namespace restitution::cli
