// SPDX-License-Identifier: BSD-3-Clause
#include "scene/scene_run.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <mutex>
#include <string>
#include <string_view>
#include <utility>

#include "parallel/parallel_for.hpp"
#include "restitution/errors.hpp"
#include "restitution/material.hpp"
#include "scene/scene_comparisons.hpp"
#include "scene/scene_extensions.hpp"
#include "scene/scene_sections.hpp"

namespace restitution::scene {
namespace {

// Solves every job once on the library's thread pool, each worker thread with its own solver; any failure
// ends the run and is rethrown (a scene has no per-point failures).
std::vector<CollisionResult> solve_all(const std::vector<SolveJob>& jobs, const Scene& scene,
                                       const RunSettings& settings) {
  std::vector<CollisionResult> solved(jobs.size());
  std::size_t done = 0;
  std::mutex lock;  // guards done and the progress callback
  restitution::detail::ParallelRun run{jobs.size(), settings.threads, {}};
  restitution::detail::parallel_for(run, [&]() -> restitution::detail::IndexBody {
    auto solver = std::make_shared<CollisionSolver>();
    return [&, solver](std::size_t i) {
      SolveOptions options;
      options.tolerance = scene.tolerance;
      options.method = scene.method;
      options.ends = jobs[i].ends;
      options.keep_trajectory = jobs[i].keep_trajectory;
      solved[i] = solver->solve(jobs[i].law, options);
      const std::lock_guard<std::mutex> guard(lock);
      ++done;
      if (settings.progress) settings.progress(done, jobs.size());
    };
  });
  return solved;
}

// A calibration's ε is range-checked only when it runs (the ε at the largest checked ζ is a solve): its
// refusal names the file, line and key as the parser's do, "FILE:LINE: calibration[i].eps: ...".
Calibration calibrate_scene_task(const CalibrationRequest& request, CollisionSolver& solver,
                                 const std::string& file_name, const CalibrationTask& task,
                                 std::size_t index) {
  try {
    return calibrate(request, solver);
  } catch (const InvalidInput& e) {
    const std::string_view message = e.what();
    const bool about_eps = message.rfind("eps ", 0) == 0;
    throw InvalidInput(fmt::format("{}:{}: calibration[{}]{}: {}", file_name,
                                   about_eps ? task.eps_line : task.line, index, about_eps ? ".eps" : "",
                                   message));
  }
}

}  // namespace

const CollisionResult* result_of(const SceneResults& results, const PlannedPoint& point) {
  return point.job == kNoJob ? nullptr : &results.solved[point.job];
}

const EndResult* end_if_computed(const CollisionResult* result, CollisionEnd end) {
  if (result == nullptr) return nullptr;
  const auto& e = (*result)[end];
  return e ? &*e : nullptr;
}

SceneResults run_scene(const Scene& scene, Plan plan, const RunSettings& settings) {
  SceneResults out;
  out.plan = std::move(plan);
  out.solved = solve_all(out.plan.jobs, scene, settings);
  for (const CollisionResult& r : out.solved) out.total += r.stats;
  out.collisions = out.solved.size();

  for (std::size_t i = 0; i < scene.sweeps.size(); ++i) {
    const Sweep& s = scene.sweeps[i];
    const std::vector<PlannedPoint>& points = out.plan.sweeps[i];
    std::vector<double> zeta;
    detail::PointResults results;
    for (const PlannedPoint& p : points) {
      zeta.push_back(p.parameter);
      results.push_back(result_of(out, p));
    }
    SweepExtras extras;
    detail::add_approximations(s, zeta, extras);
    detail::compare_approximations(zeta, results, extras);
    detail::add_power_law_fits(s, zeta, results, extras);
    if (s.empirical) {
      std::vector<double> velocity_m_s;
      velocity_m_s.reserve(points.size());
      for (const PlannedPoint& p : points) velocity_m_s.push_back(*p.velocity_m_s);
      detail::add_empirical(*s.empirical, s.ends, velocity_m_s, results, extras);
    }
    out.sweeps.push_back(std::move(extras));
  }
  for (std::size_t i = 0; i < scene.dashpots.size(); ++i) {
    std::vector<double> damping_ratio;
    detail::PointResults results;
    for (const PlannedPoint& p : out.plan.dashpots[i]) {
      damping_ratio.push_back(p.parameter);
      results.push_back(result_of(out, p));
    }
    out.dashpots.push_back(detail::check_dashpot(scene.dashpots[i], damping_ratio, results));
  }

  CollisionSolver solver;
  for (std::size_t i = 0; i < scene.calibrations.size(); ++i) {
    const CalibrationTask& task = scene.calibrations[i];
    CalibrationRequest request;
    request.law = task.law;
    request.eps = task.eps;
    request.velocity_m_s = task.velocity_m_s;
    request.end = task.end;
    request.tolerance = scene.tolerance;
    request.method = scene.method;
    CalibrationOutcome outcome;
    // Only the elastic part: the material's damping, if it has any, is what the calibration computes.
    if (task.material) request.k = elastic_constants(scene.materials.at(*task.material)).k;
    outcome.calibration = calibrate_scene_task(request, solver, scene.file_name, task, i);
    out.collisions += static_cast<std::size_t>(outcome.calibration.solves);
    out.calibrations.push_back(outcome);
  }
  const SectionRunContext context{scene, solver, settings.reference_file};
  for (const SectionTask& section : scene.sections)
    out.sections.push_back(find_section_kind(section.kind)->run(context, section.task));
  return out;
}

}  // namespace restitution::scene
