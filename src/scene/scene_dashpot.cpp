// SPDX-License-Identifier: BSD-3-Clause
// [[dashpot]]: the linear dash-pot against its closed forms (2008 paper Eqs. 10 and 12), read, planned into
// the shared plan (only the ends that exist at each damping ratio) and checked once solved.
#include "scene/scene_comparisons.hpp"
#include "scene/scene_planned_sections.hpp"
#include "scene/toml_reader.hpp"

namespace restitution::scene {

DashpotCheck detail::read_dashpot(TomlReader& r, const SectionContext& context) {
  DashpotCheck d;
  read_heading(r, context, d);
  const auto ratios = r.numbers("damping_ratio");
  if (!ratios) r.fail("damping_ratio", "missing");
  check_positive(r, "damping_ratio", *ratios);
  d.damping_ratio = *ratios;
  return d;
}

std::vector<PlannedPoint> plan_dashpot(const Scene& /*scene*/, const DashpotCheck& d, JobTable& jobs) {
  std::vector<PlannedPoint> points;
  for (const double r : d.damping_ratio) {
    PlannedPoint p;
    p.parameter = r;
    const ContactLaw law = ContactLaw::linear_dashpot(r);
    const EndSet ends = existing_ends(law, d.ends);
    if (!ends.empty()) p.job = jobs.add(law, ends, false);
    points.push_back(p);
  }
  return points;
}

DashpotOutcome run_dashpot_section(const SectionRunContext& context, const DashpotCheck& d) {
  std::vector<double> damping_ratio;
  detail::PointResults results;
  for (const PlannedPoint& p : context.points) {
    damping_ratio.push_back(p.parameter);
    results.push_back(p.job == kNoJob ? nullptr : &context.solved[p.job]);
  }
  return detail::check_dashpot(d, damping_ratio, results);
}

}  // namespace restitution::scene
