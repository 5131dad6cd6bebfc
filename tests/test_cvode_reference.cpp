// SPDX-License-Identifier: BSD-3-Clause
// The CVODE engine meets the accuracy contract against the __float128 reference solutions
// (data/reference_solutions.csv), both ends, both methods and the automatic choice, with and without the
// smooth formulation at the ends.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "reference_checks.hpp"
#include "restitution/collision_solver.hpp"

namespace restitution {
namespace {

using test_support::contract_error;
using test_support::reference_rows;

// zeta_max: Adams is not meant for the stiff large-ζ regime (auto switches to BDF at ζ = 5).
void expect_contract(Method method, bool smooth_ends, const std::vector<double>& tolerances,
                     double zeta_max = 1e300, bool naive = true) {
  CollisionSolver solver;
  for (const double tolerance : tolerances) {
    for (const ReferenceRow& row : reference_rows()) {
      if (row.zeta > zeta_max) continue;
      SolveOptions o;
      o.method = method;
      o.smooth_ends = smooth_ends;
      o.tolerance = tolerance;
      o.ends = naive && row.ends[CollisionEnd::naive].has_value() ? EndSet::both()
                                                                  : EndSet{CollisionEnd::delayed_recovery};
      const CollisionResult r = solver.solve(ContactLaw::hertz_natural(row.zeta), o);
      EXPECT_LE(contract_error(*r[CollisionEnd::delayed_recovery], *row.ends[CollisionEnd::delayed_recovery]),
                tolerance)
          << method_name(method) << " delayed zeta=" << row.zeta << " T=" << tolerance;
      if (o.ends.contains(CollisionEnd::naive)) {
        EXPECT_LE(contract_error(*r[CollisionEnd::naive], *row.ends[CollisionEnd::naive]), tolerance)
            << method_name(method) << " naive zeta=" << row.zeta << " T=" << tolerance;
      }
    }
  }
}

TEST(CvodeAgainstReference, AutomaticMethodMeetsTheContract) {
  expect_contract(Method::automatic, true, {1e-4, 1e-6, 1e-8, 1e-10, kMinTolerance});
}

TEST(CvodeAgainstReference, AutomaticMethodForTheDelayedEndAloneMeetsTheContract) {
  // Without the naive tail `auto` takes Adams at every ζ.
  expect_contract(Method::automatic, true, {1e-6, 1e-10, kMinTolerance}, 1e300, false);
}

TEST(CvodeAgainstReference, BdfMeetsTheContract) {
  expect_contract(Method::bdf, true, {1e-6, 1e-10});
}

TEST(CvodeAgainstReference, AdamsMeetsTheContract) {
  expect_contract(Method::adams, true, {1e-6, 1e-10}, 100.0);
}

// The delayed-recovery end alone runs one Sundman phase (docs/performance.md, sixth round); with both ends it
// runs the phases in u and τ. Both must give the same end across the contact-law family, to within T.
TEST(CvodeSinglePhase, DelayedEndAloneAgreesWithThePhasedSolveAcrossTheFamily) {
  CollisionSolver solver;
  for (const LawKind kind :
       {LawKind::viscoelastic_hertz, LawKind::tsuji_hertz, LawKind::hertz_constant_damping}) {
    for (const double zeta : {2e-4, 0.01, 1.0}) {
      for (const double tolerance : {1e-6, 1e-10}) {
        const ContactLaw law = ContactLaw::natural(kind, zeta);
        SolveOptions alone;
        alone.tolerance = tolerance;
        alone.ends = EndSet{CollisionEnd::delayed_recovery};
        SolveOptions both = alone;
        both.ends = EndSet::both();
        const EndResult a = *solver.solve(law, alone)[CollisionEnd::delayed_recovery];
        const EndResult b = *solver.solve(law, both)[CollisionEnd::delayed_recovery];
        const double scale = std::min(b.eps, b.one_minus_eps);
        EXPECT_LE(std::max(std::abs(a.eps - b.eps), std::abs(a.one_minus_eps - b.one_minus_eps)),
                  tolerance * scale)
            << law_name(kind) << " zeta=" << zeta << " T=" << tolerance;
        EXPECT_NEAR(a.tau, b.tau, 1e-6 * b.tau) << law_name(kind) << " zeta=" << zeta;  // a root, not ε
      }
    }
  }
}

// Its trajectory runs forward in τ from the impact to the end, through the maximal compression.
TEST(CvodeSinglePhase, TrajectoryRunsFromTheImpactToTheDelayedEnd) {
  CollisionSolver solver;
  SolveOptions options;
  options.ends = EndSet{CollisionEnd::delayed_recovery};
  options.keep_trajectory = true;
  const CollisionResult r = solver.solve(ContactLaw::hertz_natural(1.0), options);
  ASSERT_GT(r.trajectory.size(), 10U);
  EXPECT_EQ(r.trajectory.front().tau, 0.0);
  for (std::size_t i = 1; i < r.trajectory.size(); ++i)
    EXPECT_GT(r.trajectory[i].tau, r.trajectory[i - 1].tau);
  EXPECT_NEAR(r.trajectory.back().tau, r[CollisionEnd::delayed_recovery]->tau, 1e-12);
  EXPECT_GT(r.max_compression.x, r.trajectory.back().x);
}

}  // namespace
}  // namespace restitution
