// SPDX-License-Identifier: BSD-3-Clause
// Series and approximations against the solver on a log grid of ζ; convergence radii of the series.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "restitution/collision_solver.hpp"
#include "restitution/errors.hpp"
#include "restitution_series_study/series_coefficients.hpp"
#include "restitution_series_study/series_named.hpp"
#include "restitution_series_study/series_validation.hpp"
#include "series/published_tables.hpp"

namespace restitution::series {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kThresholds[] = {1e-3, 1e-6, 1e-10};
constexpr double kLargeZeta = 1e3;
constexpr double kLargeZetaStep = 1.1;

struct Approximant {
  Candidate candidate;
  std::function<Value(double)> evaluate;
};

std::vector<double> tail(const std::vector<double>& v, std::size_t from) {
  return {v.begin() + static_cast<std::ptrdiff_t>(from), v.end()};
}

std::vector<Approximant> approximants(const ValidationOptions& o, const Coefficients& computed) {
  std::vector<double> c = tail(computed.c, 1);
  c.resize(static_cast<std::size_t>(o.naive_order));
  std::vector<double> h = computed.h;
  h.resize(static_cast<std::size_t>(o.delayed_order) + 1);
  const Pade1999 corrected = pade_1999_corrected();
  const Pade1999 printed = pade_1999_published();
  return {
      {{"naive-series:published", CollisionEnd::naive,
        "naive series, c_1..c_10 of the 2008 paper's Table III"},
       [](double z) { return naive_series(z, published::kTable3C); }},
      {{fmt::format("naive-series:computed-{}", o.naive_order), CollisionEnd::naive,
        fmt::format("naive series, recomputed c_1..c_{}", o.naive_order)},
       [c](double z) { return naive_series(z, c); }},
      {{"delayed-recovery-series:published", CollisionEnd::delayed_recovery,
        "delayed-recovery series, h_0..h_20 of the 2008 paper's Table V"},
       [](double z) { return delayed_recovery_series(z, published::kTable5H); }},
      {{fmt::format("delayed-recovery-series:computed-{}", o.delayed_order), CollisionEnd::delayed_recovery,
        fmt::format("delayed-recovery series, recomputed h_0..h_{}", o.delayed_order)},
       [h](double z) { return delayed_recovery_series(z, h); }},
      {{"pade-1999", CollisionEnd::naive,
        "1999 Padé [1/4] in w = C1 zeta, d_k from Table I with a_3, a_4 of Eq. (33)"},
       [printed](double z) { return pade_1999(z, printed); }},
      {{"pade-1999-corrected", CollisionEnd::naive,
        "1999 Padé [1/4] form (Table I) with the recomputed a_3, a_4"},
       [corrected](double z) { return pade_1999(z, corrected); }},
      {{"simple-theory-1999", CollisionEnd::naive, "1999 simple theory eps + w eps^{3/5} = 1 (Eq. 27)"},
       [](double z) { return simple_theory_1999(z); }},
      {{"pade-2011-1-4", CollisionEnd::delayed_recovery, "Mueller & Poeschel 2011 Padé [1/4] in sqrt(zeta)"},
       [](double z) { return pade_2011_1_4(z); }},
      {{"pade-2011-3-6", CollisionEnd::delayed_recovery, "Mueller & Poeschel 2011 Padé [3/6] in sqrt(zeta)"},
       [](double z) { return pade_2011_3_6(z); }},
  };
}

std::vector<double> log_grid(const ValidationOptions& o) {
  if (!(o.zeta_min > 0.0) || !(o.zeta_max > o.zeta_min) || !std::isfinite(o.zeta_max))
    throw InvalidInput(
        fmt::format("validation grid needs 0 < zeta_min < zeta_max, got [{}, {}]", o.zeta_min, o.zeta_max));
  if (o.points_per_decade < 1) throw InvalidInput("validation points_per_decade must be >= 1");
  const double decades = std::log10(o.zeta_max / o.zeta_min);
  const int intervals = std::max(1, static_cast<int>(std::ceil(decades * o.points_per_decade - 1e-9)));
  std::vector<double> grid;
  for (int i = 0; i <= intervals; ++i) grid.push_back(o.zeta_min * std::pow(10.0, decades * i / intervals));
  grid.back() = o.zeta_max;  // the number asked for, not its rounded exp(log(...))
  return grid;
}

Value to_value(const EndResult& e) {
  return {e.eps, e.one_minus_eps};
}

PointError compare(const Value& approximation, const Value& reference) {
  return {approximation, std::abs(approximation.eps - reference.eps) / reference.eps,
          std::abs(approximation.one_minus_eps - reference.one_minus_eps) / reference.one_minus_eps};
}

double local_slope(double step, double eps_at_zeta, double eps_at_step) {
  if (!(eps_at_zeta > 0.0) || !(eps_at_step > 0.0)) return kNaN;
  return std::log(eps_at_step / eps_at_zeta) / std::log(step);
}

Approximation closed_form_kind(const std::string& name) {
  return *approximation_named(name.substr(0, name.find(':')));  // every candidate is named so
}

// Least-squares line y = intercept + slope x.
std::pair<double, double> fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  const auto n = static_cast<double>(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sx += x[i];
    sy += y[i];
    sxx += x[i] * x[i];
    sxy += x[i] * y[i];
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  return {(sy - slope * sx) / n, slope};
}

}  // namespace

RadiusEstimate estimate_radius(const std::string& name, const std::vector<double>& coef, bool in_sqrt_zeta) {
  const int n = static_cast<int>(coef.size()) - 1;
  if (n < 6) throw InvalidInput("radius estimate needs at least 7 coefficients of " + name);
  const double power = in_sqrt_zeta ? 2.0 : 1.0;
  RadiusEstimate r;
  r.series = name;
  r.terms = n;
  r.ratio = std::pow(std::abs(coef[n - 1] / coef[n]), power);
  double root = std::numeric_limits<double>::infinity();
  for (int k = n - n / 3; k <= n; ++k)
    if (coef[k] != 0.0) root = std::min(root, std::pow(std::abs(coef[k]), -1.0 / k));
  r.root = std::pow(root, power);
  // Ratio and Domb-Sykes need a regular sign pattern (constant or alternating: a singularity on the real
  // axis); complex singularities make the ratios oscillate and only the root test applies.
  bool same = true, alternating = true;
  for (int k = n / 2 + 1; k <= n; ++k) {
    same = same && coef[k] * coef[k - 1] > 0.0;
    alternating = alternating && coef[k] * coef[k - 1] < 0.0;
  }
  if (!same && !alternating) {
    r.ratio = r.domb_sykes = r.domb_sykes_slope = kNaN;
    return r;
  }
  std::vector<double> inverse_k, ratios;
  for (int k = n / 2; k <= n; ++k) {
    if (coef[k - 1] == 0.0) continue;
    inverse_k.push_back(1.0 / k);
    ratios.push_back(coef[k] / coef[k - 1]);
  }
  const auto [intercept, slope] = fit_line(inverse_k, ratios);
  r.domb_sykes = std::pow(1.0 / std::abs(intercept), power);
  r.domb_sykes_slope = slope;
  return r;
}

ValidationReport validate(const ValidationOptions& options) {
  if (options.naive_order < 1 || options.naive_order > kMaxOrder || options.delayed_order < 1 ||
      options.delayed_order > 2 * kMaxOrder)
    throw InvalidInput(fmt::format("validation orders out of range: naive {} (1..{}), delayed {} (1..{})",
                                   options.naive_order, kMaxOrder, options.delayed_order, 2 * kMaxOrder));
  ValidationReport report;
  report.options = options;
  const Coefficients computed =
      compute_coefficients(std::max(options.naive_order, (options.delayed_order + 1) / 2));
  const std::vector<Approximant> approx = approximants(options, computed);
  for (const Approximant& a : approx) report.candidates.push_back(a.candidate);

  CollisionSolver solver;
  SolveOptions solve;
  solve.tolerance = options.tolerance;
  auto reference = [&](double zeta) { return solver.solve(ContactLaw::hertz_natural(zeta), solve); };
  for (const double zeta : log_grid(options)) {
    const CollisionResult r = reference(zeta);
    ValidationRow row{zeta, {}, {}};
    for (const CollisionEnd end : kCollisionEnds) row.solver[end] = to_value(*r[end]);
    for (const Approximant& a : approx)
      row.errors.push_back(compare(a.evaluate(zeta), row.solver[a.candidate.end]));
    report.rows.push_back(std::move(row));
  }

  const CollisionResult at = reference(kLargeZeta);
  const CollisionResult after = reference(kLargeZeta * kLargeZetaStep);
  for (std::size_t i = 0; i < approx.size(); ++i) {
    CandidateSummary s;
    for (const double threshold : kThresholds) {
      Crossing c{threshold, kNaN, kNaN};
      for (const ValidationRow& row : report.rows) {
        if (std::isnan(c.zeta_eps) && !(row.errors[i].relative_error_eps <= threshold)) c.zeta_eps = row.zeta;
        if (std::isnan(c.zeta_one_minus_eps) && !(row.errors[i].relative_error_one_minus <= threshold))
          c.zeta_one_minus_eps = row.zeta;
      }
      s.crossings.push_back(c);
    }
    const EndResult& e0 = *at[approx[i].candidate.end];
    const EndResult& e1 = *after[approx[i].candidate.end];
    s.large_zeta.solver_slope = local_slope(kLargeZetaStep, e0.eps, e1.eps);
    s.large_zeta.approximation_slope = local_slope(kLargeZetaStep, approx[i].evaluate(kLargeZeta).eps,
                                                   approx[i].evaluate(kLargeZeta * kLargeZetaStep).eps);
    s.large_zeta.implied_exponent = implied_large_zeta_exponent(closed_form_kind(approx[i].candidate.name));
    report.summaries.push_back(s);
  }

  report.radii.push_back(estimate_radius("a", computed.a, false));
  report.radii.push_back(estimate_radius("b", computed.b, false));
  report.radii.push_back(estimate_radius("c", computed.c, false));
  report.radii.push_back(estimate_radius("h", computed.h, true));
  if (computed.v.size() >= 8) report.radii.push_back(estimate_radius("v", computed.v, false));
  return report;
}

}  // namespace restitution::series
