// SPDX-License-Identifier: BSD-3-Clause
#include "scene/scene_sections.hpp"

#include <algorithm>
#include <type_traits>

#include "scene/scene_adhesion.hpp"
#include "scene/scene_adhesion_run.hpp"
#include "scene/scene_damping_check.hpp"
#include "scene/scene_dem.hpp"
#include "scene/scene_extensions.hpp"
#include "scene/scene_fit.hpp"
#include "scene/scene_gas.hpp"
#include "scene/scene_oblique.hpp"
#include "scene/scene_oblique_run.hpp"
#include "scene/scene_planned_sections.hpp"
#include "scene/scene_studies.hpp"

namespace restitution::scene {
namespace {

// Each row's functions take the kind's own task type out of the std::any and put its outcome in one; a
// kind that computes from the scene alone takes (scene, task), one that needs more the whole context.
template <class Task, auto read, auto compute>
SectionKind row(const char* name, void (*quick)(std::any&, std::size_t), const char* own_solves) {
  return {name, [](detail::TomlReader& r, const SectionContext& c) -> std::any { return read(r, c); },
          [](const SectionRunContext& context, const std::any& task) -> std::any {
            const Task& t = std::any_cast<const Task&>(task);
            if constexpr (std::is_invocable_v<decltype(compute), const Scene&, const Task&>) {
              return compute(context.scene, t);
            } else {
              return compute(context, t);
            }
          },
          quick, own_solves};
}

// A row of the planner's: the row above with its hook that adds the task's collisions to the shared plan.
template <class Task, auto read, auto plan, auto compute>
SectionKind planned_row(const char* name, void (*quick)(std::any&, std::size_t)) {
  SectionKind kind = row<Task, read, compute>(name, quick, "");
  kind.plan = [](const Scene& scene, const std::any& task, JobTable& jobs) {
    return plan(scene, std::any_cast<const Task&>(task), jobs);
  };
  return kind;
}

// The readers of the rows whose reader takes other arguments than (TomlReader&, const SectionContext&).
DemTask read_dem(detail::TomlReader& r, const SectionContext& c) {
  return detail::read_dem_task(r, c.name, c.materials);
}
DampingCheckTask read_damping_check(detail::TomlReader& r, const SectionContext& c) {
  return detail::read_damping_check_task(r, c.name);
}
GasTask read_gas(detail::TomlReader& r, const SectionContext& c) {
  return detail::read_gas_task(r, c.name, c.materials);
}
ObliqueTask read_oblique(detail::TomlReader& r, const SectionContext& c) {
  return detail::read_oblique_task(r, c.name, c.materials, c.warnings);
}
AdhesionTask read_adhesion(detail::TomlReader& r, const SectionContext& c) {
  return detail::read_adhesion_task(r, c.name, c.materials);
}
FitTask read_fit(detail::TomlReader& r, const SectionContext& c) {
  return detail::read_fit_task(r, c.name, c.materials);
}
template <const char* kind>
ExternalStudy read_study(detail::TomlReader& r, const SectionContext& c) {
  return detail::read_study_task(r, kind, c.name);
}
constexpr char kWorkPrecision[] = "work_precision";
constexpr char kStability[] = "stability";

// The run steps that need more than the scene.
damping_check::GridResult run_damping_check_section(const SectionRunContext& c,
                                                    const DampingCheckTask& task) {
  return run_damping_check(task, c.scene.tolerance, c.solver);
}
StudyOutcome run_study_section(const SectionRunContext& c, const ExternalStudy& study) {
  return detail::run_study(study, c.scene.tolerance, c.reference_file);
}

void keep_all(std::any& /*task*/, std::size_t /*points*/) {}

template <class Task, auto... ranges>
void thin_ranges(std::any& task, std::size_t points) {
  Task& t = std::any_cast<Task&>(task);
  (thin_values(t.*ranges, points), ...);
}

void quick_study(std::any& task, std::size_t points) {
  auto& study = std::any_cast<ExternalStudy&>(task);
  thin_values(study.zeta, points);
  study.repeats = 1;  // each work-precision point timed once
}

constexpr const char* kDemWords = "the [[dem]] and [[damping_check]] sections solve their own collisions";

}  // namespace

const std::vector<SectionKind>& section_kinds() {
  // The order the parser reads the kinds in (unnamed sections are numbered in it) and the run step runs
  // them in.
  static const std::vector<SectionKind> kinds = {
      // The planner's: their collisions are solved once in the shared plan, before any row runs.
      planned_row<Sweep, detail::read_sweep, plan_sweep, run_sweep_section>(
          "sweep", thin_ranges<Sweep, &Sweep::zeta, &Sweep::velocity_m_s>),
      planned_row<Trajectory, detail::read_trajectory, plan_trajectory, run_trajectory_section>("trajectory",
                                                                                                keep_all),
      // Solved by root finding with the rows' solver, counted with the plan's collisions.
      row<CalibrationTask, detail::read_calibration, run_calibration_section>("calibration", keep_all, ""),
      planned_row<DashpotCheck, detail::read_dashpot, plan_dashpot, run_dashpot_section>(
          "dashpot", thin_ranges<DashpotCheck, &DashpotCheck::damping_ratio>),
      row<DemTask, read_dem, run_dem_section>(
          "dem",
          [](std::any& t, std::size_t n) { thin_values(std::any_cast<DemTask&>(t).inputs.speeds_m_s, n); },
          kDemWords),
      row<DampingCheckTask, read_damping_check, run_damping_check_section>(
          "damping_check", thin_ranges<DampingCheckTask, &DampingCheckTask::eps, &DampingCheckTask::speeds>,
          kDemWords),
      // --quick loosens the scene's tolerance, which the gas takes unless it gives its own.
      row<GasTask, read_gas, run_gas_section>(
          "gas", keep_all, "the [[gas]] sections take eps(v) from the fast table or from their own solves"),
      // Angles and spins are few, and Maw's diagram needs them: --quick keeps them all.
      row<ObliqueTask, read_oblique, run_oblique_section>(
          "oblique", keep_all, "the [[oblique]] sections integrate their own impacts"),
      row<AdhesionTask, read_adhesion, run_adhesion_section>(
          "adhesion", thin_ranges<AdhesionTask, &AdhesionTask::speeds_m_s>,
          "the [[adhesion]] sections integrate their own collisions"),
      // Measured data are kept whole.
      row<FitTask, read_fit, run_fit_section>("fit", keep_all, ""),
      row<ExternalStudy, read_study<kWorkPrecision>, run_study_section>(kWorkPrecision, quick_study, ""),
      row<ExternalStudy, read_study<kStability>, run_study_section>(kStability, quick_study, ""),
  };
  return kinds;
}

const SectionKind* find_section_kind(std::string_view name) {
  for (const SectionKind& kind : section_kinds()) {
    if (name == kind.name) return &kind;
  }
  return nullptr;
}

bool has_sections(const Scene& scene, std::string_view kind) {
  return std::any_of(scene.sections.begin(), scene.sections.end(),
                     [kind](const SectionTask& s) { return s.kind == kind; });
}

}  // namespace restitution::scene
