// SPDX-License-Identifier: BSD-3-Clause
// The __float128 reference solutions: closed forms (ζ = 0; the linear dash-pot, 2008 paper Eqs. 10 and 12
// and their delayed-recovery analogue), agreement of the two orders, and the stored file against a fresh
// computation.
#include <gtest/gtest.h>
#include <quadmath.h>

#include "reference/reference_solution.hpp"
#include "reference_checks.hpp"
#include "restitution/errors.hpp"

namespace restitution {
namespace {

double relative(__float128 a, __float128 b) {
  return static_cast<double>(fabsq((a - b) / b));
}

TEST(ReferenceSolution, UndampedCollisionMatchesTheEnergyIntegral) {
  // ζ = 0: x_max = (5/4)^{2/5}, τ_max0 = (4/5)^{3/5} Γ(2/5) Γ(1/2) / (2 Γ(9/10)), both ends at 2τ_max0, ε
  // = 1.
  const ReferenceSolution s = hertz_reference(0.0);
  const __float128 x_max = powq(1.25Q, 0.4Q);
  const __float128 tau_max = powq(0.8Q, 0.6Q) * tgammaq(0.4Q) * tgammaq(0.5Q) / (2 * tgammaq(0.9Q));
  EXPECT_LT(relative(s.x_max, x_max), 1e-30);
  EXPECT_LT(relative(s.tau_max, tau_max), 1e-30);
  for (const auto* end : {&s.ends[CollisionEnd::naive], &s.ends[CollisionEnd::delayed_recovery]}) {
    ASSERT_TRUE(end->has_value());
    EXPECT_LT(relative((*end)->tau, 2 * tau_max), 1e-30);
    EXPECT_LT(static_cast<double>(fabsq((*end)->one_minus_eps)), 1e-30);
  }
}

// x'' + 2r x' + x = 0, x(0) = 0, x'(0) = 1, r < 1, ω = sqrt(1 - r²): x = e^{-rτ} sin(ωτ)/ω. Maximal
// compression at ωτ = atan2(ω, r); the naive end at ωτ = π with ε = exp(-rπ/ω) (2008 paper, Eq. 10); the
// force 2r x' + x vanishes at ωτ = atan2(2rω, 2r² - 1), where ε = -x'.
struct DashpotClosedForm {
  __float128 tau_max, x_max, naive_tau, naive_eps, delayed_tau, delayed_eps;
};

DashpotClosedForm underdamped(__float128 r) {
  const __float128 w = sqrtq(1 - r * r);
  auto x = [&](__float128 t) { return expq(-r * t) * sinq(w * t) / w; };
  auto v = [&](__float128 t) { return expq(-r * t) * (cosq(w * t) - r / w * sinq(w * t)); };
  const __float128 tau_max = atan2q(w, r) / w;
  const __float128 delayed_tau = atan2q(2 * r * w, 2 * r * r - 1) / w;
  return {tau_max, x(tau_max), M_PIq / w, expq(-r * M_PIq / w), delayed_tau, -v(delayed_tau)};
}

TEST(ReferenceSolution, DashpotMatchesItsClosedForm) {
  for (const double r : {0.01, 0.2, 0.5, 0.7071, 0.9}) {
    const ReferenceSolution s = dashpot_reference(r);
    const DashpotClosedForm exact = underdamped(r);
    EXPECT_LT(relative(s.tau_max, exact.tau_max), 1e-30) << r;
    EXPECT_LT(relative(s.x_max, exact.x_max), 1e-30) << r;
    ASSERT_TRUE(s.ends[CollisionEnd::naive] && s.ends[CollisionEnd::delayed_recovery]);
    EXPECT_LT(relative(s.ends[CollisionEnd::naive]->tau, exact.naive_tau), 1e-30) << r;
    EXPECT_LT(relative(s.ends[CollisionEnd::naive]->eps, exact.naive_eps), 1e-30) << r;
    EXPECT_LT(relative(s.ends[CollisionEnd::delayed_recovery]->tau, exact.delayed_tau), 1e-30) << r;
    EXPECT_LT(relative(s.ends[CollisionEnd::delayed_recovery]->eps, exact.delayed_eps), 1e-30) << r;
    EXPECT_LT(s.agreement, kReferenceAgreement);
  }
}

TEST(ReferenceSolution, OverdampedDashpotHasOnlyTheDelayedEnd) {
  // r > 1: x = e^{-rτ} sinh(ωτ)/ω with ω = sqrt(r² - 1); the force vanishes at tanh(ωτ) = 2rω/(2r² - 1).
  const __float128 r = 3;
  const __float128 w = sqrtq(r * r - 1);
  const __float128 tau = atanhq(2 * r * w / (2 * r * r - 1)) / w;
  const __float128 eps = -expq(-r * tau) * (coshq(w * tau) - r / w * sinhq(w * tau));
  const ReferenceSolution s = dashpot_reference(3.0);
  EXPECT_FALSE(s.ends[CollisionEnd::naive]);
  ASSERT_TRUE(s.ends[CollisionEnd::delayed_recovery]);
  EXPECT_LT(relative(s.ends[CollisionEnd::delayed_recovery]->tau, tau), 1e-30);
  EXPECT_LT(relative(s.ends[CollisionEnd::delayed_recovery]->eps, eps), 1e-30);
}

TEST(ReferenceSolution, StoredFileCoversTheGridAndAgreesWithAFreshComputation) {
  const auto& rows = test_support::reference_rows();
  const std::vector<double> grid = reference_zeta_grid();
  ASSERT_EQ(rows.size(), grid.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].zeta, grid[i]);
    EXPECT_LE(rows[i].agreement, kReferenceAgreement);
    EXPECT_TRUE(rows[i].ends[CollisionEnd::delayed_recovery]);
    EXPECT_EQ(rows[i].ends[CollisionEnd::naive].has_value(), grid[i] <= kReferenceNaiveZetaMax);
  }
  // Recompute a few cheap points (the file was written by `restitution reference`).
  for (const std::size_t i : {std::size_t{1}, std::size_t{20}, std::size_t{33}, rows.size() - 1}) {
    const ReferenceSolution s = hertz_reference(rows[i].zeta);
    EXPECT_EQ(static_cast<double>(s.ends[CollisionEnd::delayed_recovery]->eps),
              rows[i].ends[CollisionEnd::delayed_recovery]->eps);
    EXPECT_EQ(static_cast<double>(s.ends[CollisionEnd::delayed_recovery]->one_minus_eps),
              rows[i].ends[CollisionEnd::delayed_recovery]->one_minus_eps);
    EXPECT_EQ(static_cast<double>(s.x_max), rows[i].x_max);
  }
}

TEST(ReferenceSolution, SmallZetaMatchesTheClosedFormC1) {
  // 1 - ε = C1 ζ + O(ζ²) at both ends (the delayed end differs at O(ζ²)); C1 from the 1999 paper's Eq. 30.
  const __float128 c1 = sqrtq(M_PIq) / (powq(2.0Q, 0.2Q) * powq(5.0Q, 0.4Q)) * tgammaq(0.6Q) / tgammaq(2.1Q);
  const double zeta = 1e-8;
  const ReferenceSolution s = hertz_reference(zeta);
  EXPECT_LT(relative(s.ends[CollisionEnd::naive]->one_minus_eps / zeta, c1), 2e-8);
}

TEST(ReferenceSolution, RejectsBadParameters) {
  EXPECT_THROW(hertz_reference(-1.0), InvalidInput);
  EXPECT_THROW(dashpot_reference(0.0), InvalidInput);
}

}  // namespace
}  // namespace restitution
