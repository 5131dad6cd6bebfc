// SPDX-License-Identifier: BSD-3-Clause
#include "reference/work_precision.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <tuple>
#include <utility>

#include "restitution/errors.hpp"
#include "taylor/taylor_engine.hpp"

namespace restitution {
namespace {

bool accepts(const WorkPrecisionEngine& engine, CollisionEnd end, double zeta) {
  if (engine.method == Method::adams && zeta > 100.0) return false;
  if (engine.method == Method::taylor && end == CollisionEnd::naive && zeta > kTaylorNaiveZetaMax)
    return false;
  return true;
}

}  // namespace

const ReferenceRow* reference_row_for(const std::vector<ReferenceRow>& reference, double zeta) {
  for (const ReferenceRow& row : reference)
    if (std::abs(row.zeta - zeta) <= 1e-12 * zeta) return &row;
  return nullptr;
}

double contract_error(const EndResult& result, const ReferenceEndValues& reference) {
  const double scale = std::min(reference.eps, reference.one_minus_eps);
  // ε is a double: near ε = 1 its spacing (1.1e-16) can exceed T·(1-ε), so one spacing of the reference ε
  // is not counted against it (1-ε carries the full accuracy there).
  const double spacing = std::nextafter(reference.eps, 2.0) - reference.eps;
  const double eps_error = std::max(std::abs(result.eps - reference.eps) - spacing, 0.0);
  const double difference = std::max(eps_error, std::abs(result.one_minus_eps - reference.one_minus_eps));
  return scale > 0 ? difference / scale : difference;
}

SolveOptions work_precision_options(const WorkPrecisionEngine& engine, CollisionEnd end, double tolerance) {
  SolveOptions options;
  options.method = engine.method;
  options.smooth_ends = engine.smooth_ends;
  options.tolerance = tolerance;
  options.ends = EndSet{end};
  return options;
}

std::vector<WorkPrecisionEngine> work_precision_engines() {
  // The methods by their names; "-plain": integrated in τ throughout (SolveOptions::smooth_ends = false).
  std::vector<WorkPrecisionEngine> engines;
  for (const Method method : {Method::taylor, Method::bdf, Method::adams}) {
    engines.push_back({method_name(method), method, true});
  }
  for (const Method method : {Method::bdf, Method::adams}) {
    engines.push_back({std::string(method_name(method)) + "-plain", method, false});
  }
  return engines;
}

bool is_work_precision_engine(const std::string& name) {
  const std::vector<WorkPrecisionEngine> all = work_precision_engines();
  return std::any_of(all.begin(), all.end(), [&](const WorkPrecisionEngine& e) { return e.name == name; });
}

std::string work_precision_engine_names() {
  std::string names;
  for (const WorkPrecisionEngine& e : work_precision_engines()) names += (names.empty() ? "" : ", ") + e.name;
  return names;
}

std::vector<double> work_precision_zetas() {
  std::vector<double> z;
  for (int k = -4; k <= 4; ++k) z.push_back(std::pow(10.0, k));
  return z;
}

std::vector<double> work_precision_tolerances() {
  std::vector<double> t;
  for (int k = 4; k <= 13; ++k) t.push_back(std::pow(10.0, -k));
  return t;
}

std::vector<WorkPrecisionRow> measure_work_precision(
    const std::vector<ReferenceRow>& reference, int repeats, const std::vector<std::string>& engines,
    const std::function<void(std::size_t done, std::size_t total)>& progress) {
  const std::vector<WorkPrecisionEngine> all = work_precision_engines();
  for (const std::string& name : engines) {
    if (!is_work_precision_engine(name))
      throw InvalidInput(fmt::format("unknown engine '{}' (known: {})", name, work_precision_engine_names()));
  }
  const auto measured = [&engines](const WorkPrecisionEngine& engine) {
    return engines.empty() || std::find(engines.begin(), engines.end(), engine.name) != engines.end();
  };
  std::size_t groups = 0;  // (engine, end, tolerance) triples, the unit of progress
  for (const WorkPrecisionEngine& engine : all) {
    if (!measured(engine)) continue;
    for (const double tolerance : work_precision_tolerances())
      groups += tolerance < min_tolerance(engine.method) ? 0 : 2;
  }
  std::size_t done = 0;
  std::vector<WorkPrecisionRow> rows;
  CollisionSolver solver;
  std::vector<double> samples(static_cast<std::size_t>(std::max(repeats, 1)));
  for (const WorkPrecisionEngine& engine : all) {
    if (!measured(engine)) continue;
    for (const CollisionEnd end : {CollisionEnd::delayed_recovery, CollisionEnd::naive}) {
      for (const double tolerance : work_precision_tolerances()) {
        if (tolerance < min_tolerance(engine.method)) continue;
        if (progress) progress(done, groups);
        ++done;
        for (const double zeta : work_precision_zetas()) {
          const ReferenceRow* row = reference_row_for(reference, zeta);
          if (row == nullptr || !accepts(engine, end, zeta)) continue;
          const auto& ref = row->ends[end];
          if (!ref) continue;
          const SolveOptions options = work_precision_options(engine, end, tolerance);
          const ContactLaw law = ContactLaw::hertz_natural(zeta);
          CollisionResult result = solver.solve(law, options);
          for (double& sample : samples) {
            const auto start = std::chrono::steady_clock::now();
            result = solver.solve(law, options);
            sample = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          }
          std::nth_element(samples.begin(), samples.begin() + static_cast<long>(samples.size() / 2),
                           samples.end());
          rows.push_back({engine.name, end_name(end), tolerance, zeta, contract_error(*result[end], *ref),
                          samples[samples.size() / 2], result.stats.rhs_evaluations, result.stats.steps});
        }
      }
    }
  }
  if (progress) progress(done, groups);
  return rows;
}

std::vector<WorkPrecisionGroup> group_work_precision(const std::vector<WorkPrecisionRow>& rows) {
  std::map<std::tuple<std::string, std::string, double>, WorkPrecisionGroup> groups;
  for (const WorkPrecisionRow& r : rows) {
    WorkPrecisionGroup& g = groups[{r.engine, r.end, -r.tolerance}];
    g.engine = r.engine;
    g.end = r.end;
    g.tolerance = r.tolerance;
    g.max_error = std::max(g.max_error, r.error);
    g.mean_median_seconds += r.median_seconds;
    g.max_median_seconds = std::max(g.max_median_seconds, r.median_seconds);
    ++g.points;
  }
  std::vector<WorkPrecisionGroup> out;
  for (auto& [key, g] : groups) {
    g.mean_median_seconds /= g.points;
    out.push_back(std::move(g));
  }
  return out;
}

}  // namespace restitution
