// SPDX-License-Identifier: BSD-3-Clause
// The viscoelastic Hertz collision: limits, published series, invariance under the (β, v) form, energy
// balance, and solver details (methods, formulations, trajectory, statistics).
#include <gtest/gtest.h>

#include <cmath>

#include "reference_values.hpp"
#include "restitution/collision_solver.hpp"
#include "restitution/errors.hpp"
#include "series/published_tables.hpp"

namespace restitution {
namespace {

using test_support::c1_closed_form;
constexpr const auto& kPaperC = series::published::kTable3C;  // c_1 ... c_10
constexpr const auto& kPaperH = series::published::kTable5H;  // h_0 ... h_20

SolveOptions options(double tolerance, Method method = Method::automatic) {
  SolveOptions o;
  o.tolerance = tolerance;
  o.method = method;
  return o;
}

double relative_error_bound(const EndResult& e) {
  return std::min(e.eps, e.one_minus_eps);
}

TEST(HertzSolver, UndampedCollisionIsElasticAndSymmetric) {
  CollisionSolver solver;
  for (const Method method : {Method::adams, Method::bdf}) {
    const CollisionResult r = solver.solve(ContactLaw::hertz_natural(0.0), options(1e-10, method));
    const double tau_max = test_support::undamped_max_time();
    EXPECT_NEAR(r.max_compression.x, test_support::undamped_max_compression(), 1e-10);
    EXPECT_NEAR(r.max_compression.tau, tau_max, 1e-10);
    for (const EndResult& e : {*r[CollisionEnd::naive], *r[CollisionEnd::delayed_recovery]}) {
      EXPECT_NEAR(e.eps, 1.0, 1e-12);
      EXPECT_NEAR(e.one_minus_eps, 0.0, 1e-12);
      EXPECT_NEAR(e.tau, 2.0 * tau_max, 1e-9);
      EXPECT_NEAR(e.x, 0.0, 1e-12);
    }
  }
}

TEST(HertzSolver, SmallZetaMatchesC1ClosedFormAndPublishedSeries) {
  // 1 - ε = C1 ζ - c2 ζ² + ... ; at ζ = 1e-8, (1-ε)/ζ + c2 ζ gives C1 up to c3 ζ² ~ 5e-17.
  CollisionSolver solver;
  const double zeta = 1e-8;
  const CollisionResult r = solver.solve(ContactLaw::hertz_natural(zeta), options(1e-10));
  EXPECT_NEAR(r[CollisionEnd::naive]->one_minus_eps / zeta + kPaperC[1] * zeta, c1_closed_form(),
              2e-10 * c1_closed_form());
  // Published c_1 = -1.153448854 has ten digits and differs from the closed form in the ninth.
  EXPECT_NEAR(r[CollisionEnd::naive]->one_minus_eps / zeta + kPaperC[1] * zeta, -kPaperC[0], 5e-9);

  // At ζ = 1e-3 the published four-term series (c1 from the closed form) is good to ~c5 ζ^5 = 2e-16.
  const double z = 1e-3;
  const CollisionResult s = solver.solve(ContactLaw::hertz_natural(z), options(1e-10));
  const double series =
      c1_closed_form() * z - kPaperC[1] * z * z - kPaperC[2] * z * z * z - kPaperC[3] * z * z * z * z;
  EXPECT_NEAR(s[CollisionEnd::naive]->one_minus_eps, series, 1e-10 * series);
  // Delayed recovery: 1 - ε = -Σ h_k ζ^{k/2}; h_5 = 4/15 is exact (2008 paper, Eq. C5).
  double delayed_series = c1_closed_form() * z;
  for (int k = 4; k <= 8; ++k) delayed_series -= kPaperH[k] * std::pow(z, 0.5 * k);
  EXPECT_NEAR(s[CollisionEnd::delayed_recovery]->one_minus_eps, delayed_series, 1e-9 * delayed_series);
  EXPECT_GT(s[CollisionEnd::delayed_recovery]->eps, s[CollisionEnd::naive]->eps);
}

TEST(HertzSolver, BetaVelocityFormDependsOnlyOnZeta) {
  CollisionSolver solver;
  for (const double beta : {0.05, 0.2, 1.0, 5.0}) {
    for (const double v : {1e-6, 1e-3, 1.0, 10.0, 1e3, 1e6}) {
      SCOPED_TRACE(testing::Message() << "beta=" << beta << " v=" << v);
      const ContactLaw scaled = ContactLaw::hertz_scaled(beta, v);
      const double zeta = beta * std::pow(v, 0.2);
      const CollisionResult a = solver.solve(scaled, options(1e-9));
      const CollisionResult b = solver.solve(ContactLaw::hertz_natural(zeta), options(1e-9));
      for (const auto& [ea, eb] :
           {std::pair{*a[CollisionEnd::naive], *b[CollisionEnd::naive]},
            std::pair{*a[CollisionEnd::delayed_recovery], *b[CollisionEnd::delayed_recovery]}}) {
        const double scale = relative_error_bound(eb);
        EXPECT_NEAR(ea.eps, eb.eps, 2e-9 * scale);
        EXPECT_NEAR(ea.one_minus_eps, eb.one_minus_eps, 2e-9 * scale);
        EXPECT_NEAR(ea.tau, eb.tau, 1e-7 * eb.tau);
        EXPECT_NEAR(ea.x, eb.x, 1e-7 * (eb.x + 1e-300));
      }
      EXPECT_NEAR(a.max_compression.x, b.max_compression.x, 1e-7 * b.max_compression.x);
    }
  }
}

TEST(HertzSolver, EnergyBalanceHoldsAtBothEnds) {
  // x'(τ_c)²/2 + (2/5) x_end^{5/2} = 1/2 - D: the velocity comes from the trajectory, D from the quadrature,
  // so this checks the two against each other (to the trajectory's accuracy, relative to the energy 1/2).
  CollisionSolver solver;
  for (const double zeta : {1e-4, 0.1, 1.0, 10.0, 300.0}) {
    const CollisionResult r = solver.solve(ContactLaw::hertz_natural(zeta), options(1e-10));
    for (const EndResult& e : {*r[CollisionEnd::naive], *r[CollisionEnd::delayed_recovery]}) {
      const double kinetic = 0.5 * e.velocity * e.velocity;
      const double elastic = 0.4 * std::pow(e.x, 2.5);
      EXPECT_NEAR(kinetic + elastic, 0.5 - e.dissipated_energy, 1e-11) << "zeta=" << zeta;
      EXPECT_GT(e.dissipated_energy, 0.0);
      EXPECT_NEAR(e.eps, -e.velocity, 1e-11 + 1e-10 * e.eps);
    }
  }
}

TEST(HertzSolver, DelayedRecoveryEndsEarlierWithLargerEps) {
  CollisionSolver solver;
  for (const double zeta : {1e-6, 0.01, 0.5, 3.0, 100.0}) {
    const CollisionResult r = solver.solve(ContactLaw::hertz_natural(zeta), options(1e-8));
    EXPECT_LT(r[CollisionEnd::delayed_recovery]->tau, r[CollisionEnd::naive]->tau);
    EXPECT_GT(r[CollisionEnd::delayed_recovery]->eps, r[CollisionEnd::naive]->eps);
    EXPECT_GT(r[CollisionEnd::delayed_recovery]->x, 0.0);
    EXPECT_LT(r.max_compression.tau, r[CollisionEnd::delayed_recovery]->tau);
    // the force vanishes there: ζ x' + x = 0
    EXPECT_NEAR(zeta * -r[CollisionEnd::delayed_recovery]->eps + r[CollisionEnd::delayed_recovery]->x, 0.0,
                1e-7 * r[CollisionEnd::delayed_recovery]->x);
  }
}

TEST(HertzSolver, MethodsAndFormulationsAgree) {
  CollisionSolver solver;
  for (const double zeta : {1e-3, 0.3, 2.0}) {
    const CollisionResult ref = solver.solve(ContactLaw::hertz_natural(zeta), options(1e-10, Method::bdf));
    for (const bool smooth : {true, false}) {
      SolveOptions o = options(1e-8, Method::adams);
      o.smooth_ends = smooth;
      const CollisionResult r = solver.solve(ContactLaw::hertz_natural(zeta), o);
      EXPECT_NEAR(r[CollisionEnd::naive]->eps, ref[CollisionEnd::naive]->eps,
                  1e-8 * relative_error_bound(*ref[CollisionEnd::naive]))
          << zeta << smooth;
      EXPECT_NEAR(r[CollisionEnd::delayed_recovery]->eps, ref[CollisionEnd::delayed_recovery]->eps,
                  1e-8 * relative_error_bound(*ref[CollisionEnd::delayed_recovery]));
    }
  }
}

TEST(HertzSolver, OnlyRequestedEndsAreComputed) {
  CollisionSolver solver;
  SolveOptions delayed = options(1e-8);
  delayed.ends.erase(CollisionEnd::naive);
  SolveOptions both = options(1e-8);
  const CollisionResult d = solver.solve(ContactLaw::hertz_natural(50.0), delayed);
  const CollisionResult b = solver.solve(ContactLaw::hertz_natural(50.0), both);
  EXPECT_FALSE(d[CollisionEnd::naive]);
  ASSERT_TRUE(d[CollisionEnd::delayed_recovery]);
  // the naive tail (a slow relaxation over ~ζ ln ζ) is not integrated when only delayed recovery is asked
  EXPECT_LT(d.stats.steps, b.stats.steps);
  delayed.keep_trajectory = true;
  const CollisionResult t = solver.solve(ContactLaw::hertz_natural(50.0), delayed);
  EXPECT_EQ(t.trajectory.back().tau, t[CollisionEnd::delayed_recovery]->tau);
  EXPECT_LT(t[CollisionEnd::delayed_recovery]->tau, 0.01 * b[CollisionEnd::naive]->tau);
  EXPECT_NEAR(d[CollisionEnd::delayed_recovery]->eps, b[CollisionEnd::delayed_recovery]->eps,
              1e-8 * d[CollisionEnd::delayed_recovery]->eps);
}

TEST(HertzSolver, TrajectoryIsKeptOnlyWhenAsked) {
  CollisionSolver solver;
  SolveOptions o = options(1e-8);
  EXPECT_TRUE(solver.solve(ContactLaw::hertz_natural(0.5), o).trajectory.empty());
  o.keep_trajectory = true;
  const CollisionResult r = solver.solve(ContactLaw::hertz_natural(0.5), o);
  ASSERT_GT(r.trajectory.size(), 10U);
  EXPECT_EQ(r.trajectory.front().tau, 0.0);
  EXPECT_EQ(r.trajectory.front().velocity, 1.0);
  for (std::size_t i = 1; i < r.trajectory.size(); ++i) {
    EXPECT_GE(r.trajectory[i].tau, r.trajectory[i - 1].tau);
    const auto& p = r.trajectory[i];
    EXPECT_NEAR(p.acceleration, -std::sqrt(std::max(p.x, 0.0)) * (0.5 * p.velocity + p.x), 1e-12);
  }
  EXPECT_NEAR(r.trajectory.back().tau, r[CollisionEnd::naive]->tau, 1e-12);
}

TEST(HertzSolver, StatisticsAreCounted) {
  CollisionSolver solver;
  const CollisionResult r = solver.solve(ContactLaw::hertz_natural(20.0), options(1e-8, Method::bdf));
  EXPECT_GT(r.stats.steps, 10);
  EXPECT_GE(r.stats.rhs_evaluations, r.stats.steps);
  EXPECT_GT(r.stats.jacobian_evaluations, 0);
  EXPECT_GT(r.stats.root_evaluations, 0);
  EXPECT_EQ(r.method, Method::bdf);
}

TEST(HertzSolver, SolverIsReusableAcrossLawsAndMethods) {
  CollisionSolver solver;
  const CollisionResult first = solver.solve(ContactLaw::hertz_natural(0.7), options(1e-9));
  solver.solve(ContactLaw::linear_dashpot(0.3), options(1e-6, Method::bdf));
  solver.solve(ContactLaw::hertz_natural(40.0), options(1e-6, Method::adams));
  const CollisionResult again = solver.solve(ContactLaw::hertz_natural(0.7), options(1e-9));
  EXPECT_EQ(first[CollisionEnd::naive]->eps, again[CollisionEnd::naive]->eps);
  EXPECT_EQ(first[CollisionEnd::delayed_recovery]->eps, again[CollisionEnd::delayed_recovery]->eps);
  EXPECT_EQ(first.stats.steps, again.stats.steps);
}

TEST(HertzSolver, RejectsBadRequests) {
  CollisionSolver solver;
  const ContactLaw law = ContactLaw::hertz_natural(1.0);
  for (const double tol : {0.0, -1e-8, 1e-15, 0.5, std::nan("")}) {
    EXPECT_THROW(solver.solve(law, options(tol)), InvalidInput) << tol;
  }
  SolveOptions none = options(1e-8);
  none.ends = EndSet{};
  EXPECT_THROW(solver.solve(law, none), InvalidInput);
}

}  // namespace
}  // namespace restitution
