// SPDX-License-Identifier: BSD-3-Clause
#include "restitution/fit.hpp"

#include <algorithm>
#include <limits>

#include "restitution/fast.hpp"
#include "restitution/units.hpp"

namespace restitution {

FitRejection judge_reported_fit(const std::vector<ReportedFit>& fits, std::size_t chosen, std::size_t best,
                                const std::vector<std::size_t>& tied, bool sigma_estimated,
                                std::size_t points) {
  FitRejection out;
  const ReportedFit& f = fits.at(chosen);
  if (chosen != best && std::find(tied.begin(), tied.end(), chosen) == tied.end()) out.better_fit = best;
  // The χ² test means something with the data's own σ only (restitution/fit.hpp, chi2_p_value).
  if (!sigma_estimated && points > 1) {
    const double p = chi2_p_value(f.chi2, points);
    if (p < kFitSignificance) {
      out.chi2_per_dof = f.chi2 / static_cast<double>(points - 1);
      out.chi2_p_value = p;
    }
  }
  for (const char* trend : {"falls-with-speed", "rises-with-speed", "runs"}) {
    if (f.residual_verdict == trend) out.residual_trend = trend;
  }
  return out;
}

FittedEps fitted_eps_at_speed(double beta, const FitInterval& ci68, const FitInterval& ci95, CollisionEnd end,
                              double velocity_m_s) {
  // β carried over passes the domain check of a β typed with `eps --beta --velocity`.
  require_checked_zeta(zeta_from(beta, velocity_m_s));
  auto eps = [&](double b) { return fast::eps(zeta_from(b, velocity_m_s), end); };
  // A bound whose ζ at this speed lies beyond the checked range is at the edge here, as fit-data reports it.
  auto beyond = [&](double b) { return zeta_from(b, velocity_m_s) > kLargestCheckedZeta; };
  auto map = [&](const FitInterval& b) {
    FitInterval out;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    out.low_at_edge = b.high_at_edge || beyond(b.high);
    out.low = out.low_at_edge ? nan : eps(b.high);
    out.high_at_edge = b.low_at_edge;
    out.high = b.low_at_edge ? nan : eps(b.low);
    return out;
  };
  return {eps(beta), map(ci68), map(ci95)};
}

}  // namespace restitution
