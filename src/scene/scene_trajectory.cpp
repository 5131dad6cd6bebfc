// SPDX-License-Identifier: BSD-3-Clause
// [[trajectory]]: one collision with its trajectory x, x', x'' (the 2008 paper's Fig. 3), read, planned into
// the shared plan (a trajectory is kept for its job) and read back solved.
#include <fmt/core.h>

#include "restitution/material.hpp"
#include "scene/scene_planned_sections.hpp"
#include "scene/section_material.hpp"
#include "scene/toml_reader.hpp"

namespace restitution::scene {

Trajectory detail::read_trajectory(TomlReader& r, const SectionContext& context) {
  Trajectory t;
  read_heading(r, context, t);
  t.law = read_law(r);
  t.zeta = r.number("zeta");
  t.velocity_m_s = r.number("velocity");
  t.beta = r.number("beta");
  t.material = read_optional_material(r, context.materials);
  require_dissipation(r, context.materials, t.material, "a trajectory");
  if (t.zeta) {
    if (t.velocity_m_s || t.beta || t.material)
      r.fail("zeta", "give zeta alone, or velocity with beta or material");
    check_zeta(r, {*t.zeta});
    check_law_zeta(r, t.law, t.ends, {*t.zeta});
  } else {
    if (!has_dissipative_constant(t.law))
      r.fail("law", "a trajectory of a law other than viscoelastic-hertz takes zeta (its natural form)");
    if (!t.velocity_m_s) r.fail("", "give zeta, or velocity with beta or material");
    if (t.beta.has_value() == t.material.has_value())
      r.fail("velocity", "needs exactly one of beta, material");
    check_positive(r, "velocity", {*t.velocity_m_s});
    if (t.beta && *t.beta < 0.0) r.fail("beta", "expected a value >= 0");
  }
  return t;
}

std::vector<PlannedPoint> plan_trajectory(const Scene& scene, const Trajectory& t, JobTable& jobs) {
  PlannedPoint p;
  if (t.zeta) {
    p.parameter = *t.zeta;
  } else {
    const std::optional<MaterialConstants> c =
        t.material ? std::optional(material_constants(scene.materials.at(*t.material))) : std::nullopt;
    p = detail::physical_point(*t.velocity_m_s, c ? c->hertz.beta : *t.beta,
                               c ? std::optional(c->hertz.k) : std::nullopt,
                               fmt::format("{}:{}: trajectory {}", scene.file_name, t.line, t.name));
  }
  p.job = jobs.add(ContactLaw::natural(t.law, p.parameter), t.ends, true);
  return {p};
}

TrajectoryOutcome run_trajectory_section(const SectionRunContext& context, const Trajectory& /*trajectory*/) {
  const PlannedPoint& p = context.points.front();
  return {p, context.solved[p.job]};
}

}  // namespace restitution::scene
