// SPDX-License-Identifier: BSD-3-Clause
#include "dem/deck_eps.hpp"

#include <fmt/core.h>

#include <cmath>

#include "restitution/contact_law.hpp"
#include "restitution/errors.hpp"
#include "restitution/units.hpp"

namespace restitution::dem {

double eps_for(double beta, double velocity_m_s, CollisionEnd end, double tolerance,
               CollisionSolver& solver) {
  const double zeta = zeta_from(beta, velocity_m_s);
  if (zeta == 0.0) return 1.0;
  try {
    require_checked_zeta(zeta);
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("impact speed {} m/s: {}", velocity_m_s, e.what()));
  }
  SolveOptions options;
  options.ends = EndSet{end};
  options.tolerance = tolerance;
  options.keep_trajectory = false;
  return end_of(solver.solve(ContactLaw::hertz_natural(zeta), options), end).eps;
}

std::vector<SizeCheck> size_checks(const Deck& deck, const Pair& pair, double dissipative_constant_s,
                                   double velocity_m_s, const std::vector<double>& factors, double tolerance,
                                   CollisionSolver& solver) {
  std::vector<SizeCheck> checks;
  for (double f : factors) {
    const Pair other = scaled(pair, f);
    const double k =
        hertz_stiffness(other.effective_modulus_pa, other.effective_radius_m) / other.effective_mass_kg;
    SizeCheck c;
    c.radius_factor = f;
    c.eps_lines = eps_for(deck_beta(deck, other), velocity_m_s, deck.end, tolerance, solver);
    c.eps_law =
        eps_for(hertz_constants(k, dissipative_constant_s).beta, velocity_m_s, deck.end, tolerance, solver);
    checks.push_back(c);
  }
  return checks;
}

}  // namespace restitution::dem
