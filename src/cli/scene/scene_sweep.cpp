// SPDX-License-Identifier: BSD-3-Clause
// A [[sweep]]'s table, figure, report paragraph and summary.json object.
#include <fmt/core.h>

#include <algorithm>
#include <string>
#include <vector>

#include "cli/scene/scene_planned_sections.hpp"
#include "cli/scene/scene_tables.hpp"
#include "cli/scene/scene_text.hpp"
#include "restitution/material.hpp"
#include "restitution/series.hpp"
#include "restitution/units.hpp"
#include "sweep/physical_columns.hpp"

namespace restitution::cli {
namespace {

// A markdown table of up to `limit` rows spread evenly over the table (first and last included).
std::string markdown_rows(const Table& t, const std::vector<std::string>& columns, std::size_t limit) {
  std::string out = "| " + join(columns, " | ") + " |";
  out += "\n|";
  for (std::size_t i = 0; i < columns.size(); ++i) out += "---|";
  out += "\n";
  const std::size_t n = t.rows.size();
  const std::size_t shown = std::min(n, limit);
  for (std::size_t k = 0; k < shown; ++k) {
    const std::size_t i = shown == 1 ? 0 : k * (n - 1) / (shown - 1);
    std::vector<std::string> cells;
    cells.reserve(columns.size());
    for (const auto& c : columns) cells.push_back(report_number(t.rows[i][t.column(c)]));
    out += "| " + join(cells, " | ") + " |\n";
  }
  if (shown < n) {
    out += fmt::format(
        "\n{} of {} rows shown, spread evenly from the first to the last; every row is in the CSV.\n", shown,
        n);
  }
  return out;
}

std::string describe_sweep(const scene::Scene& scene, const scene::Sweep& s,
                           const scene::SweepOutcome& outcome, const Table& t) {
  std::vector<std::string> names;
  for (const CollisionEnd e : s.ends.members()) names.emplace_back(end_name(e));
  const std::string ends = join(names, " and ");
  const auto& points = outcome.points;
  std::string what;
  if (s.velocity_m_s.empty()) {
    what = fmt::format("ε at the {} end for {} values of ζ from {} to {}", ends, t.rows.size(),
                       report_number(s.zeta.front()), report_number(s.zeta.back()));
    if (s.law != LawKind::viscoelastic_hertz) {
      what += fmt::format(" (law {}: x'' + ζ x^{} x' + x^{} = 0)", law_name(s.law),
                          report_number(law_exponents(s.law).damping),
                          report_number(law_exponents(s.law).elastic));
    }
  } else {
    std::string subject;
    if (s.beta) subject = fmt::format("β = {} s^(1/5) m^(-1/5)", report_number(*s.beta));
    if (s.characteristic_velocity_m_s) {
      subject = fmt::format(
          "the 1999 paper's characteristic velocity g* = {} m/s, i.e. β = (g*)^(-1/5)/C1 = {} "
          "s^(1/5) m^(-1/5) (C1 = {})",
          report_number(*s.characteristic_velocity_m_s), report_number(*points.front().beta),
          report_number(series::c1_closed_form()));
    }
    if (s.material) {
      const MaterialConstants c = material_constants(scene.materials.at(*s.material));
      subject = fmt::format(
          "material `{}`: R_eff = {} m, m_eff = {} kg, k = ρ/m_eff = {} s^-2 m^-1/2, A = {} s, "
          "β = {} s^(1/5) m^(-1/5), 1999 g* = {} m/s",
          *s.material, report_number(c.elastic.effective_radius_m),
          report_number(c.elastic.effective_mass_kg), report_number(c.hertz.k),
          report_number(c.dissipative_constant_s), report_number(c.hertz.beta),
          report_number(characteristic_velocity_m_s(c.hertz.beta)));
    }
    what = fmt::format("ε at the {} end for {} impact speeds from {} to {} m/s with {}; ζ = β v^(1/5)", ends,
                       t.rows.size(), report_number(s.velocity_m_s.front()),
                       report_number(s.velocity_m_s.back()), subject);
  }
  return fmt::format(
      "Computed: {}. Table `{}.csv` (times τ and compressions x in natural units, x'(0) = 1; columns "
      "ending "
      "in _s and _m are seconds and metres).\n\n",
      what, s.name);
}

void empirical_summary(const scene::Sweep& s, const scene::EmpiricalDeviation& d, std::string& report,
                       JsonWriter& json) {
  report += fmt::format(
      "Empirical law ε = {} (v / {} m/s)^{}: where it is below 1, the computed ε at the {} end deviates "
      "from "
      "it by at most {:.1f}% (at v = {} m/s).\n\n",
      report_number(s.empirical->coefficient), report_number(s.empirical->velocity_unit_m_s),
      report_number(s.empirical->exponent), end_name(d.end), 100.0 * d.max_relative_deviation,
      report_number(d.at_velocity_m_s));
  json.field("max_relative_deviation_from_empirical", d.max_relative_deviation)
      .field("at_velocity_m_s", d.at_velocity_m_s);
}

// The sweep's object of summary.json (and the empirical law's paragraph of the report).
void sweep_summary(const scene::Sweep& s, const scene::SweepExtras& extras, const Table& t,
                   const std::vector<std::string>& notes, std::string& report, JsonWriter& json) {
  json.key(s.name).begin_object();
  json.field("kind", "sweep")
      .field("points", static_cast<long>(t.rows.size()))
      .field("table", s.name + ".csv");
  json.key("notes").begin_array();
  for (const auto& n : notes) json.value(n);
  json.end_array();
  json.key("fits").begin_array();
  for (const auto& f : extras.fits) {
    json.begin_object();
    json.field("end", end_name(f.end)).field("prefactor", f.prefactor).field("exponent", f.exponent);
    json.field("exponent_uncertainty", f.exponent_uncertainty).field("points", static_cast<long>(f.points));
    json.end_object();
  }
  json.end_array();
  if (extras.empirical_deviation) empirical_summary(s, *extras.empirical_deviation, report, json);
  json.end_object();
}

}  // namespace

void write_sweep_section(const scene::Scene& scene, const scene::Sweep& s, const scene::SweepOutcome& outcome,
                         SectionOutput& out) {
  const scene::SweepExtras& extras = outcome.extras;
  const Table t = sweep_table(s, outcome);
  std::string report;
  out.file(s.name + ".csv", t.csv());
  const bool physical = !s.velocity_m_s.empty();
  const std::string x = physical ? "velocity_m_s" : "zeta";
  std::vector<std::string> eps_columns;
  for (const CollisionEnd e : s.ends.members()) {
    if (s.quantities.eps) eps_columns.push_back(std::string(end_key(e)) + "_eps");
  }
  std::vector<std::string> dashed;
  std::vector<std::string> differences;
  for (const auto& a : extras.approximations) {
    dashed.push_back(a.label + "_eps");
    differences.push_back(a.label + "_rel_diff");
  }
  if (s.empirical) dashed.emplace_back("empirical_eps");
  report += fmt::format("## {}\n\n", s.title);
  if (!eps_columns.empty()) {
    // No title in the figure: the section's heading carries it. x: scripts/plots/style.py names it.
    std::vector<std::string> args = {"--x", x, "--y", join(eps_columns), "--ylabel", R"($\varepsilon$)"};
    if (!dashed.empty()) args.insert(args.end(), {"--dashed", join(dashed)});
    if (!differences.empty()) args.insert(args.end(), {"--error", join(differences)});
    if (s.axes != scene::Axes::linear) args.insert(args.end(), {"--xscale", "log"});
    if (s.axes == scene::Axes::log_log) args.insert(args.end(), {"--yscale", "log"});
    report += out.plot("scene_xy", s.name, args);
  }
  report += describe_sweep(scene, s, outcome, t);
  if (!s.note.empty()) report += s.note + "\n\n";
  std::vector<std::string> shown = {"zeta"};
  if (physical) shown.emplace_back("velocity_m_s");
  shown.insert(shown.end(), eps_columns.begin(), eps_columns.end());
  for (std::size_t k = 0; k < differences.size(); ++k) {  // each approximation with its difference
    shown.push_back(dashed[k]);
    shown.push_back(differences[k]);
  }
  if (s.empirical) shown.emplace_back("empirical_eps");
  for (const CollisionEnd e : s.ends.members()) {
    const std::string c = duration_column(e);
    if (std::find(t.columns.begin(), t.columns.end(), c) != t.columns.end()) shown.push_back(c);
  }
  if (std::find(t.columns.begin(), t.columns.end(), "max_compression_m") != t.columns.end()) {
    shown.emplace_back("max_compression_m");
  }
  report += markdown_rows(t, shown, 9) + "\n";
  for (const auto& f : extras.fits) {
    report += fmt::format("Power-law fit at the {} end: eps ≈ {} · zeta^({} ± {}) over {} points.\n\n",
                          end_name(f.end), report_number(f.prefactor), report_number(f.exponent),
                          report_number(f.exponent_uncertainty), f.points);
  }
  for (const auto& a : extras.approximations) {
    report += fmt::format("* `{}`: {}; {}\n", a.label, approximation_source(a),
                          comparison_text(a.comparison, t.rows.size()));
  }
  if (!extras.approximations.empty()) report += "\n";
  std::vector<std::string> notes;
  for (const auto& f : extras.fit_shortfalls) notes.push_back(fit_shortfall_text(f));
  for (const auto& n : notes) report += "*" + n + "*\n\n";
  sweep_summary(s, extras, t, notes, report, out.summary());
  out.report(report);
}

}  // namespace restitution::cli
