// SPDX-License-Identifier: BSD-3-Clause
// The stick/slip events of the oblique contact (src/oblique/) against an independent reference
// (tests/oblique_reference.hpp: SI units, long double, RK4 with graded fixed steps, bisection on the crossing
// step, the slip -> stick condition by numerical differentiation of LAMMPS's step rule): near-head-on impacts
// of linear_history contacts stick, slide and stick again within one collision.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "oblique/oblique_contact.hpp"
#include "oblique_reference.hpp"
#include "oblique_steel.hpp"

namespace {

using namespace restitution;
using namespace restitution::oblique;

using namespace restitution::test_support::oblique_steel;  // kRadius, kMass, kHertzStiffness, kHertzDamping
constexpr double kTangentialStiffness = 2.2e6;  // N/m, about 2/7 of the normal contact stiffness at 1 m/s
constexpr double kTangentialDamping = 0.5;
constexpr double kFriction = 0.3;

struct Case {
  double angle_deg;
  bool pair;
  std::vector<ContactMode> modes;  // the expected sequence (a regression guard on the case's physics)
};

class ObliqueEvents : public ::testing::TestWithParam<Case> {};

TEST_P(ObliqueEvents, SwitchTimesAndOutputsMatchTheReference) {
  const Case& c = GetParam();
  ObliqueGeometry g{solid_sphere(kRadius, kMass), std::nullopt, TorqueArm::radius};
  if (c.pair) g.second = solid_sphere(2.0 * kRadius, 8.0 * kMass);
  g.fixed_normal = true;  // as the reference
  const ImpactVelocity v{1.0, std::tan(c.angle_deg * std::numbers::pi / 180.0), 0.0, 0.0};
  ObliqueOptions options;
  options.relative_tolerance = 1e-12;
  const NormalForce normal{LawKind::viscoelastic_hertz, kHertzStiffness, kHertzDamping};
  const TangentialForce tangential{TangentialKind::linear_history, kTangentialStiffness, kTangentialDamping,
                                   kFriction};
  const ObliqueResult r = solve_oblique(g, normal, tangential, v, options);

  oblique_reference::Integrator reference(reference_problem(g, normal, tangential, v));
  const oblique_reference::Outcome fine = reference.run(r.contact_time_s / 2e4);
  const oblique_reference::Outcome coarse = reference.run(r.contact_time_s / 1e4);
  const auto tc = static_cast<double>(fine.contact_time);
  // The reference is converged far below what is checked.
  ASSERT_EQ(fine.switches.size(), coarse.switches.size());
  for (std::size_t i = 0; i < fine.switches.size(); ++i) {
    ASSERT_NEAR(static_cast<double>(fine.switches[i].time), static_cast<double>(coarse.switches[i].time),
                1e-11 * tc);
  }

  ASSERT_EQ(r.switches.size(), c.modes.size());
  ASSERT_EQ(fine.switches.size(), c.modes.size());
  for (std::size_t i = 0; i < c.modes.size(); ++i) {
    EXPECT_EQ(r.switches[i].mode, c.modes[i]) << "switch " << i;
    EXPECT_EQ(fine.switches[i].stick, c.modes[i] == ContactMode::stick) << "reference switch " << i;
    EXPECT_NEAR(r.switches[i].time_s, static_cast<double>(fine.switches[i].time), 1e-9 * tc)
        << "switch " << i;
  }
  EXPECT_NEAR(r.contact_time_s, tc, 1e-9 * tc);
  EXPECT_NEAR(r.normal_restitution, static_cast<double>(fine.eps), 1e-9);
  const auto et = static_cast<double>(-fine.slip_final / fine.slip_initial);
  EXPECT_NEAR(r.tangential_restitution, et, 1e-8 * std::abs(et));
}

using M = ContactMode;
INSTANTIATE_TEST_SUITE_P(
    StickSlipStick, ObliqueEvents,
    ::testing::Values(
        // Sticks, slides from 1.8e-8 s, sticks again from 1.0e-7 s, slides in the last 4 % of the contact.
        Case{20.0, false, {M::stick, M::slip, M::stick, M::slip}},
        Case{25.0, false, {M::stick, M::slip, M::stick, M::slip}},
        // Starts sliding (γ_t |s| > μ v_n), sticks, slides, sticks and slides again.
        Case{45.0, false, {M::slip, M::stick, M::slip, M::stick, M::slip}},
        Case{5.0, false, {M::stick, M::slip}}, Case{20.0, true, {M::stick, M::slip, M::stick, M::slip}}));

}  // namespace
