// SPDX-License-Identifier: BSD-3-Clause
// The accuracy contract: for every ζ in [1e-8, 1e4] and T in {1e-6, 1e-8, 1e-10}, the error of ε relative
// to min(ε, 1-ε) is at most T, measured against a much tighter solve (T = 1e-11 with the other method, so
// that the reference does not share the tested method's error).
#include <gtest/gtest.h>

#include <cmath>

#include "restitution/collision_solver.hpp"

namespace restitution {
namespace {

double contract_error(const EndResult& tested, const EndResult& reference) {
  const double scale = std::min(reference.eps, reference.one_minus_eps);
  return std::max(std::abs(tested.eps - reference.eps),
                  std::abs(tested.one_minus_eps - reference.one_minus_eps)) /
         scale;
}

TEST(ToleranceHonesty, ErrorStaysBelowRequestedTolerance) {
  CollisionSolver solver;
  int checked = 0;
  for (double log_zeta = -8.0; log_zeta <= 4.0 + 1e-9; log_zeta += 0.5) {
    const double zeta = std::pow(10.0, log_zeta);
    const ContactLaw law = ContactLaw::hertz_natural(zeta);
    SolveOptions tight;
    tight.tolerance = 1e-11;
    tight.method = Method::bdf;
    const CollisionResult reference = solver.solve(law, tight);
    for (const double tolerance : {1e-6, 1e-8, 1e-10}) {
      SolveOptions o;
      o.tolerance = tolerance;
      const CollisionResult r = solver.solve(law, o);
      // The reference itself carries an error of up to ~1e-11 relative.
      const double allowed = tolerance + 1e-11;
      EXPECT_LE(contract_error(*r[CollisionEnd::naive], *reference[CollisionEnd::naive]), allowed)
          << "naive zeta=" << zeta << " T=" << tolerance;
      EXPECT_LE(
          contract_error(*r[CollisionEnd::delayed_recovery], *reference[CollisionEnd::delayed_recovery]),
          allowed)
          << "delayed zeta=" << zeta << " T=" << tolerance;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 25 * 3);
}

}  // namespace
}  // namespace restitution
