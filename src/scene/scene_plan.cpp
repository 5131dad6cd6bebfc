// SPDX-License-Identifier: BSD-3-Clause
#include "scene/scene_plan.hpp"

#include <fmt/core.h>

#include <map>
#include <utility>

#include "restitution/errors.hpp"
#include "restitution/material.hpp"
#include "restitution/units.hpp"

namespace restitution::scene {
namespace {

class JobTable {
 public:
  explicit JobTable(std::vector<SolveJob>& jobs) : jobs_(jobs) {}

  std::size_t add(const ContactLaw& law, EndSet ends, bool trajectory) {
    const auto key = std::make_pair(static_cast<int>(law.kind()), law.parameter());
    auto [it, inserted] = index_.try_emplace(key, jobs_.size());
    if (inserted) jobs_.push_back(SolveJob{law, EndSet{}, false});
    SolveJob& job = jobs_[it->second];
    job.ends = job.ends | ends;
    job.keep_trajectory = job.keep_trajectory || trajectory;
    return it->second;
  }

 private:
  std::vector<SolveJob>& jobs_;
  std::map<std::pair<int, double>, std::size_t> index_;
};

// `task` names the scene file, the line and the task, as every scene error does.
PlannedPoint physical_point(double velocity_m_s, double beta, std::optional<double> k,
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

}  // namespace

EndSet existing_ends(const ContactLaw& law, EndSet requested) {
  if (!law.naive_end_may_exist()) requested.erase(CollisionEnd::naive);
  return requested;
}

Plan plan_scene(const Scene& scene) {
  Plan plan;
  JobTable table(plan.jobs);
  for (const Sweep& s : scene.sweeps) {
    std::vector<PlannedPoint> points;
    if (s.velocity_m_s.empty()) {
      for (const double zeta : s.zeta) {
        PlannedPoint p;
        p.parameter = zeta;
        points.push_back(p);
      }
    } else {
      std::optional<double> k;
      double beta = 0.0;
      if (s.beta) beta = *s.beta;
      if (s.characteristic_velocity_m_s)
        beta = beta_from_characteristic_velocity(*s.characteristic_velocity_m_s);
      if (s.material) {
        const MaterialConstants c = material_constants(scene.materials.at(*s.material));
        beta = c.hertz.beta;
        k = c.hertz.k;
      }
      const std::string task = fmt::format("{}:{}: sweep {}", scene.file_name, s.line, s.name);
      for (const double v : s.velocity_m_s) points.push_back(physical_point(v, beta, k, task));
    }
    for (PlannedPoint& p : points) p.job = table.add(ContactLaw::natural(s.law, p.parameter), s.ends, false);
    plan.sweeps.push_back(std::move(points));
  }
  for (const Trajectory& t : scene.trajectories) {
    PlannedPoint p;
    if (t.zeta) {
      p.parameter = *t.zeta;
    } else {
      const std::optional<MaterialConstants> c =
          t.material ? std::optional(material_constants(scene.materials.at(*t.material))) : std::nullopt;
      p = physical_point(*t.velocity_m_s, c ? c->hertz.beta : *t.beta,
                         c ? std::optional(c->hertz.k) : std::nullopt,
                         fmt::format("{}:{}: trajectory {}", scene.file_name, t.line, t.name));
    }
    p.job = table.add(ContactLaw::natural(t.law, p.parameter), t.ends, true);
    plan.trajectories.push_back(p);
  }
  for (const DashpotCheck& d : scene.dashpots) {
    std::vector<PlannedPoint> points;
    for (const double r : d.damping_ratio) {
      PlannedPoint p;
      p.parameter = r;
      const ContactLaw law = ContactLaw::linear_dashpot(r);
      const EndSet ends = existing_ends(law, d.ends);
      if (!ends.empty()) p.job = table.add(law, ends, false);
      points.push_back(p);
    }
    plan.dashpots.push_back(std::move(points));
  }
  return plan;
}

}  // namespace restitution::scene
