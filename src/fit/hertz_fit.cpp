// SPDX-License-Identifier: BSD-3-Clause
// Viscoelastic Hertz: β by weighted least squares on the certified fast table (ε at ζ = β v^{1/5}), over
// u = ln β. A grid brackets the minimum of χ²(u), Brent's method narrows it, and the root of dχ²/du
// polishes it to full precision (a minimiser alone stops at sqrt(machine ε) in u). The intervals are the
// roots of χ²(u) - χ²_min - Δ on either side, Δ from fit_detail::Problem (scaled by χ²_min/dof when σ is
// estimated).
#include <fmt/core.h>

#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>

#include "fit/fit_internal.hpp"
#include "restitution/fast.hpp"
#include "restitution/units.hpp"

namespace restitution::fit_detail {
namespace {

// The grid spans this many e-folds of β below the edge of the checked range: ζ from 1e6 down to 1e-20.
constexpr double kSpan = 60.0;
constexpr double kGridStep = 0.5;

class HertzChi2 {
 public:
  HertzChi2(const Problem& problem, CollisionEnd end) : problem_(problem), end_(end) {
    const FitData& d = *problem.data;
    // ζ = β v^{1/5} is linear in β: each point's ζ per unit β, computed once.
    zeta_per_beta_.reserve(d.velocity_m_s.size());
    for (const double v : d.velocity_m_s) zeta_per_beta_.push_back(zeta_from(1.0, v));
    const double largest = *std::max_element(zeta_per_beta_.begin(), zeta_per_beta_.end());
    u_high_ = std::log(kLargestCheckedZeta / largest);
  }

  [[nodiscard]] double u_high() const { return u_high_; }
  [[nodiscard]] double u_low() const { return u_high_ - kSpan; }

  [[nodiscard]] double operator()(double u) const { return chi2_of_beta(std::exp(u)); }
  [[nodiscard]] double chi2_of_beta(double beta) const {
    double sum = 0.0;
    for (std::size_t i = 0; i < zeta_per_beta_.size(); ++i) {
      const double r = problem_.data->eps[i] - fast::eps(beta * zeta_per_beta_[i], end_);
      sum += problem_.weight[i] * r * r;
    }
    return sum;
  }
  // dχ²/du = -2 Σ w r dε/d ln ζ, the derivative by a central difference in ln ζ (its error only moves the
  // root by the residuals times that error: nothing for exact data, far below the interval otherwise).
  [[nodiscard]] double slope(double u) const {
    constexpr double h = 1e-4;
    const double beta = std::exp(u);
    double sum = 0.0;
    for (std::size_t i = 0; i < zeta_per_beta_.size(); ++i) {
      const double zeta = beta * zeta_per_beta_[i];
      const double r = problem_.data->eps[i] - fast::eps(zeta, end_);
      const double d = (fast::eps(zeta * std::exp(h), end_) - fast::eps(zeta * std::exp(-h), end_)) / (2 * h);
      sum += problem_.weight[i] * r * d;
    }
    return -2.0 * sum;
  }
  [[nodiscard]] std::vector<double> model(double beta) const {
    std::vector<double> out;
    out.reserve(zeta_per_beta_.size());
    for (const double f : zeta_per_beta_) out.push_back(fast::eps(beta * f, end_));
    return out;
  }

 private:
  const Problem& problem_;
  CollisionEnd end_;
  std::vector<double> zeta_per_beta_;
  double u_high_ = 0.0;
};

// The minimum of χ²(u) on [u_low, u_high]: grid, Brent, then the root of the slope.
double minimise(const HertzChi2& chi2) {
  const auto steps = static_cast<int>(kSpan / kGridStep);
  int best = 0;
  double best_value = chi2(chi2.u_low());
  for (int k = 1; k <= steps; ++k) {
    const double value = chi2(chi2.u_low() + k * kGridStep);
    if (value < best_value) {
      best = k;
      best_value = value;
    }
  }
  const double lo = chi2.u_low() + std::max(best - 1, 0) * kGridStep;
  const double hi = std::min(chi2.u_low() + (best + 1) * kGridStep, chi2.u_high());
  std::uintmax_t iterations = 200;
  const double u = boost::math::tools::brent_find_minima(chi2, lo, hi, 40, iterations).first;
  // Polish: a bracket of the slope's sign change around u.
  double width = 1e-6;
  for (int attempt = 0; attempt < 8; ++attempt, width *= 8.0) {
    const double a = std::max(u - width, lo);
    const double b = std::min(u + width, hi);
    const double fa = chi2.slope(a);
    const double fb = chi2.slope(b);
    if (fa <= 0.0 && fb >= 0.0) {
      if (fa == 0.0) return a;
      if (fb == 0.0) return b;
      iterations = 200;
      const auto [r1, r2] =
          boost::math::tools::toms748_solve([&](double x) { return chi2.slope(x); }, a, b, fa, fb,
                                            boost::math::tools::eps_tolerance<double>(50), iterations);
      return 0.5 * (r1 + r2);
    }
  }
  return u;  // no sign change (a flat χ²): Brent's value
}

// The bound where χ²(u) = target, searched from u_best towards `direction` (+1 or -1). Returns nullopt when
// χ² stays below the target up to the end of the range.
std::optional<double> profile_root(const HertzChi2& chi2, double u_best, double target, int direction) {
  const double limit = direction > 0 ? chi2.u_high() : chi2.u_low();
  double inner = u_best;
  double step = 0.02;
  while (true) {
    double outer = u_best + direction * step;
    if (direction * (outer - limit) >= 0.0) outer = limit;
    const double f_outer = chi2(outer) - target;
    if (f_outer >= 0.0) {
      std::uintmax_t iterations = 200;
      const double f_inner = chi2(inner) - target;
      const auto [r1, r2] = boost::math::tools::toms748_solve(
          [&](double x) { return chi2(x) - target; }, std::min(inner, outer), std::max(inner, outer),
          direction > 0 ? f_inner : f_outer, direction > 0 ? f_outer : f_inner,
          boost::math::tools::eps_tolerance<double>(50), iterations);
      return 0.5 * (r1 + r2);
    }
    if (outer == limit) return std::nullopt;
    inner = outer;
    step *= 2.0;
  }
}

FitInterval interval(const HertzChi2& chi2, double u_best, double chi2_min, double delta) {
  const double target = chi2_min + delta;
  FitInterval out;
  if (const auto high = profile_root(chi2, u_best, target, +1)) {
    out.high = std::exp(*high);
  } else {
    set_edge_high(out);
  }
  // Below the grid β is ~1e-26 of the edge's: if χ² stays below the target there, the bound is β = 0 (ζ = 0,
  // elastic spheres, a point of the checked range).
  const auto low = profile_root(chi2, u_best, target, -1);
  out.low = low ? std::exp(*low) : 0.0;
  return out;
}

}  // namespace

void fit_hertz(const Problem& problem, LawFit& fit) {
  const HertzChi2 chi2(problem, fit.candidate.end);
  const double u = minimise(chi2);
  const double beta = std::exp(u);
  fit.model_eps = chi2.model(beta);
  fit.chi2 = chi2(u);
  const double grid_tolerance = 1e-6;
  if (u >= chi2.u_high() - grid_tolerance) {
    fit.status = FitStatus::at_edge;
    fit.message = fmt::format(
        "the best beta lies at zeta = {:g} for the largest speed, the edge of the checked "
        "range: the data are more dissipative than the law can describe there",
        kLargestCheckedZeta);
    set_edge_high(fit.ci68);
    set_edge_high(fit.ci95);
    return;
  }
  if (u <= chi2.u_low() + grid_tolerance) {
    fit.status = FitStatus::at_edge;
    fit.message = "the best beta is 0 (elastic spheres): the data show no dissipation this law can fit";
    return;
  }
  fit.status = FitStatus::converged;
  fit.value = beta;
  const double scale = problem.sigma_estimated ? fit.chi2 / static_cast<double>(problem.size() - 1) : 1.0;
  fit.ci68 = interval(chi2, u, fit.chi2, problem.delta68 * scale);
  fit.ci95 = interval(chi2, u, fit.chi2, problem.delta95 * scale);
}

}  // namespace restitution::fit_detail
