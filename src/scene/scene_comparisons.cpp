// SPDX-License-Identifier: BSD-3-Clause
#include "scene/scene_comparisons.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "analysis/contract_error.hpp"
#include "reference/dashpot_closed_form.hpp"
#include "scene/scene_run.hpp"

namespace restitution::scene::detail {
namespace {

constexpr double kNone = std::numeric_limits<double>::quiet_NaN();

ApproximationComparison comparison_of(const std::vector<double>& zeta,
                                      const std::vector<double>& difference) {
  ApproximationComparison c;
  for (std::size_t i = 0; i < zeta.size(); ++i) {
    if (!std::isfinite(difference[i])) continue;
    c.zeta_min = c.compared == 0 ? zeta[i] : std::min(c.zeta_min, zeta[i]);
    c.zeta_max = c.compared == 0 ? zeta[i] : std::max(c.zeta_max, zeta[i]);
    c.max_abs_relative_difference = std::max(c.max_abs_relative_difference, std::abs(difference[i]));
    ++c.compared;
  }
  return c;
}

}  // namespace

void compare_approximations(const std::vector<double>& zeta, const PointResults& results,
                            SweepExtras& extras) {
  for (ApproximationColumn& column : extras.approximations) {
    column.relative_difference.clear();
    for (std::size_t i = 0; i < zeta.size(); ++i) {
      const EndResult* end = end_if_computed(results[i], column.end);
      column.relative_difference.push_back(end != nullptr ? column.eps[i] / end->eps - 1.0 : kNone);
    }
    column.comparison = comparison_of(zeta, column.relative_difference);
  }
}

void add_empirical(const EmpiricalLaw& law, EndSet ends, const std::vector<double>& velocity_m_s,
                   const PointResults& results, SweepExtras& extras) {
  EmpiricalDeviation deviation;
  deviation.end = ends.contains(CollisionEnd::naive) ? CollisionEnd::naive : CollisionEnd::delayed_recovery;
  for (std::size_t i = 0; i < velocity_m_s.size(); ++i) {
    const double empirical =
        law.coefficient * std::pow(velocity_m_s[i] / law.velocity_unit_m_s, law.exponent);
    extras.empirical_eps.push_back(empirical);
    if (!(empirical < 1.0)) continue;  // the law is no coefficient of restitution there
    const EndResult* end = end_if_computed(results[i], deviation.end);
    const double d = std::abs((end != nullptr ? end->eps : kNone) / empirical - 1.0);
    if (d > deviation.max_relative_deviation) {
      deviation.max_relative_deviation = d;
      deviation.at_velocity_m_s = velocity_m_s[i];
    }
  }
  extras.empirical_deviation = deviation;
}

DashpotOutcome check_dashpot(const DashpotCheck& check, const std::vector<double>& damping_ratio,
                             const PointResults& results) {
  DashpotOutcome out;
  for (std::size_t i = 0; i < damping_ratio.size(); ++i) {
    const double r = damping_ratio[i];
    DashpotPoint point;
    point.damping_ratio = r;
    for (const CollisionEnd e : check.ends.members()) {
      const EndResult* end = end_if_computed(results[i], e);
      if (end == nullptr) continue;
      const double tau = e == CollisionEnd::naive ? dashpot_naive_duration(r) : dashpot_delayed_duration(r);
      const double exact = dashpot_eps(r, tau);
      const double error = analysis::contract_error(end->eps, exact);
      point.ends[e] = DashpotEndCheck{end->eps, exact, error};
      if (std::isfinite(error)) out.max_relative_error[e] = std::max(out.max_relative_error[e], error);
    }
    out.points.push_back(point);
  }
  return out;
}

}  // namespace restitution::scene::detail
