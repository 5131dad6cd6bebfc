// SPDX-License-Identifier: BSD-3-Clause
// The Taylor engine (--method taylor) against the __float128 reference solutions, across ζ and tolerances,
// both ends: the accuracy contract |ε - ε*| <= T·min(ε*, 1-ε*), and τ_c, x_end, maximal compression.
#include <gtest/gtest.h>

#include <cmath>

#include "reference_checks.hpp"
#include "restitution/collision_solver.hpp"
#include "restitution/errors.hpp"
#include "taylor/taylor_engine.hpp"

namespace restitution {
namespace {

using test_support::contract_error;
using test_support::reference_rows;

SolveOptions taylor_options(double tolerance, bool naive) {
  SolveOptions o;
  o.method = Method::taylor;
  o.tolerance = tolerance;
  o.ends = naive ? EndSet::both() : EndSet{CollisionEnd::delayed_recovery};
  return o;
}

TEST(TaylorEngine, MeetsTheContractAgainstTheReference) {
  CollisionSolver solver;
  for (const double tolerance : {1e-4, 1e-6, 1e-8, 1e-10, 1e-12, kMinTaylorTolerance}) {
    double worst_ratio = 0;
    for (const ReferenceRow& row : reference_rows()) {
      const bool naive = row.ends[CollisionEnd::naive].has_value() && row.zeta <= kTaylorNaiveZetaMax;
      const CollisionResult r =
          solver.solve(ContactLaw::hertz_natural(row.zeta), taylor_options(tolerance, naive));
      ASSERT_TRUE(r[CollisionEnd::delayed_recovery]);
      const double delayed =
          contract_error(*r[CollisionEnd::delayed_recovery], *row.ends[CollisionEnd::delayed_recovery]);
      EXPECT_LE(delayed, tolerance) << "delayed zeta=" << row.zeta << " T=" << tolerance;
      worst_ratio = std::max(worst_ratio, delayed / tolerance);
      if (naive) {
        const double e = contract_error(*r[CollisionEnd::naive], *row.ends[CollisionEnd::naive]);
        EXPECT_LE(e, tolerance) << "naive zeta=" << row.zeta << " T=" << tolerance;
        worst_ratio = std::max(worst_ratio, e / tolerance);
      }
    }
    RecordProperty("worst_error_over_T_" + std::to_string(tolerance), std::to_string(worst_ratio));
  }
}

TEST(TaylorEngine, TimesAndCompressionsMatchTheReference) {
  CollisionSolver solver;
  const double tolerance = 1e-12;
  for (const ReferenceRow& row : reference_rows()) {
    const bool naive = row.ends[CollisionEnd::naive].has_value() && row.zeta <= kTaylorNaiveZetaMax;
    const CollisionResult r =
        solver.solve(ContactLaw::hertz_natural(row.zeta), taylor_options(tolerance, naive));
    // For large ζ, x' crosses zero with slope -x^{3/2} << 1 at maximal compression: τ_max is ill-conditioned
    // (x_max is not), hence the looser bound for τ_max.
    EXPECT_NEAR(r.max_compression.tau, row.tau_max, 1e-8 * row.tau_max) << row.zeta;
    EXPECT_NEAR(r.max_compression.x, row.x_max, 1e-10 * row.x_max) << row.zeta;
    // For large ζ the force factor ζx' + x approaches zero slowly (x' relaxes onto -x/ζ), so τ_c is
    // ill-conditioned although ε = x/ζ there is not: a looser bound for τ_c.
    EXPECT_NEAR(r[CollisionEnd::delayed_recovery]->tau, row.ends[CollisionEnd::delayed_recovery]->tau,
                1e-8 * row.ends[CollisionEnd::delayed_recovery]->tau)
        << row.zeta;
    EXPECT_NEAR(r[CollisionEnd::delayed_recovery]->x, row.ends[CollisionEnd::delayed_recovery]->x,
                1e-10 * row.ends[CollisionEnd::delayed_recovery]->x + 1e-300)
        << row.zeta;
    if (naive) {
      EXPECT_NEAR(r[CollisionEnd::naive]->tau, row.ends[CollisionEnd::naive]->tau,
                  1e-10 * row.ends[CollisionEnd::naive]->tau)
          << row.zeta;
      EXPECT_EQ(r[CollisionEnd::naive]->x, 0.0);
    }
  }
}

TEST(TaylorEngine, DashpotMatchesItsClosedForm) {
  // x'' + 2r x' + x = 0: ε_naive = exp(-rπ/ω), ω = sqrt(1 - r²) (2008 paper, Eq. 10).
  CollisionSolver solver;
  for (const double r : {0.05, 0.3, 0.8}) {
    const CollisionResult result = solver.solve(ContactLaw::linear_dashpot(r), taylor_options(1e-12, true));
    const double w = std::sqrt(1.0 - r * r);
    const double eps = std::exp(-r * M_PI / w);
    EXPECT_NEAR(result[CollisionEnd::naive]->eps, eps, 1e-12 * std::min(eps, 1.0 - eps)) << r;
    EXPECT_NEAR(result[CollisionEnd::naive]->tau, M_PI / w, 1e-12) << r;
    EXPECT_NEAR(result.max_compression.tau, std::atan2(w, r) / w, 1e-12) << r;
  }
}

TEST(TaylorEngine, ScaledFormGivesTheNaturalResult) {
  // ε depends on β and v only through ζ = β v^{1/5}; results are reported in natural units.
  CollisionSolver solver;
  const CollisionResult scaled =
      solver.solve(ContactLaw::hertz_scaled(0.2, 3.0), taylor_options(1e-12, true));
  const CollisionResult natural =
      solver.solve(ContactLaw::hertz_natural(0.2 * std::pow(3.0, 0.2)), taylor_options(1e-12, true));
  EXPECT_NEAR(scaled[CollisionEnd::delayed_recovery]->eps, natural[CollisionEnd::delayed_recovery]->eps,
              1e-13);
  EXPECT_NEAR(scaled[CollisionEnd::naive]->tau, natural[CollisionEnd::naive]->tau, 1e-12);
  EXPECT_NEAR(scaled.max_compression.x, natural.max_compression.x, 1e-12);
}

TEST(TaylorEngine, RefusesWhatItCannotDeliver) {
  CollisionSolver solver;
  EXPECT_THROW(solver.solve(ContactLaw::hertz_natural(1.0), taylor_options(1e-14, true)), InvalidInput);
  EXPECT_THROW(solver.solve(ContactLaw::hertz_natural(2 * kTaylorNaiveZetaMax), taylor_options(1e-8, true)),
               InvalidInput);
  SolveOptions trajectory = taylor_options(1e-8, true);
  trajectory.keep_trajectory = true;
  EXPECT_THROW(solver.solve(ContactLaw::hertz_natural(1.0), trajectory), InvalidInput);
}

}  // namespace
}  // namespace restitution
