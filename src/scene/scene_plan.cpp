// SPDX-License-Identifier: BSD-3-Clause
#include "scene/scene_plan.hpp"

#include <fmt/core.h>

#include "restitution/errors.hpp"
#include "restitution/units.hpp"
#include "scene/scene_sections.hpp"

namespace restitution::scene {

std::size_t JobTable::add(const ContactLaw& law, EndSet ends, bool trajectory) {
  const auto key = std::make_pair(static_cast<int>(law.kind()), law.parameter());
  auto [it, inserted] = index_.try_emplace(key, jobs_.size());
  if (inserted) jobs_.push_back(SolveJob{law, EndSet{}, false});
  SolveJob& job = jobs_[it->second];
  job.ends = job.ends | ends;
  job.keep_trajectory = job.keep_trajectory || trajectory;
  return it->second;
}

PlannedPoint detail::physical_point(double velocity_m_s, double beta, std::optional<double> k,
                                    const std::string& task) {
  PlannedPoint p;
  p.velocity_m_s = velocity_m_s;
  p.beta = beta;
  p.k = k;
  p.parameter = zeta_from(beta, velocity_m_s);
  if (p.parameter > kLargestCheckedZeta) {
    throw InvalidInput(
        fmt::format("{}: velocity {} m/s with beta {} gives zeta = {:g}, outside the checked "
                    "range 0 <= zeta <= {:g}",
                    task, velocity_m_s, beta, p.parameter, kLargestCheckedZeta));
  }
  return p;
}

EndSet existing_ends(const ContactLaw& law, EndSet requested) {
  if (!law.naive_end_may_exist()) requested.erase(CollisionEnd::naive);
  return requested;
}

Plan plan_scene(const Scene& scene) {
  Plan plan;
  JobTable table(plan.jobs);
  // In the order of Scene::sections (the table's): the jobs are numbered as the sections ask for them.
  for (const SectionTask& section : scene.sections) {
    const SectionKind& kind = *find_section_kind(section.kind);
    plan.points.push_back(kind.plan != nullptr ? kind.plan(scene, section.task, table)
                                               : std::vector<PlannedPoint>{});
  }
  return plan;
}

}  // namespace restitution::scene
