// SPDX-License-Identifier: BSD-3-Clause
// [[sweep]]: ε tables over ζ or impact speeds, read, planned into the shared plan and studied once solved.
#include <fmt/core.h>
#include <fmt/format.h>

#include <string>

#include "restitution/errors.hpp"
#include "restitution/head_on_parameters.hpp"
#include "restitution/material.hpp"
#include "restitution_series_study/series_named.hpp"
#include "scene/parameter_keys.hpp"
#include "scene/scene_approximations.hpp"
#include "scene/scene_comparisons.hpp"
#include "scene/scene_extensions.hpp"
#include "scene/scene_planned_sections.hpp"
#include "scene/section_material.hpp"
#include "scene/toml_reader.hpp"

namespace restitution::scene {
namespace {

series::Approximation approximation_from(const detail::TomlReader& r, const std::string& name) {
  if (const auto kind = series::approximation_named(name)) return *kind;
  r.fail("approximations", fmt::format("unknown approximation \"{}\" (known: {})", name,
                                       fmt::join(series::evaluation_kinds(), ", ")));
}

}  // namespace

namespace detail {

Sweep read_sweep(TomlReader& r, const SectionContext& context) {
  Sweep s;
  read_heading(r, context, s);
  s.note = r.text("note").value_or("");
  if (const auto q = r.words("quantities")) {
    s.quantities = {false, false, false, false};
    for (const std::string& w : *q) {
      if (w == "eps")
        s.quantities.eps = true;
      else if (w == "one_minus_eps")
        s.quantities.one_minus_eps = true;
      else if (w == "duration")
        s.quantities.duration = true;
      else if (w == "max_compression")
        s.quantities.max_compression = true;
      else
        r.fail("quantities",
               fmt::format("unknown quantity \"{}\" (eps, one_minus_eps, duration, max_compression)", w));
    }
  }
  HeadOnInputs
      inputs;  // the keys [[sweep]] shares with `eps` and `sweep` (restitution/head_on_parameters.hpp)
  read_parameter_key(r, head_on_field("law"), inputs);
  s.law = law_from_name(inputs.law);
  const auto zeta = r.numbers("zeta");
  const auto velocity = r.numbers("velocity");
  if (velocity && !has_dissipative_constant(s.law)) {
    r.fail("velocity", fmt::format("a sweep over impact speeds is for law \"viscoelastic-hertz\"; law \"{}\" "
                                   "sweeps zeta (`restitution sweep --law {} --stiffness ...` sweeps its "
                                   "impact speeds)",
                                   law_name(s.law), law_name(s.law)));
  }
  s.beta = r.number("beta");
  s.material = read_optional_material(r, context.materials);
  require_dissipation(r, context.materials, s.material, "a sweep");
  s.characteristic_velocity_m_s = r.number("characteristic_velocity");
  const int subjects = static_cast<int>(s.beta.has_value()) + static_cast<int>(s.material.has_value()) +
                       static_cast<int>(s.characteristic_velocity_m_s.has_value());
  if (zeta) {
    if (velocity || subjects > 0)
      r.fail("zeta", "give zeta alone, or velocity with one of beta, material, characteristic_velocity");
    check_zeta(r, *zeta);
    check_law_zeta(r, s.law, s.ends, *zeta);
    s.zeta = *zeta;
  } else {
    if (!velocity) r.fail("", "give zeta, or velocity with one of beta, material, characteristic_velocity");
    if (subjects != 1) r.fail("velocity", "needs exactly one of beta, material, characteristic_velocity");
    check_positive(r, "velocity", *velocity);
    s.velocity_m_s = *velocity;
    if (s.beta && *s.beta < 0.0) r.fail("beta", "expected a value >= 0");
    if (s.characteristic_velocity_m_s && *s.characteristic_velocity_m_s <= 0.0) {
      r.fail("characteristic_velocity", "expected a value > 0 (m/s)");
    }
  }
  if (const auto names = r.words("approximations")) {
    for (const std::string& name : *names) s.approximations.push_back(approximation_from(r, name));
  }
  s.asymptotics = r.flag("asymptotics").value_or(false);
  const bool compare_series = r.flag("compare_series").value_or(false);
  if (s.law != LawKind::viscoelastic_hertz) {
    const char* hertz_only = !s.approximations.empty() ? "approximations"
                             : s.asymptotics           ? "asymptotics"
                             : compare_series          ? "compare_series"
                                                       : nullptr;
    if (hertz_only != nullptr) {
      r.fail(hertz_only, fmt::format("the series and asymptotics are those of viscoelastic Hertz, not of "
                                     "law \"{}\"",
                                     law_name(s.law)));
    }
  }
  if (compare_series) {
    if (s.ends.contains(CollisionEnd::naive)) s.approximations.push_back(series::Approximation::naive_series);
    if (s.ends.contains(CollisionEnd::delayed_recovery))
      s.approximations.push_back(series::Approximation::delayed_recovery_series);
  }
  if (const toml::table* e = r.table("empirical")) {
    TomlReader er(*e, r.child_path("empirical"), r.file_name());
    EmpiricalLaw law;
    law.coefficient = er.number("coefficient").value_or(0.0);
    law.exponent = er.number("exponent").value_or(0.0);
    law.velocity_unit_m_s = er.number("velocity_unit").value_or(1.0);
    er.finish();
    if (law.coefficient <= 0.0) er.fail("coefficient", "expected a value > 0");
    if (law.velocity_unit_m_s <= 0.0) er.fail("velocity_unit", "expected a value > 0 (m/s)");
    if (s.velocity_m_s.empty()) r.fail("empirical", "needs a sweep over velocity");
    s.empirical = law;
  }
  if (const toml::table* f = r.table("fit")) {
    TomlReader fr(*f, r.child_path("fit"), r.file_name());
    PowerLawFitRequest fit;
    fit.zeta_min = fr.number("zeta_min").value_or(0.0);
    fr.finish();
    if (fit.zeta_min <= 0.0) fr.fail("zeta_min", "expected a value > 0");
    s.fit = fit;
  }
  const std::string axes = r.text("axes").value_or("linear");
  if (axes == "linear")
    s.axes = Axes::linear;
  else if (axes == "log-log")
    s.axes = Axes::log_log;
  else if (axes == "log-x")
    s.axes = Axes::log_x;
  else
    r.fail("axes", R"(expected "linear", "log-x" or "log-log")");
  return s;
}

}  // namespace detail

std::vector<PlannedPoint> plan_sweep(const Scene& scene, const Sweep& s, JobTable& jobs) {
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
    for (const double v : s.velocity_m_s) points.push_back(detail::physical_point(v, beta, k, task));
  }
  for (PlannedPoint& p : points) p.job = jobs.add(ContactLaw::natural(s.law, p.parameter), s.ends, false);
  return points;
}

SweepOutcome run_sweep_section(const SectionRunContext& context, const Sweep& s) {
  SweepOutcome out;
  out.points = context.points;
  std::vector<double> zeta;
  detail::PointResults results;
  for (const PlannedPoint& p : out.points) {
    zeta.push_back(p.parameter);
    out.results.push_back(context.solved[p.job]);
  }
  for (const CollisionResult& r : out.results) results.push_back(&r);
  SweepExtras& extras = out.extras;
  detail::add_approximations(s, zeta, extras);
  detail::compare_approximations(zeta, results, extras);
  detail::add_power_law_fits(s, zeta, results, extras);
  if (s.empirical) {
    std::vector<double> velocity_m_s;
    velocity_m_s.reserve(out.points.size());
    for (const PlannedPoint& p : out.points) velocity_m_s.push_back(*p.velocity_m_s);
    detail::add_empirical(*s.empirical, s.ends, velocity_m_s, results, extras);
  }
  return out;
}

}  // namespace restitution::scene
