#include "scene/scene_run.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>

#include "restitution/material.hpp"
#include "scene/scene_extensions.hpp"

namespace restitution::scene {
namespace {

// Solves every job once; workers take the next job from a shared counter, each with its own solver.
std::vector<CollisionResult> solve_all(const std::vector<SolveJob>& jobs, const Scene& scene,
                                       const RunSettings& settings) {
  std::vector<CollisionResult> solved(jobs.size());
  std::atomic<std::size_t> next{0};
  std::size_t done = 0;
  std::mutex lock;
  std::exception_ptr failure;
  auto work = [&] {
    CollisionSolver solver;
    for (std::size_t i = next++; i < jobs.size(); i = next++) {
      SolveOptions options;
      options.tolerance = scene.tolerance;
      options.method = scene.method;
      options.ends = jobs[i].ends;
      options.keep_trajectory = jobs[i].keep_trajectory;
      try {
        solved[i] = solver.solve(jobs[i].law, options);
      } catch (...) {
        const std::lock_guard<std::mutex> guard(lock);
        if (!failure) failure = std::current_exception();
        next = jobs.size();
        return;
      }
      const std::lock_guard<std::mutex> guard(lock);
      ++done;
      if (settings.progress) settings.progress(done, jobs.size());
    }
  };
  const unsigned hardware = std::max(1U, std::thread::hardware_concurrency());
  const std::size_t threads = std::min<std::size_t>(settings.threads != 0 ? settings.threads : hardware,
                                                    std::max<std::size_t>(1, jobs.size()));
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  return solved;
}

}  // namespace

const CollisionResult* result_of(const SceneResults& results, const PlannedPoint& point) {
  return point.job == kNoJob ? nullptr : &results.solved[point.job];
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
    std::vector<const CollisionResult*> results;
    for (const PlannedPoint& p : points) {
      zeta.push_back(p.parameter);
      results.push_back(result_of(out, p));
    }
    SweepExtras extras;
    detail::add_approximations(s, zeta, extras);
    detail::add_power_law_fits(s, zeta, results, extras);
    if (s.empirical) {
      for (const PlannedPoint& p : points) {
        extras.empirical_eps.push_back(
            s.empirical->coefficient *
            std::pow(*p.velocity_m_s / s.empirical->velocity_unit_m_s, s.empirical->exponent));
      }
    }
    out.sweeps.push_back(std::move(extras));
  }

  CollisionSolver solver;
  for (const CalibrationTask& task : scene.calibrations) {
    CalibrationRequest request;
    request.eps = task.eps;
    request.velocity_m_s = task.velocity_m_s;
    request.end = task.end;
    request.tolerance = scene.tolerance;
    request.method = scene.method;
    CalibrationOutcome outcome;
    if (task.material) {
      outcome.material = material_constants(scene.materials.at(*task.material));
      request.k = outcome.material->hertz.k;
    }
    outcome.calibration = calibrate(request, solver);
    out.collisions += static_cast<std::size_t>(outcome.calibration.solves);
    out.calibrations.push_back(outcome);
  }
  for (const ExternalStudy& study : scene.studies)
    out.studies.push_back(detail::run_study(study, scene.tolerance, settings.reference_file));
  return out;
}

}  // namespace restitution::scene
