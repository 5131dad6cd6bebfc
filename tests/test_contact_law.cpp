// SPDX-License-Identifier: BSD-3-Clause
// Contact laws: parameters, guards and the analytic Jacobian against finite differences.
#include "law/law_rhs.hpp"
#include "restitution/contact_law.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "restitution/errors.hpp"

namespace restitution {
namespace {

TEST(ContactLaw, NaturalHertzHasUnitStiffnessAndSpeed) {
  const ContactLaw law = ContactLaw::hertz_natural(0.7);
  EXPECT_EQ(law.kind(), LawKind::viscoelastic_hertz);
  EXPECT_DOUBLE_EQ(law.damping(), 0.7);
  EXPECT_DOUBLE_EQ(law.stiffness(), 1.0);
  EXPECT_DOUBLE_EQ(law.initial_velocity(), 1.0);
  // x'' = -sqrt(x)(ζ x' + x)
  EXPECT_DOUBLE_EQ(law.acceleration(0.25, 0.5), -0.5 * (0.7 * 0.5 + 0.25));
}

TEST(ContactLaw, ScaledHertzFollowsEquation23) {
  const double beta = 0.2;
  const double v = 3.0;
  const ContactLaw law = ContactLaw::hertz_scaled(beta, v);
  EXPECT_DOUBLE_EQ(law.parameter(), beta * std::pow(v, 0.2));
  EXPECT_DOUBLE_EQ(law.initial_velocity(), std::pow(v, 0.8));
  const double x = 0.3;
  const double xdot = -0.1;
  const double expected =
      -(beta * std::pow(v, -0.2) * xdot * std::sqrt(x) + std::pow(v, -0.4) * std::pow(x, 1.5));
  EXPECT_NEAR(law.acceleration(x, xdot), expected, 1e-15);
  // In natural variables X = x / v^{4/5}: c_d x' + c_s x = v^{2/5} (ζ X' + X).
  const double X = x / std::pow(v, 0.8);
  const double Xdot = xdot / std::pow(v, 0.8);
  EXPECT_NEAR(law.force_factor(x, xdot), std::pow(v, 0.4) * (law.parameter() * Xdot + X), 1e-14);
}

TEST(ContactLaw, HertzHasNoForceWithoutOverlap) {
  const ContactLaw law = ContactLaw::hertz_natural(1.0);
  EXPECT_EQ(law.acceleration(-1e-3, -0.5), 0.0);
  EXPECT_EQ(law.acceleration(0.0, -0.5), 0.0);
  EXPECT_EQ(law.dissipation_integrand(-1e-3, 1.0), 0.0);
  EXPECT_EQ(law.elastic_energy(-1.0), 0.0);
  EXPECT_TRUE(std::isfinite(law_rhs::dacceleration_dx(law, 0.0, 1.0)));
  EXPECT_TRUE(std::isfinite(law_rhs::dacceleration_dx(law, -1.0, 1.0)));
}

TEST(ContactLaw, DashpotContinuesSmoothlyPastZero) {
  // Only trial steps see x < 0; a smooth continuation keeps the naive end's location exact.
  const ContactLaw law = ContactLaw::linear_dashpot(0.3);
  EXPECT_DOUBLE_EQ(law.acceleration(-1e-3, -0.5), -(0.6 * -0.5 - 1e-3));
  EXPECT_EQ(law.elastic_energy(-1.0), 0.0);
}

TEST(ContactLaw, DashpotIsLinear) {
  const ContactLaw law = ContactLaw::linear_dashpot(0.4);
  EXPECT_DOUBLE_EQ(law.acceleration(0.5, 0.25), -(0.8 * 0.25 + 0.5));
  EXPECT_DOUBLE_EQ(law.elastic_energy(0.5), 0.125);
}

TEST(ContactLaw, JacobianMatchesFiniteDifferences) {
  for (const ContactLaw& law : {ContactLaw::hertz_natural(0.0), ContactLaw::hertz_natural(3.0),
                                ContactLaw::hertz_scaled(0.5, 20.0), ContactLaw::linear_dashpot(0.7)}) {
    for (const double x : {1e-4, 0.3, 1.2}) {
      for (const double v : {-0.7, 0.01, 0.9}) {
        const double h = 1e-7 * x;
        const double dadx = (law.acceleration(x + h, v) - law.acceleration(x - h, v)) / (2 * h);
        const double dadv = (law.acceleration(x, v + 1e-7) - law.acceleration(x, v - 1e-7)) / 2e-7;
        const double didx =
            (law.dissipation_integrand(x + h, v) - law.dissipation_integrand(x - h, v)) / (2 * h);
        const double didv =
            (law.dissipation_integrand(x, v + 1e-7) - law.dissipation_integrand(x, v - 1e-7)) / 2e-7;
        const double scale = 1.0 + std::abs(dadx);
        EXPECT_NEAR(law_rhs::dacceleration_dx(law, x, v), dadx, 1e-6 * scale)
            << law_name(law.kind()) << " x=" << x;
        EXPECT_NEAR(law_rhs::dacceleration_dv(law, x), dadv, 1e-6);
        EXPECT_NEAR(law_rhs::ddissipation_integrand_dx(law, x, v), didx, 1e-6 * (1.0 + std::abs(didx)));
        EXPECT_NEAR(law_rhs::ddissipation_integrand_dv(law, x, v), didv, 1e-6);
      }
    }
  }
}

TEST(ContactLaw, ElasticEnergyIsTheIntegralOfTheElasticForce) {
  const ContactLaw law = ContactLaw::hertz_scaled(0.3, 5.0);
  const double x = 0.8;
  const int n = 20000;
  double integral = 0.0;  // midpoint rule of c_s w(s) s
  for (int i = 0; i < n; ++i) {
    const double s = (i + 0.5) * x / n;
    integral += law.stiffness() * law.shape(s) * s * x / n;
  }
  EXPECT_NEAR(law.elastic_energy(x), integral, 1e-7);
}

TEST(ContactLaw, RejectsBadParameters) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(ContactLaw::hertz_natural(-1.0), InvalidInput);
  EXPECT_THROW(ContactLaw::hertz_natural(nan), InvalidInput);
  EXPECT_THROW(ContactLaw::hertz_natural(inf), InvalidInput);
  EXPECT_THROW(ContactLaw::hertz_scaled(0.2, 0.0), InvalidInput);
  EXPECT_THROW(ContactLaw::hertz_scaled(0.2, -1.0), InvalidInput);
  EXPECT_THROW(ContactLaw::hertz_scaled(-0.2, 1.0), InvalidInput);
  EXPECT_THROW(ContactLaw::hertz_scaled(nan, 1.0), InvalidInput);
  EXPECT_THROW(ContactLaw::hertz_scaled(1e300, 1e300), InvalidInput);  // ζ overflows
  EXPECT_EQ(ContactLaw::linear_dashpot(0.0).zeta(), 0.0);              // r = 0: undamped, ε = 1 (issue 33)
  EXPECT_THROW(ContactLaw::linear_dashpot(-0.5), InvalidInput);
  EXPECT_THROW(ContactLaw::linear_dashpot(nan), InvalidInput);
  try {
    ContactLaw::hertz_natural(-2.5);
    FAIL();
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("zeta"), std::string::npos);
  }
}

}  // namespace
}  // namespace restitution
