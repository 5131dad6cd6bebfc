// SPDX-License-Identifier: BSD-3-Clause
// YADE's Hertz-Mindlin (yade_mindlin: the incremental shear spring ks = kso sqrt(δ) over the Tsuji normal
// force, the elastic force tested and capped alone) against closed forms: a grazing elastic impact slides
// throughout and changes the slip by -μ(1 + ε) v_n (1 + m R²/I); a frictionless one keeps u and the spins;
// the incremental spring (F_e' = -ks(δ) s) is not the total form -ks(δ) ξ of LIGGGHTS's history, though both
// have the same tangent stiffness and the same gross sliding.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "oblique/oblique_contact.hpp"
#include "oblique_steel.hpp"

namespace {

using namespace restitution;
using namespace restitution::oblique;
using namespace restitution::test_support::oblique_steel;  // kRadius, kMass, kHertzStiffness

constexpr double kShearCoefficient = 1e10;  // kso [N/m^{3/2}]: ks = kso sqrt(δ)

ObliqueGeometry wall() {
  // YADE's arms: the torque to the contact point R - δ, the spins' velocity at R.
  return {solid_sphere(kRadius, kMass), std::nullopt, TorqueArm::radius_minus_overlap,
          /*fixed_normal=*/false, TorqueArm::radius};
}

ObliqueGeometry fixed_pair() {
  return {solid_sphere(kRadius, kMass), Body{1.5e-3, 2.0 * kMass, 0.55 * 2.0 * kMass * 1.5e-3 * 1.5e-3},
          TorqueArm::radius, /*fixed_normal=*/true};
}

double rotation_factor(const ObliqueGeometry& g) {
  const double m = effective_mass_kg(g);
  double factor = 1.0 + m * g.first.radius_m * g.first.radius_m / g.first.inertia_kg_m2;
  if (g.second) factor += m * g.second->radius_m * g.second->radius_m / g.second->inertia_kg_m2;
  return factor;
}

ImpactVelocity at_angle(double degrees, double spin = 0.0) {
  return {1.0, std::tan(degrees * std::numbers::pi / 180.0), spin, 0.0};
}

ObliqueOptions tight(CollisionEnd end) {
  ObliqueOptions o;
  o.end = end;
  o.relative_tolerance = 1e-12;
  return o;
}

// Undamped, the cap μ kno δ^{3/2} and the incremental spring's (2/3) kso δ^{3/2} |s| grow alike: a stiff
// spring slides from the start and, grazing, throughout; the wall's arm R - δ moves the spin, not the slip's
// closed form (which holds for the arm at the end, R).
TEST(YadeMindlin, GrossSlidingChangesSlipByTheClosedForm) {
  const double mu = 0.1;
  const NormalForce elastic{LawKind::tsuji_hertz, kHertzStiffness, 0.0};
  ObliqueOptions options = tight(CollisionEnd::delayed_recovery);
  options.relative_tolerance = 1e-13;
  for (const bool pair : {false, true}) {
    ObliqueGeometry g = pair ? fixed_pair() : wall();
    // The closed form takes the arm R throughout.
    g.torque_arm = g.contact_point_arm = TorqueArm::radius;
    const ImpactVelocity v = at_angle(80.0, pair ? -200.0 : 100.0);
    const ObliqueResult r = solve_oblique(
        g, elastic, {TangentialKind::yade_mindlin, 1e3 * kShearCoefficient, 0.0, mu}, v, options);
    const std::string label = pair ? "pair" : "wall";
    ASSERT_EQ(r.switches.size(), 1U) << label;
    EXPECT_EQ(r.switches[0].mode, ContactMode::slip) << label;
    const double s0 = v.tangential_m_s + g.first.radius_m * v.spin_first_rad_s;
    const double expected = -mu * (1.0 + r.normal_restitution) * v.normal_m_s * rotation_factor(g);
    EXPECT_NEAR(r.slip_velocity_m_s - s0, expected, 1e-10 * std::abs(expected)) << label;
    EXPECT_NEAR(r.impulse_ratio, -mu, 1e-10 * mu) << label;
  }
}

TEST(YadeMindlin, FrictionlessKeepsTangentialVelocityAndSpin) {
  const NormalForce damped{LawKind::tsuji_hertz, kHertzStiffness, 0.05};
  const ImpactVelocity v = at_angle(30.0, 300.0);
  const ObliqueResult r =
      solve_oblique(wall(), damped, {TangentialKind::yade_mindlin, kShearCoefficient, 0.8, 0.0}, v,
                    tight(CollisionEnd::delayed_recovery));
  EXPECT_DOUBLE_EQ(r.tangential_velocity_m_s, v.tangential_m_s);
  EXPECT_DOUBLE_EQ(r.spin_first_rad_s, v.spin_first_rad_s);
  EXPECT_GT(r.normal_restitution, 0.0);
  EXPECT_LT(r.normal_restitution, 1.0);
}

// LIGGGHTS's history with kt sqrt(R* δ) and the same tangent stiffness (kt sqrt(R*) = kso), no tangential
// damping: where the contact slides throughout the two agree (the capped force is the same), where it sticks
// while δ changes they do not (-d(k ξ)/dt = -k s - k' ξ against YADE's -k s).
TEST(YadeMindlin, IncrementalSpringIsNotTheTotalForm) {
  const NormalForce elastic{LawKind::tsuji_hertz, kHertzStiffness, 0.0};
  const auto solve = [&](TangentialKind kind, double angle) {
    const double stiffness =
        kind == TangentialKind::yade_mindlin ? kShearCoefficient : kShearCoefficient / std::sqrt(kRadius);
    return solve_oblique(wall(), elastic, {kind, stiffness, 0.0, 0.3}, at_angle(angle),
                         tight(CollisionEnd::delayed_recovery));
  };
  const ObliqueResult yade_grazing = solve(TangentialKind::yade_mindlin, 85.0);
  const ObliqueResult total_grazing = solve(TangentialKind::liggghts_history, 85.0);
  EXPECT_NEAR(yade_grazing.tangential_restitution, total_grazing.tangential_restitution, 1e-9);
  const ObliqueResult yade_stuck = solve(TangentialKind::yade_mindlin, 10.0);
  const ObliqueResult total_stuck = solve(TangentialKind::liggghts_history, 10.0);
  EXPECT_GT(std::abs(yade_stuck.tangential_restitution - total_stuck.tangential_restitution), 1e-3);
}

TEST(YadeMindlin, NamedAndParsed) {
  EXPECT_STREQ(tangential_name(TangentialKind::yade_mindlin), "yade_mindlin");
  EXPECT_EQ(tangential_from_name("yade_mindlin"), TangentialKind::yade_mindlin);
}

}  // namespace
