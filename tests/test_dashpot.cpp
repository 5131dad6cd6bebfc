// SPDX-License-Identifier: BSD-3-Clause
// The linear dash-pot x'' + 2r x' + x = 0, x(0) = 0, x'(0) = 1: the library's closed forms
// (dashpot_closed_form.hpp) are checked against the exact solution evaluated directly and against the 2008
// paper's printed Eqs. 10 and 12; they then check the event machinery at both ends, in all three regimes
// and at the regime boundaries.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "conditioning_grid.hpp"
#include "reference/dashpot_closed_form.hpp"
#include "restitution/collision_solver.hpp"
#include "restitution/errors.hpp"

namespace restitution {
namespace {

// Exact solution, evaluated directly (independent of the closed forms in dashpot_closed_form.hpp):
// underdamped x = e^{-rτ} sin(ωτ)/ω, ω = sqrt(1-r²); overdamped x = e^{-rτ} sinh(ωτ)/ω, ω = sqrt(r²-1);
// critical x = τ e^{-τ}.
double exact_position(double r, double tau) {
  if (r < 1.0) {
    const double w = std::sqrt(1.0 - r * r);
    return std::exp(-r * tau) * std::sin(w * tau) / w;
  }
  if (r > 1.0) {
    const double w = std::sqrt(r * r - 1.0);
    return std::exp(-r * tau) * std::sinh(w * tau) / w;
  }
  return tau * std::exp(-tau);
}

double exact_velocity(double r, double tau) {
  if (r < 1.0) {
    const double w = std::sqrt(1.0 - r * r);
    return std::exp(-r * tau) * (std::cos(w * tau) - r / w * std::sin(w * tau));
  }
  if (r > 1.0) {
    const double w = std::sqrt(r * r - 1.0);
    return std::exp(-r * tau) * (std::cosh(w * tau) - r / w * std::sinh(w * tau));
  }
  return std::exp(-tau) * (1.0 - tau);
}

// The 2008 paper's Eq. (10) and Eq. (12) with β = r, ω0 = 1, in the form printed there.
double paper_naive_eps(double r) {
  return std::exp(-r * M_PI / std::sqrt(1.0 - r * r));
}
double paper_delayed_eps_as_printed(double r) {
  const double w = std::sqrt(std::abs(1.0 - r * r));
  if (r < M_SQRT1_2) return std::exp(-r / w * (M_PI - std::atan(2.0 * r * w / (w * w - r * r))));
  if (r < 1.0) return std::exp(-r / w * std::atan(2.0 * r * w / (w * w - r * r)));
  return std::exp(-r / w * std::log((r + w) / (r - w)));
}

SolveOptions options(double tolerance, Method method = Method::automatic) {
  SolveOptions o;
  o.tolerance = tolerance;
  o.method = method;
  return o;
}

TEST(DashpotClosedForm, EndTimesAreTheEventsOfTheExactSolution) {
  for (const double r : {1e-3, 0.3, 0.7, 0.9, 1.0, 1.5, 10.0}) {
    SCOPED_TRACE(testing::Message() << "r=" << r);
    const double t = dashpot_delayed_duration(r);
    EXPECT_GT(t, 0.0);
    EXPECT_GT(exact_position(r, t), 0.0);
    // The force vanishes, to the rounding of the two terms (2r|x'| = 0.05 at r = 10).
    EXPECT_NEAR(exact_position(r, t) + 2.0 * r * exact_velocity(r, t), 0.0,
                1e-15 + 1e-13 * 2.0 * r * std::abs(exact_velocity(r, t)));
    // ε = exp(-r τ_c): |x'| carries only the exponential there.
    EXPECT_NEAR(dashpot_eps(r, t), -exact_velocity(r, t), 1e-14);
    if (r < 1.0) {
      const double naive = dashpot_naive_duration(r);
      EXPECT_GT(naive, t);
      EXPECT_NEAR(exact_position(r, naive), 0.0, 1e-15);
      EXPECT_NEAR(dashpot_eps(r, naive), -exact_velocity(r, naive), 1e-14);
    } else {
      EXPECT_THROW(dashpot_naive_duration(r), InvalidInput);
    }
  }
  // r = 0, the undamped oscillator: both ends at the half period π (issue 33, item 9).
  EXPECT_EQ(dashpot_delayed_duration(0.0), M_PI);
  EXPECT_EQ(dashpot_naive_duration(0.0), M_PI);
  EXPECT_THROW(dashpot_delayed_duration(-0.1), InvalidInput);
}

TEST(DashpotClosedForm, DelayedDurationIsContinuousThroughCriticalDamping) {
  // τ_c = 2 (1 − d/3 + O(d²)) at r = 1 + d from both sides: the overdamped form has no cancellation left.
  for (const double d : {1e-12, 1e-9, 1e-6}) {
    SCOPED_TRACE(testing::Message() << "d=" << d);
    const double above = 1.0 + d;
    const double below = 1.0 - d;
    EXPECT_NEAR(dashpot_delayed_duration(above), 2.0 * (1.0 - (above - 1.0) / 3.0), 1e-11);
    EXPECT_NEAR(dashpot_delayed_duration(below), 2.0 * (1.0 + (1.0 - below) / 3.0), 1e-11);
  }
}

TEST(DashpotClosedForm, DerivedFormsAgreeWithPaperWhereItsPrintedFormIsRight) {
  for (const double r : {0.05, 0.3, 0.6, 0.7}) {
    EXPECT_NEAR(dashpot_eps(r, dashpot_naive_duration(r)), paper_naive_eps(r), 1e-14);
    EXPECT_NEAR(dashpot_eps(r, dashpot_delayed_duration(r)), paper_delayed_eps_as_printed(r), 1e-14);
  }
  for (const double r : {1.5, 3.0, 10.0}) {
    EXPECT_NEAR(-exact_velocity(r, dashpot_delayed_duration(r)), paper_delayed_eps_as_printed(r), 1e-14);
  }
}

TEST(DashpotClosedForm, PrintedMiddleRegimeOfEq12HasTheWrongSign) {
  // For 1/√2 < r < 1 the printed exp(-(β/ω) arctan(2βω/(ω²-β²))) exceeds 1: arctan is negative there.
  // The exact solution gives exp(+(r/ω) arctan(2rω/(ω²-r²))) = exp(-r τ_c).
  for (const double r : {0.75, 0.9, 0.99}) {
    const double w = std::sqrt(1.0 - r * r);
    EXPECT_GT(paper_delayed_eps_as_printed(r), 1.0);
    const double corrected = std::exp(r / w * std::atan(2.0 * r * w / (w * w - r * r)));
    EXPECT_NEAR(-exact_velocity(r, dashpot_delayed_duration(r)), corrected, 1e-14);
  }
}

TEST(DashpotSolver, MatchesClosedFormsInAllRegimes) {
  CollisionSolver solver;
  const double tol = 1e-10;
  const double boundary = M_SQRT1_2;
  for (const double r : {1e-3, 0.05, 0.3, 0.6, boundary - 1e-6, boundary, boundary + 1e-6, 0.8, 0.95,
                         1.0 - 1e-6, 1.0, 1.0 + 1e-6, 1.5, 3.0, 10.0}) {
    SCOPED_TRACE(testing::Message() << "r=" << r);
    SolveOptions o = options(tol);
    if (r >= 0.99)
      o.ends.erase(CollisionEnd::naive);  // closer to r = 1 the naive ε = exp(-πr/ω) underflows double
    const CollisionResult result = solver.solve(ContactLaw::linear_dashpot(r), o);
    ASSERT_TRUE(result[CollisionEnd::delayed_recovery]);
    const double t_delayed = dashpot_delayed_duration(r);
    const double eps_delayed = -exact_velocity(r, t_delayed);
    const double scale_d = std::min(eps_delayed, 1.0 - eps_delayed);
    EXPECT_NEAR(result[CollisionEnd::delayed_recovery]->eps, eps_delayed, tol * scale_d);
    EXPECT_NEAR(result[CollisionEnd::delayed_recovery]->one_minus_eps, 1.0 - eps_delayed, tol * scale_d);
    EXPECT_NEAR(result[CollisionEnd::delayed_recovery]->tau, t_delayed, 1e-8 * t_delayed);
    if (o.ends.contains(CollisionEnd::naive)) {
      ASSERT_TRUE(result[CollisionEnd::naive]);
      const double eps_naive = paper_naive_eps(r);
      const double scale_n = std::min(eps_naive, 1.0 - eps_naive);
      EXPECT_NEAR(result[CollisionEnd::naive]->eps, eps_naive, tol * scale_n);
      EXPECT_NEAR(result[CollisionEnd::naive]->one_minus_eps, 1.0 - eps_naive, tol * scale_n);
      EXPECT_NEAR(result[CollisionEnd::naive]->tau, dashpot_naive_duration(r),
                  1e-8 * dashpot_naive_duration(r));
      EXPECT_GT(result[CollisionEnd::delayed_recovery]->eps,
                result[CollisionEnd::naive]->eps);  // delayed recovery ends earlier, faster
    }
  }
}

TEST(DashpotSolver, BothMethodsMeetTheContractOnAGrid) {
  CollisionSolver solver;
  for (const Method method : {Method::bdf, Method::adams}) {
    for (const double tol : {1e-6, 1e-10}) {
      for (double r = 0.01; r <= 10.0; r *= 1.7) {
        SCOPED_TRACE(testing::Message() << method_name(method) << " tol=" << tol << " r=" << r);
        SolveOptions o = options(tol, method);
        if (r >= 0.99) o.ends.erase(CollisionEnd::naive);
        const CollisionResult result = solver.solve(ContactLaw::linear_dashpot(r), o);
        const double eps = -exact_velocity(r, dashpot_delayed_duration(r));
        EXPECT_NEAR(result[CollisionEnd::delayed_recovery]->eps, eps, tol * std::min(eps, 1.0 - eps));
        if (o.ends.contains(CollisionEnd::naive)) {
          const double eps_n = paper_naive_eps(r);
          EXPECT_NEAR(result[CollisionEnd::naive]->eps, eps_n, tol * std::min(eps_n, 1.0 - eps_n));
        }
      }
    }
  }
}

// Near critical damping the naive ε is tiny (3e-31 at r = 0.999) and the two modes cancel there to
// 1/sqrt(1 - r²): every engine must still hold the tolerance, or refuse it (issue 12, item 3).
TEST(DashpotSolver, NearCriticalNaiveEndHoldsTheToleranceDownToTheConditioningFloor) {
  // Each engine answers within T just above the tolerance rounding lets it deliver (gain · κ · DBL_EPSILON,
  // check_solve_request) and refuses just below it; tests/test_conditioning_grid.cpp covers the whole grid.
  CollisionSolver solver;
  for (const Method method : {Method::bdf, Method::adams, Method::taylor}) {
    for (const double r : {0.99, 0.999, 0.9999}) {
      SCOPED_TRACE(testing::Message() << method_name(method) << " r=" << r);
      const ContactLaw law = ContactLaw::linear_dashpot(r);
      const double floor = conditioning_grid::gain_of(method) *
                           law.input_conditioning(EndSet{CollisionEnd::naive}).condition * DBL_EPSILON;
      SolveOptions o = options(std::max(1.01 * floor, min_tolerance(method)), method);
      o.ends = EndSet{CollisionEnd::naive};
      // 1 - r² as (1 - r)(1 + r): r·r would round to an error of 5e-11 in ε at r = 0.9999.
      const double eps = std::exp(-r * M_PI / std::sqrt((1.0 - r) * (1.0 + r)));
      EXPECT_NEAR(solver.solve(law, o)[CollisionEnd::naive]->eps / eps, 1.0, o.tolerance);
      if (floor > min_tolerance(method)) {
        o.tolerance = 0.99 * floor;
        EXPECT_THROW(solver.solve(law, o), InvalidInput);
      }
    }
  }
}

TEST(DashpotSolver, NaiveEndOfOverdampedDashpotIsAnInputError) {
  CollisionSolver solver;
  SolveOptions o = options(1e-8);
  o.ends.erase(CollisionEnd::delayed_recovery);
  EXPECT_THROW(solver.solve(ContactLaw::linear_dashpot(1.0), o), InvalidInput);
  EXPECT_THROW(solver.solve(ContactLaw::linear_dashpot(2.0), o), InvalidInput);
}

}  // namespace
}  // namespace restitution
