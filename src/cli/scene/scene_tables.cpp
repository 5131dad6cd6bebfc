// SPDX-License-Identifier: BSD-3-Clause
#include "cli/scene/scene_tables.hpp"

#include <fmt/core.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "restitution/units.hpp"
#include "scene/scene_run.hpp"
#include "sweep/number_text.hpp"
#include "sweep/physical_columns.hpp"

namespace restitution::cli {
namespace {

constexpr double kNone = std::numeric_limits<double>::quiet_NaN();

}  // namespace

std::string Table::csv() const {
  std::string out;
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (i != 0) out += ',';
    out += columns[i];
  }
  out += '\n';
  for (const auto& row : rows) {
    for (std::size_t i = 0; i < row.size(); ++i) {
      if (i != 0) out += ',';
      out += number17(row[i]);
    }
    out += '\n';
  }
  return out;
}

std::size_t Table::column(const std::string& name) const {
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (columns[i] == name) return i;
  }
  throw std::logic_error("no column " + name);
}

Table sweep_table(const scene::Sweep& s, const scene::SweepOutcome& outcome) {
  const auto& points = outcome.points;
  const scene::SweepExtras& extras = outcome.extras;
  const bool physical = !s.velocity_m_s.empty();
  const bool si = physical && points.front().k.has_value();
  const auto ends = s.ends.members();
  const scene::Quantities& q = s.quantities;

  Table t;
  t.columns = {"zeta"};
  if (physical) t.columns.insert(t.columns.end(), velocity_columns().begin(), velocity_columns().end());
  for (const CollisionEnd e : ends) {
    const std::string n = end_key(e);
    if (q.eps) t.columns.push_back(n + "_eps");
    if (q.one_minus_eps) t.columns.push_back(n + "_one_minus_eps");
    if (q.duration) t.columns.push_back(n + "_tau");
    if (q.duration && si) t.columns.push_back(duration_column(e));
  }
  if (q.max_compression) {
    t.columns.insert(t.columns.end(), {"max_compression_tau", "max_compression_x"});
    if (si) {
      const auto& si_columns = si_max_compression_columns();
      t.columns.insert(t.columns.end(), si_columns.begin(), si_columns.end());
    }
  }
  for (const auto& a : extras.approximations) {
    t.columns.push_back(a.label + "_eps");
    t.columns.push_back(a.label + "_rel_diff");
  }
  if (s.empirical) t.columns.emplace_back("empirical_eps");

  for (std::size_t i = 0; i < points.size(); ++i) {
    const scene::PlannedPoint& p = points[i];
    const CollisionResult* r = &outcome.results[i];
    const NaturalScales scales = si ? natural_scales(*p.k, *p.velocity_m_s) : NaturalScales{};
    std::vector<double> row = {p.parameter};
    if (physical) row.insert(row.end(), {*p.velocity_m_s, *p.beta});
    for (const CollisionEnd e : ends) {
      const EndResult* end = scene::end_if_computed(r, e);
      const bool found = end != nullptr;
      if (q.eps) row.push_back(found ? end->eps : kNone);
      if (q.one_minus_eps) row.push_back(found ? end->one_minus_eps : kNone);
      if (q.duration) row.push_back(found ? end->tau : kNone);
      if (q.duration && si) row.push_back(found ? duration_s(*end, scales) : kNone);
    }
    if (q.max_compression) {
      row.insert(row.end(), {r->max_compression.tau, r->max_compression.x});
      if (si) {
        const std::vector<double> values = si_max_compression(r->max_compression, scales);
        row.insert(row.end(), values.begin(), values.end());
      }
    }
    for (const auto& a : extras.approximations) row.insert(row.end(), {a.eps[i], a.relative_difference[i]});
    if (s.empirical) row.push_back(extras.empirical_eps[i]);
    t.rows.push_back(std::move(row));
  }
  return t;
}

Table trajectory_table(const scene::TrajectoryOutcome& outcome) {
  const scene::PlannedPoint& p = outcome.point;
  const CollisionResult& r = outcome.result;
  const bool si = p.k.has_value();
  const NaturalScales scales = si ? natural_scales(*p.k, *p.velocity_m_s) : NaturalScales{};
  Table t;
  t.columns = {"tau", "x", "velocity", "acceleration"};
  if (si) t.columns.insert(t.columns.end(), {"time_s", "compression_m"});
  // The shared solve may run past this trajectory's last requested end (another task asked for more).
  for (const TrajectoryPoint& point : r.trajectory) {
    std::vector<double> row = {point.tau, point.x, point.velocity, point.acceleration};
    if (si) row.insert(row.end(), {point.tau * scales.time_s, point.x * scales.length_m});
    t.rows.push_back(std::move(row));
  }
  return t;
}

Table dashpot_table(const scene::DashpotCheck& d, const scene::DashpotOutcome& outcome) {
  Table t;
  t.columns = {"damping_ratio"};
  const auto ends = d.ends.members();
  for (const CollisionEnd e : ends) {
    const std::string n = end_key(e);
    t.columns.insert(t.columns.end(), {n + "_eps", n + "_eps_exact", n + "_relative_error"});
  }
  for (const scene::DashpotPoint& p : outcome.points) {
    std::vector<double> row = {p.damping_ratio};
    for (const CollisionEnd e : ends) {
      const auto& check = p.ends[e];
      if (check)
        row.insert(row.end(), {check->eps, check->eps_exact, check->relative_error});
      else
        row.insert(row.end(), {kNone, kNone, kNone});
    }
    t.rows.push_back(std::move(row));
  }
  return t;
}

std::string report_number(double v) {
  return std::isfinite(v) ? fmt::format("{:.10g}", v) : "—";
}

std::string join(const std::vector<std::string>& items, const char* separator) {
  std::string out;
  for (const auto& item : items) {
    if (!out.empty()) out += separator;
    out += item;
  }
  return out;
}

}  // namespace restitution::cli
