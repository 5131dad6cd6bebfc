// SPDX-License-Identifier: BSD-3-Clause
#include "analysis/stability_report.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "restitution/errors.hpp"

namespace restitution {
namespace {

double small_part(const EndResult& r) {
  return r.eps < 0.5 ? r.eps : r.one_minus_eps;
}

void record_failure(const std::exception& e, EngineCheck& check) {
  const std::string what = e.what();
  // The solver's step bound (SolveOptions::max_steps_per_phase) was reached, or the engine refuses the stiff
  // tail it could not finish (method adams on the naive end beyond kAdamsNaiveZetaMax).
  if (what.find("too much work") != std::string::npos || what.find("is stiff") != std::string::npos) {
    check.failure = EngineFailure::too_much_work;
  } else {
    check.failure = EngineFailure::other;
    check.failure_message = what;
  }
}

double decade_of(double zeta) {
  return zeta > 0.0 ? std::pow(10.0, std::floor(std::log10(zeta) + 1e-12)) : 0.0;
}

StabilityPoint check_point(CollisionSolver& solver, double zeta, CollisionEnd end,
                           const StabilityOptions& o) {
  const ContactLaw law = ContactLaw::hertz_natural(zeta);
  SolveOptions options;
  options.tolerance = o.tolerance;
  options.ends = EndSet{end};
  const CollisionResult production = solver.solve(law, options);
  StabilityPoint p;
  p.zeta = zeta;
  p.end = end;
  p.method = production.method;
  p.result = end_of(production, end);
  p.steps = production.stats.steps;
  p.rhs_evaluations = production.stats.rhs_evaluations;

  SolveOptions tight = options;
  // At the smallest tolerance accepted, 100 kMinTolerance (9.999999999999999e-10 in doubles), the quotient is
  // an ulp below kMinTolerance, which the engine refuses.
  tight.tolerance = std::max(o.tolerance / 100.0, kMinTolerance);
  tight.method = production.method;
  p.self_convergence = relative_difference(p.result, end_of(solver.solve(law, tight), end));
  if (p.self_convergence > o.tolerance)
    p.flags.push_back({StabilityFlagKind::self_convergence, production.method, p.self_convergence});

  for (const Method method : kCrossCheckedMethods) {
    EngineCheck check;
    check.method = method;
    if (method == production.method) {
      check.solved = true;
      check.steps = production.stats.steps;
    } else {
      SolveOptions other = options;
      other.method = method;
      other.max_steps_per_phase = o.max_steps_per_phase;
      try {
        const CollisionResult r = solver.solve(law, other);
        check.solved = true;
        check.steps = r.stats.steps;
        check.relative_difference = relative_difference(end_of(r, end), p.result);
      } catch (const NumericalFailure& e) {
        record_failure(e, check);
      } catch (const InvalidInput& e) {
        record_failure(e, check);
      }
    }
    // Each result is within T/3 of the truth by contract, so two engines may differ by up to 2T/3.
    if (check.solved && check.relative_difference > o.tolerance)
      p.flags.push_back({StabilityFlagKind::engine_difference, method, check.relative_difference});
    p.engines.push_back(check);
  }
  return p;
}

std::vector<DecadeSummary> summarize(const std::vector<StabilityPoint>& points) {
  std::vector<DecadeSummary> decades;
  for (const StabilityPoint& p : points) {
    const double decade = decade_of(p.zeta);
    auto it = std::find_if(decades.begin(), decades.end(),
                           [&](const DecadeSummary& d) { return d.decade == decade && d.end == p.end; });
    if (it == decades.end()) {
      decades.push_back({decade, p.end});
      it = std::prev(decades.end());
    }
    it->worst_self_convergence = std::max(it->worst_self_convergence, p.self_convergence);
    for (const EngineCheck& e : p.engines) {
      if (e.solved)
        it->worst_engine_difference = std::max(it->worst_engine_difference, e.relative_difference);
      else
        ++it->engine_failures;
    }
  }
  return decades;
}

}  // namespace

int StabilityReport::flagged() const {
  return static_cast<int>(
      std::count_if(points.begin(), points.end(), [](const StabilityPoint& p) { return !p.flags.empty(); }));
}

std::vector<double> stability_grid(int points_per_decade) {
  if (points_per_decade < 1 || points_per_decade > kMaxStabilityPointsPerDecade)
    throw InvalidInput(fmt::format("--points-per-decade must lie in [1, {}], got {}",
                                   kMaxStabilityPointsPerDecade, points_per_decade));
  std::vector<double> grid{0.0};
  constexpr int kFirstDecade = -12;
  constexpr int kLastDecade = 6;
  for (int k = kFirstDecade; k < kLastDecade; ++k)
    for (int j = 0; j < points_per_decade; ++j)
      grid.push_back(std::pow(10.0, k + static_cast<double>(j) / points_per_decade));
  grid.push_back(std::pow(10.0, kLastDecade));
  return grid;
}

double relative_difference(const EndResult& value, const EndResult& reference) {
  const double difference = std::abs(small_part(value) - small_part(reference));
  if (difference == 0.0) return 0.0;
  return difference / std::abs(small_part(reference));
}

StabilityReport stability_report(const std::vector<double>& zetas, const StabilityOptions& options) {
  if (!(options.tolerance >= 100.0 * kMinTolerance && options.tolerance <= kMaxTolerance))
    throw InvalidInput(
        fmt::format("stability --tolerance must lie in [{:g}, {:g}] (the check tightens it 100x), got {}",
                    100.0 * kMinTolerance, kMaxTolerance, options.tolerance));
  StabilityReport report;
  report.tolerance = options.tolerance;
  CollisionSolver solver;
  for (std::size_t i = 0; i < zetas.size(); ++i) {
    const double zeta = zetas[i];
    if (!(zeta >= 0.0) || !std::isfinite(zeta))
      throw InvalidInput(fmt::format("stability: zeta must be finite and >= 0, got {}", zeta));
    for (const CollisionEnd end : {CollisionEnd::naive, CollisionEnd::delayed_recovery})
      report.points.push_back(check_point(solver, zeta, end, options));
    if (options.progress) options.progress(i + 1, zetas.size());
  }
  report.decades = summarize(report.points);
  return report;
}

}  // namespace restitution
