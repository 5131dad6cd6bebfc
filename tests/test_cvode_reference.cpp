// SPDX-License-Identifier: BSD-3-Clause
// The CVODE engine meets the accuracy contract against the __float128 reference solutions
// (data/reference_solutions.csv), both ends, both methods and the automatic choice, with and without the
// smooth formulation at the ends.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace restitution
