// SPDX-License-Identifier: BSD-3-Clause
// The oblique contact (src/oblique/) against its closed forms: a contact that slides throughout changes the
// contact-point velocity by μ(1 + ε) v_n (1 + m* R1²/I1 + m* R2²/I2) whatever the normal law; a frictionless
// contact leaves the tangential velocity and the spins as they were; the normal restitution is the head-on ε.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "oblique/oblique_contact.hpp"
#include "oblique_steel.hpp"
#include "restitution/collision_solver.hpp"
#include "restitution/errors.hpp"

namespace {

using namespace restitution;
using namespace restitution::oblique;

using namespace restitution::test_support::oblique_steel;  // kRadius, kMass, kHertzStiffness, kHertzDamping

// LAMMPS's tangential models (pair_granular.cpp:56-59).
constexpr std::array kLammpsModels{TangentialKind::linear_nohistory, TangentialKind::linear_history,
                                   TangentialKind::mindlin,          TangentialKind::mindlin_rescale,
                                   TangentialKind::mindlin_force,    TangentialKind::mindlin_rescale_force};

ObliqueGeometry wall_geometry() {
  return {solid_sphere(kRadius, kMass), std::nullopt, TorqueArm::radius};
}

ObliqueGeometry pair_geometry() {
  // Unequal spheres, one of them hollow-ish, so that both rotation terms count and differ; the normal of the
  // impact kept throughout, as the closed form has it.
  return {solid_sphere(kRadius, kMass), Body{1.5e-3, 2.0 * kMass, 0.55 * 2.0 * kMass * 1.5e-3 * 1.5e-3},
          TorqueArm::radius, /*fixed_normal=*/true};
}

double rotation_factor(const ObliqueGeometry& g) {
  const double m = effective_mass_kg(g);
  double factor = 1.0 + m * g.first.radius_m * g.first.radius_m / g.first.inertia_kg_m2;
  if (g.second) factor += m * g.second->radius_m * g.second->radius_m / g.second->inertia_kg_m2;
  return factor;
}

ImpactVelocity at_angle(double degrees, double speed = 1.0) {
  return {speed, speed * std::tan(degrees * std::numbers::pi / 180.0), 0.0, 0.0};
}

struct NormalCase {
  const char* name;
  NormalForce normal;
  CollisionEnd end;
};

std::vector<NormalCase> normal_cases() {
  return {
      {"damped Hertz, delayed end",
       {LawKind::viscoelastic_hertz, kHertzStiffness, kHertzDamping},
       CollisionEnd::delayed_recovery},
      {"elastic Hertz", {LawKind::viscoelastic_hertz, kHertzStiffness, 0.0}, CollisionEnd::naive},
      {"linear dash-pot, delayed end", {LawKind::linear_dashpot, 1e7, 0.05}, CollisionEnd::delayed_recovery}};
}

// Slides throughout: a single mode, slip, from first contact to the end.
void expect_gross_sliding(const ObliqueResult& r, const ImpactVelocity& v, const ObliqueGeometry& g,
                          double mu, const std::string& label) {
  ASSERT_EQ(r.switches.size(), 1U) << label;
  EXPECT_EQ(r.switches[0].mode, ContactMode::slip) << label;
  const double slip0 = v.tangential_m_s + g.first.radius_m * v.spin_first_rad_s +
                       (g.second ? g.second->radius_m * v.spin_second_rad_s : 0.0);
  const double expected_change = -mu * (1.0 + r.normal_restitution) * v.normal_m_s * rotation_factor(g);
  const double change = r.slip_velocity_m_s - slip0;
  EXPECT_NEAR(change, expected_change, 1e-10 * std::abs(expected_change)) << label;
  // The impulse ratio of a slide is μ (the force is μ F_n throughout).
  EXPECT_NEAR(r.impulse_ratio, -mu, 1e-10 * mu) << label;
}

TEST(ObliqueGrossSliding, WallChangesSlipByTheClosedFormForEveryModelAndLaw) {
  const double mu = 0.1;
  for (const NormalCase& n : normal_cases()) {
    for (const TangentialKind kind : kLammpsModels) {
      // Grazing and stiff enough that the slip starts at once and never stops (mindlin starts sliding where
      // κ_m|s| > μ in natural units, Maw et al.'s ψ; elastic, mindlin/force slides throughout only from
      // ψ₁ = 4χ − 1, beyond what 1e10 N/m² gives here); linear_nohistory needs its viscous force beyond the
      // cap.
      const double stiffness = kind == TangentialKind::mindlin ? 1e10 : is_lammps_mindlin(kind) ? 1e11 : 2e6;
      const double damping_factor = kind == TangentialKind::linear_nohistory ? 1e4 : 0.5;
      const TangentialForce t{kind, stiffness, damping_factor, mu};
      const ImpactVelocity v = at_angle(80.0);
      ObliqueOptions options;
      options.end = n.end;
      options.relative_tolerance = 1e-12;
      if (kind == TangentialKind::linear_nohistory && n.normal.damping == 0.0) continue;  // no viscous force
      // mindlin on the dash-pot sticks first (its stiffness grows from 0 under a cap that does not: LAMMPS
      // sticks there too, tests/test_oblique_accuracy.cpp): no slide throughout.
      if (is_lammps_mindlin(kind) && n.normal.kind == LawKind::linear_dashpot) continue;
      const ObliqueResult r = solve_oblique(wall_geometry(), n.normal, t, v, options);
      expect_gross_sliding(r, v, wall_geometry(), mu, std::string(n.name) + " / " + tangential_name(kind));
    }
  }
}

TEST(ObliqueGrossSliding, PairWithSpinsChangesSlipByTheClosedForm) {
  const double mu = 0.25;
  const ObliqueGeometry g = pair_geometry();
  ImpactVelocity v = at_angle(70.0, 2.0);
  v.spin_first_rad_s = 300.0;
  v.spin_second_rad_s = -100.0;
  ObliqueOptions options;
  options.relative_tolerance = 1e-12;
  const NormalForce n{LawKind::viscoelastic_hertz, kHertzStiffness, kHertzDamping};
  const ObliqueResult r = solve_oblique(g, n, {TangentialKind::linear_history, 2e6, 0.3, mu}, v, options);
  expect_gross_sliding(r, v, g, mu, "pair");
  // Each spin changes by R_i m* Δu / I_i: the torques are the arms times the one tangential force.
  const double du = r.tangential_velocity_m_s - v.tangential_m_s;
  const double m = effective_mass_kg(g);
  EXPECT_NEAR(r.spin_first_rad_s - v.spin_first_rad_s, g.first.radius_m * m * du / g.first.inertia_kg_m2,
              1e-9 * std::abs(r.spin_first_rad_s - v.spin_first_rad_s));
  EXPECT_NEAR(r.spin_second_rad_s - v.spin_second_rad_s,
              g.second->radius_m * m * du / g.second->inertia_kg_m2,
              1e-9 * std::abs(r.spin_second_rad_s - v.spin_second_rad_s));
}

// The linear dash-pot with a linear tangential spring (the model of Becker, Schwager & Pöschel, PRE 77,
// 011304 (2008)) in its sticking limit μ -> ∞, on a wall: the slip obeys ξ'' + 2β_t ξ' + ω_t² ξ = 0 with ω_t²
// = k_t K/m, 2β_t = γ_t γ_n K/m, K = 1 + m R²/I = 7/2, during the delayed-recovery contact of the dash-pot,
// t_c = (π - atan(2β ω_d/(ω0² - 2β²)))/ω_d, ω0² = k_n/m, β = γ_n/(2m), ω_d² = ω0² - β²: so
// e_t = -s(t_c)/s0 = -e^{-β_t t_c}(cos Ω t_c - (β_t/Ω) sin Ω t_c), Ω² = ω_t² - β_t². μ = 1e9: the cap
// vanishes with F_n at the end, where a finite μ slides for the last ~1/μ of the contact (e_t moves by
// ~1e-10); k_t/k_n = 2/7 undamped gives e_t = 1 (ω_t = ω0).
TEST(ObliqueLinearSpring, StickingLimitIsTheDampedOscillatorOverTheDashpotContact) {
  const double kn = 1e7;
  const double kk = 3.5;  // 1 + m R²/I, solid sphere
  for (const double gamma_n : {0.0, 0.05}) {
    for (const double kt_ratio : {2.0 / 7.0, 0.2, 0.5, 1.0}) {
      for (const double gamma_t : {0.0, 0.5}) {
        const double kt = kt_ratio * kn;
        const double omega0 = std::sqrt(kn / kMass);
        const double beta = gamma_n / (2.0 * kMass);
        const double omega_d = std::sqrt(omega0 * omega0 - beta * beta);
        const double tc =
            (std::numbers::pi - std::atan2(2.0 * beta * omega_d, omega0 * omega0 - 2.0 * beta * beta)) /
            omega_d;
        const double beta_t = gamma_t * gamma_n * kk / (2.0 * kMass);
        const double big_omega = std::sqrt(kt * kk / kMass - beta_t * beta_t);
        const double expected = -std::exp(-beta_t * tc) *
                                (std::cos(big_omega * tc) - beta_t / big_omega * std::sin(big_omega * tc));
        ObliqueOptions options;
        options.relative_tolerance = 1e-12;
        const ObliqueResult r =
            solve_oblique(wall_geometry(), {LawKind::linear_dashpot, kn, gamma_n},
                          {TangentialKind::linear_history, kt, gamma_t, 1e9}, at_angle(30.0), options);
        const std::string label = fmt::format("gamma_n={} kt/kn={} gamma_t={}", gamma_n, kt_ratio, gamma_t);
        EXPECT_NEAR(r.contact_time_s, tc, 1e-10 * tc) << label;
        EXPECT_NEAR(r.tangential_restitution, expected, 1e-9) << label;
        EXPECT_EQ(r.switches.front().mode, ContactMode::stick) << label;
      }
    }
  }
}

TEST(ObliqueFrictionless, LeavesTangentialVelocityAndSpinUnchanged) {
  for (const TangentialKind kind : kLammpsModels) {
    ImpactVelocity v = at_angle(30.0);
    v.spin_first_rad_s = 123.0;
    const NormalForce n{LawKind::viscoelastic_hertz, kHertzStiffness, kHertzDamping};
    const ObliqueResult r = solve_oblique(wall_geometry(), n, {kind, 1e9, 0.5, 0.0}, v);
    EXPECT_EQ(r.tangential_velocity_m_s, v.tangential_m_s) << tangential_name(kind);
    EXPECT_EQ(r.spin_first_rad_s, v.spin_first_rad_s) << tangential_name(kind);
    EXPECT_DOUBLE_EQ(r.tangential_restitution, -1.0) << tangential_name(kind);
    EXPECT_EQ(r.impulse_ratio, 0.0) << tangential_name(kind);
  }
}

// A pair whose line of centres turns: without friction the normal force is central, so an elastic contact is
// a scattering: the relative speed is kept and the outgoing velocity is the incoming one mirrored about the
// apse line, the line of centres at maximal compression, halfway through the turn θ (the orbit is symmetric).
TEST(ObliqueTurningNormal, FrictionlessElasticPairIsACentralForceScattering) {
  ObliqueGeometry g = pair_geometry();
  g.fixed_normal = false;
  const NormalForce elastic{LawKind::viscoelastic_hertz, kHertzStiffness, 0.0};
  for (const double angle : {10.0, 45.0, 80.0}) {
    const ImpactVelocity v = at_angle(angle, 3.0);
    ObliqueOptions options;
    options.relative_tolerance = 1e-12;
    const ObliqueResult r =
        solve_oblique(g, elastic, {TangentialKind::linear_history, 2e6, 0.0, 0.0}, v, options);
    const double speed0 = std::hypot(v.normal_m_s, v.tangential_m_s);
    const double speed1 = std::hypot(r.normal_velocity_m_s, r.tangential_velocity_m_s);
    EXPECT_NEAR(speed1, speed0, 1e-10 * speed0) << angle;
    EXPECT_GT(r.line_of_centres_turn_rad, 0.0) << angle;
    // The incoming relative velocity (u, -v_n) mirrored about the apse n = (sin θ/2, cos θ/2): v - 2 (v·n) n.
    const double th = 0.5 * r.line_of_centres_turn_rad;
    const double vn = v.tangential_m_s * std::sin(th) - v.normal_m_s * std::cos(th);
    EXPECT_NEAR(r.tangential_velocity_m_s, v.tangential_m_s - 2.0 * vn * std::sin(th), 1e-9 * speed0)
        << angle;
    EXPECT_NEAR(r.normal_velocity_m_s, -v.normal_m_s - 2.0 * vn * std::cos(th), 1e-9 * speed0) << angle;
  }
}

TEST(ObliqueNormal, RestitutionIsTheHeadOnOne) {
  // The normal motion does not feel the tangential force: ε and the contact time are the head-on solve's.
  const NormalForce n{LawKind::viscoelastic_hertz, kHertzStiffness, kHertzDamping};
  ObliqueOptions options;
  options.relative_tolerance = 1e-12;
  const ObliqueResult r = solve_oblique(wall_geometry(), n, {TangentialKind::linear_history, 2e6, 0.5, 0.3},
                                        at_angle(20.0), options);
  const ContactLaw law =
      ContactLaw::physical(LawKind::viscoelastic_hertz, kHertzStiffness, kHertzDamping, kMass, 1.0);
  CollisionSolver solver;
  SolveOptions head_on;
  head_on.ends = EndSet{CollisionEnd::delayed_recovery};
  const CollisionResult c = solver.solve(law, head_on);
  const EndResult& end = *c[CollisionEnd::delayed_recovery];
  EXPECT_NEAR(r.normal_restitution, end.eps, 1e-9);
  const double time_scale = physical_time_scale_s(LawKind::viscoelastic_hertz, kHertzStiffness, kMass, 1.0);
  EXPECT_NEAR(r.contact_time_s, end.tau * time_scale, 1e-8 * end.tau * time_scale);
  EXPECT_NEAR(r.stick_time_s + r.slip_time_s, r.contact_time_s, 1e-12 * r.contact_time_s);
}

TEST(ObliqueInput, RefusesBadArgumentsNamingThem) {
  const NormalForce n{LawKind::viscoelastic_hertz, kHertzStiffness, kHertzDamping};
  const TangentialForce t{TangentialKind::linear_history, 2e6, 0.5, 0.3};
  const auto message = [&](const ObliqueGeometry& g, const NormalForce& nf, const TangentialForce& tf,
                           const ImpactVelocity& v) {
    try {
      solve_oblique(g, nf, tf, v);
    } catch (const InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(wall_geometry(), n, {TangentialKind::linear_history, 2e6, 0.5, -0.1}, at_angle(10))
                .find("friction"),
            std::string::npos);
  EXPECT_NE(
      message(wall_geometry(), n, {TangentialKind::mindlin, 0.0, 0.5, 0.1}, at_angle(10)).find("mindlin"),
      std::string::npos);
  EXPECT_NE(message({Body{0.0, kMass, 1.0}, std::nullopt}, n, t, at_angle(10)).find("radius"),
            std::string::npos);
  EXPECT_NE(message(wall_geometry(), n, t, {0.0, 1.0, 0.0, 0.0}).find("normal impact speed"),
            std::string::npos);
  EXPECT_NE(message(wall_geometry(), n, t, {1.0, 0.0, 0.0, 5.0}).find("wall"), std::string::npos);
  EXPECT_NE(
      message(wall_geometry(), {LawKind::viscoelastic_hertz, -1.0, 0.0}, t, at_angle(10)).find("stiffness"),
      std::string::npos);
}

TEST(ObliqueNames, RoundTripAndRefuseUnknown) {
  for (const std::string& name : tangential_names())
    EXPECT_EQ(tangential_name(tangential_from_name(name)), name);
  try {
    tangential_from_name("mindlin/rescale");  // LAMMPS spells it mindlin_rescale
    FAIL() << "accepted an unsupported model";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("mindlin/rescale"), std::string::npos);
  }
}

}  // namespace
