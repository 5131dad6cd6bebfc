// SPDX-License-Identifier: BSD-3-Clause
#include "analysis/power_law_study.hpp"

#include "analysis/asymptotics.hpp"
#include "restitution/collision_solver.hpp"
#include "restitution/contact_law.hpp"

namespace restitution {

PowerLawStudy power_law_study(const std::vector<double>& zetas, CollisionEnd end, double tolerance,
                              const std::function<void(std::size_t, std::size_t)>& progress) {
  if (!zetas.empty()) require_checked_zeta(zetas.back());
  CollisionSolver solver;
  SolveOptions options;
  options.tolerance = tolerance;
  options.ends = EndSet{end};
  PowerLawStudy study;
  study.zeta = zetas;
  for (const double zeta : zetas) {
    study.eps.push_back(end_of(solver.solve(ContactLaw::hertz_natural(zeta), options), end).eps);
    study.slopes.push_back(local_slope(solver, zeta, end, kMinTolerance));
    if (progress) progress(study.eps.size(), zetas.size());
  }
  study.fit = fit_power_law(zetas, study.eps);
  if (end == CollisionEnd::naive) {
    study.derived_exponent = asymptotics::kNaiveExponent;
    study.derived_prefactor = asymptotics::naive_prefactor().value;
  } else {
    study.derived_exponent = asymptotics::kDelayedRecoveryExponent;
    study.derived_prefactor = asymptotics::delayed_recovery_prefactor();
  }
  return study;
}

}  // namespace restitution
