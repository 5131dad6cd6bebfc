// SPDX-License-Identifier: BSD-3-Clause
#include "scene/scene_run.hpp"

#include <algorithm>
#include <mutex>
#include <utility>

#include "parallel/parallel_for.hpp"
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
  // Every section through its row, in the table's order, one solver shared (one at a time).
  CollisionSolver solver;
  for (std::size_t i = 0; i < scene.sections.size(); ++i) {
    const SectionTask& section = scene.sections[i];
    const SectionRunContext context{scene,      solver,        settings.reference_file, out.plan.points.at(i),
                                    out.solved, out.collisions};
    out.sections.push_back(find_section_kind(section.kind)->run(context, section.task));
  }
  return out;
}

}  // namespace restitution::scene
