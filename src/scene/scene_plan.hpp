// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The planner: from what a scene asks, the collisions to integrate. Each distinct collision is solved once,
// with the union of the ends and the trajectory every output needs from it; only the requested ends are
// integrated (no naive tail when only delayed recovery is wanted) and trajectories only when asked. The
// sections whose rows have a plan hook (scene_sections.hpp) add their collisions here.
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "restitution/collision_solver.hpp"
#include "scene/scene.hpp"

namespace restitution::scene {

struct SolveJob {
  ContactLaw law;  // always in natural units (ζ or the damping ratio r)
  EndSet ends;
  bool keep_trajectory = false;
};

inline constexpr std::size_t kNoJob = static_cast<std::size_t>(-1);  // nothing to integrate (no such end)

// One collision of a task: its ζ (or r), the physical data it came from, and the job that solves it.
struct PlannedPoint {
  double parameter = 0.0;              // ζ, or r for the dash-pot
  std::optional<double> velocity_m_s;  // impact speed, for sweeps over velocity
  std::optional<double> beta;          // s^{1/5} m^{-1/5}
  std::optional<double> k;             // ρ/m_eff of a material [s^-2 m^-1/2]: SI times and lengths
  std::size_t job = kNoJob;
};

struct Plan {
  std::vector<SolveJob> jobs;
  // Parallel to Scene::sections: the points each section of a planner row asked for (none for the others).
  std::vector<std::vector<PlannedPoint>> points;
};

// The plan's distinct collisions as the sections add them: a collision asked for again (same law and
// parameter) is the same job, solved with the union of the ends and trajectories asked for.
class JobTable {
 public:
  explicit JobTable(std::vector<SolveJob>& jobs) : jobs_(jobs) {}
  // The job's index in the plan.
  std::size_t add(const ContactLaw& law, EndSet ends, bool trajectory);

 private:
  std::vector<SolveJob>& jobs_;
  std::map<std::pair<int, double>, std::size_t> index_;
};

// Throws InvalidInput when a physical point lies outside the solver's range (ζ > 1e4), naming the file, the
// line where the task starts and the task.
Plan plan_scene(const Scene& scene);

// The requested ends a collision has: no naive end where the law rules it out before solving
// (ContactLaw::naive_end_may_exist: the dash-pot at r >= 1, Tsuji at ζ >= √5; x never returns to 0).
EndSet existing_ends(const ContactLaw& law, EndSet requested);

namespace detail {
// The point of an impact at velocity_m_s with β (and k for a material's SI columns); `task` names the scene
// file, the line and the task, as every scene error does, when ζ lies outside the checked range.
PlannedPoint physical_point(double velocity_m_s, double beta, std::optional<double> k,
                            const std::string& task);
}  // namespace detail

}  // namespace restitution::scene
