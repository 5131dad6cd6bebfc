// SPDX-License-Identifier: BSD-3-Clause
// Tests of the residuals against ln v (restitution/fit.hpp ResidualTests): a weighted straight line and a
// runs test on the signs. Where data leave a viscoelastic law they do so at one end of the speed range
// (plasticity or fracture at high speed, adhesion at low speed; 1999 paper §V on ice), so the residuals
// acquire a trend in ln v.
#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <numeric>

#include "fit/fit_internal.hpp"

namespace restitution::fit_detail {
namespace {

void slope_test(const Problem& problem, const std::vector<double>& residual, ResidualTests& out) {
  const FitData& d = *problem.data;
  const std::size_t n = problem.size();
  double w_total = 0.0;
  double x_mean = 0.0;
  double r_mean = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    w_total += problem.weight[i];
    x_mean += problem.weight[i] * std::log(d.velocity_m_s[i]);
    r_mean += problem.weight[i] * residual[i];
  }
  x_mean /= w_total;
  r_mean /= w_total;
  double sxx = 0.0;
  double sxr = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double dx = std::log(d.velocity_m_s[i]) - x_mean;
    sxx += problem.weight[i] * dx * dx;
    sxr += problem.weight[i] * dx * residual[i];
  }
  out.slope = sxr / sxx;
  double scale = 1.0;  // known σ: the weights are 1/σ²
  if (problem.sigma_estimated) {
    double rss = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double e = residual[i] - r_mean - out.slope * (std::log(d.velocity_m_s[i]) - x_mean);
      rss += problem.weight[i] * e * e;
    }
    scale = std::sqrt(rss / static_cast<double>(n - 2));
  }
  out.slope_error = scale / std::sqrt(sxx);
  if (out.slope_error == 0.0) {
    out.slope_p_value = out.slope == 0.0 ? 1.0 : 0.0;
    return;
  }
  const double t = std::abs(out.slope) / out.slope_error;
  out.slope_p_value = problem.sigma_estimated
                          ? 2.0 * boost::math::cdf(boost::math::complement(
                                      boost::math::students_t(static_cast<double>(n - 2)), t))
                          : 2.0 * boost::math::cdf(boost::math::complement(boost::math::normal(), t));
}

// Wald-Wolfowitz: too few runs of equal signs (ordered by speed) means the residuals are not independent
// scatter. Normal approximation; zero residuals are skipped.
void runs_test(const Problem& problem, const std::vector<double>& residual, ResidualTests& out) {
  const FitData& d = *problem.data;
  std::vector<std::size_t> order(problem.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return d.velocity_m_s[a] < d.velocity_m_s[b]; });
  double positive = 0.0;
  double negative = 0.0;
  int previous = 0;
  for (const std::size_t i : order) {
    const int sign = residual[i] > 0.0 ? 1 : (residual[i] < 0.0 ? -1 : 0);
    if (sign == 0) continue;
    (sign > 0 ? positive : negative) += 1.0;
    if (sign != previous) ++out.runs;
    previous = sign;
  }
  const double total = positive + negative;
  out.runs_expected = total > 0.0 ? 1.0 + 2.0 * positive * negative / total : 0.0;
  const double variance = total > 1.0 ? 2.0 * positive * negative * (2.0 * positive * negative - total) /
                                            (total * total * (total - 1.0))
                                      : 0.0;
  if (variance <= 0.0) return;
  const double z = (out.runs - out.runs_expected) / std::sqrt(variance);
  out.runs_p_value = boost::math::cdf(boost::math::normal(), z);
}

}  // namespace

ResidualTests residual_tests(const Problem& problem, const std::vector<double>& model_eps) {
  ResidualTests out;
  const FitData& d = *problem.data;
  const auto [lo, hi] = std::minmax_element(d.velocity_m_s.begin(), d.velocity_m_s.end());
  if (problem.size() < 3 || *lo == *hi) {
    out.unavailable = problem.size() < 3 ? "too few points" : "one speed";
    return out;
  }
  out.available = true;
  out.unavailable.clear();
  out.verdict = "none";
  std::vector<double> residual(problem.size());
  for (std::size_t i = 0; i < problem.size(); ++i) residual[i] = d.eps[i] - model_eps[i];
  slope_test(problem, residual, out);
  runs_test(problem, residual, out);
  if (out.slope_p_value < kFitSignificance) {
    out.verdict = out.slope < 0.0 ? "falls-with-speed" : "rises-with-speed";
  } else if (out.runs_p_value < kFitSignificance) {
    out.verdict = "runs";
  }
  return out;
}

}  // namespace restitution::fit_detail

namespace restitution {

double chi2_p_value(double chi2, std::size_t points) {
  if (points < 2) return 1.0;
  const auto dof = static_cast<double>(points - 1);
  return boost::math::cdf(boost::math::complement(boost::math::chi_squared(dof), chi2));
}

}  // namespace restitution
