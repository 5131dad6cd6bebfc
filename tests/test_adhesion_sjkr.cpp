// SPDX-License-Identifier: BSD-3-Clause
// LIGGGHTS's sjkr cohesion on Hertz (restitution/adhesion.hpp, AdhesiveModel::sjkr) against the energy
// balance of the elastic model (ε = 1: the force is conservative and ends at δ = 0) and an independent
// fixed-step RK4 integration in time of the force as LIGGGHTS writes it (cohesion_model_sjkr.h).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "restitution/adhesion.hpp"
#include "restitution/errors.hpp"

namespace {

using restitution::AdhesiveContact;
using restitution::AdhesiveModel;
using restitution::AdhesiveOutcome;
constexpr double kPi = std::numbers::pi;

struct Spheres {
  double r1, r2, density;
};

// Soft mm spheres (Y = 5 MPa, ν = 0.45): the overlap reaches a few % of R, where the lens area matters.
AdhesiveContact soft(const Spheres& s, double cohesion, double gamman) {
  const double young = 5e6, poisson = 0.45;
  const double m1 = 4.0 / 3.0 * kPi * s.r1 * s.r1 * s.r1 * s.density;
  const double m2 = 4.0 / 3.0 * kPi * s.r2 * s.r2 * s.r2 * s.density;
  AdhesiveContact c;
  c.model = AdhesiveModel::sjkr;
  c.effective_modulus_pa = young / (2.0 * (1.0 - poisson * poisson));
  c.effective_radius_m = s.r1 * s.r2 / (s.r1 + s.r2);
  c.effective_mass_kg = m1 * m2 / (m1 + m2);
  c.damping = gamman;
  c.cohesion_energy_density_j_per_m3 = cohesion;
  c.sphere_radius_1_m = s.r1;
  c.sphere_radius_2_m = s.r2;
  return c;
}

// LIGGGHTS's normal force on the pair at overlap δ > 0 and approach speed v (hertz/stiffness + sjkr),
// written from its source: centre distance r, lens area −(π/4)(r−ri−rj)(r+ri−rj)(r−ri+rj)(r+ri+rj)/r².
double liggghts_force(const AdhesiveContact& c, double overlap, double speed) {
  const double ri = c.sphere_radius_1_m, rj = c.sphere_radius_2_m, r = ri + rj - overlap;
  const double area = -kPi / 4.0 * ((r - ri - rj) * (r + ri - rj) * (r - ri + rj) * (r + ri + rj)) / (r * r);
  const double polyhertz = std::sqrt(c.effective_radius_m * overlap);
  const double hertz = (4.0 / 3.0) * c.effective_modulus_pa * polyhertz * overlap;
  return hertz + c.damping * c.effective_mass_kg * polyhertz * speed -
         c.cohesion_energy_density_j_per_m3 * area;
}

// RK4 in time on δ'' = −F/m* from δ = 0, δ' = v until δ < 0 again (returns |δ'|/v) or the spheres turn
// back inwards while overlapping (returns 0: stuck).
double rk4_eps(const AdhesiveContact& c, double v, double dt) {
  auto accel = [&](double d, double s) {
    return d > 0.0 ? -liggghts_force(c, d, s) / c.effective_mass_kg : 0.0;
  };
  double d = 0.0, s = v;
  bool receding = false;
  for (long step = 0; step < 100000000L; ++step) {
    const double k1d = s, k1s = accel(d, s);
    const double k2d = s + 0.5 * dt * k1s, k2s = accel(d + 0.5 * dt * k1d, s + 0.5 * dt * k1s);
    const double k3d = s + 0.5 * dt * k2s, k3s = accel(d + 0.5 * dt * k2d, s + 0.5 * dt * k2s);
    const double k4d = s + dt * k3s, k4s = accel(d + dt * k3d, s + dt * k3s);
    d += dt / 6.0 * (k1d + 2.0 * k2d + 2.0 * k3d + k4d);
    s += dt / 6.0 * (k1s + 2.0 * k2s + 2.0 * k3s + k4s);
    if (s < 0.0) receding = true;
    if (receding && s > 0.0 && d > 0.0) return 0.0;
    // Overdamped: at rest inside the cohesive well (never turning inwards again), bound as well.
    if (receding && d > 0.0 && std::abs(s) < 1e-9 * v) return 0.0;
    if (d < 0.0) return -s / v;
  }
  return -1.0;
}

TEST(AdhesionSjkr, ElasticIsConservative) {
  const auto c = soft({1e-3, 1e-3, 2500.0}, 1e5, 0.0);
  for (const double v : {1e-3, 0.01, 0.1, 1.0}) {
    const auto r = restitution::solve_adhesive(c, v);
    EXPECT_EQ(r.outcome, AdhesiveOutcome::bounced) << v;
    EXPECT_NEAR(r.eps, 1.0, 1e-12) << v;
    EXPECT_NEAR(r.one_minus_eps, 0.0, 1e-12) << v;
  }
  EXPECT_EQ(restitution::sticking_speed(c).speed_m_per_s, 0.0);
  EXPECT_EQ(restitution::elastic_hysteresis_work_j(c), 0.0);
  EXPECT_EQ(restitution::break_overlap_m(c), 0.0);
}

TEST(AdhesionSjkr, DampedMatchesIndependentIntegration) {
  for (const Spheres s : {Spheres{1e-3, 1e-3, 2500.0}, Spheres{1e-3, 3e-4, 2500.0}}) {
    const auto c = soft(s, 1e5, 2e4);
    for (const double v : {0.02, 0.1, 1.0}) {
      const auto r = restitution::solve_adhesive(c, v);
      ASSERT_EQ(r.outcome, AdhesiveOutcome::bounced) << v;
      const double reference = rk4_eps(c, v, r.contact_time_s / 4e5);
      EXPECT_NEAR(r.eps, reference, 1e-9) << "r2 " << s.r2 << " v " << v;
    }
  }
}

TEST(AdhesionSjkr, SticksBelowTheStickingSpeed) {
  const auto c = soft({1e-3, 1e-3, 2500.0}, 1e5, 2e4);
  const double vs = restitution::sticking_speed(c).speed_m_per_s;
  ASSERT_GT(vs, 0.0);
  EXPECT_EQ(restitution::solve_adhesive(c, 0.97 * vs).outcome, AdhesiveOutcome::stuck);
  EXPECT_EQ(rk4_eps(c, 0.97 * vs, 1e-8), 0.0);
  EXPECT_EQ(restitution::solve_adhesive(c, 1.03 * vs).outcome, AdhesiveOutcome::bounced);
  EXPECT_GT(rk4_eps(c, 1.03 * vs, 1e-8), 0.0);
}

// Strong damping (LIGGGHTS's gamman for A = 1e-4 s, the damping number c ≈ 1.2): the spheres stick at every
// impact speed, so there is no sticking speed. The search used to double the speed until CVODE ran out of
// steps ("too much work"); it now stops at 1e6 speed units and says so.
TEST(AdhesionSjkr, StrongDampingHasNoStickingSpeed) {
  const auto c = soft({1e-3, 1e-3, 2500.0}, 1e5, 1.1974039605659839e8);
  try {
    (void)restitution::sticking_speed(c);
    ADD_FAILURE() << "a sticking speed for a contact that sticks at every speed";
  } catch (const restitution::InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("no sticking speed"), std::string::npos) << e.what();
  }
  for (const double v : {0.01, 0.3, 3.0, 100.0, 1e4}) {
    const auto r = restitution::solve_adhesive(c, v);
    EXPECT_EQ(r.outcome, AdhesiveOutcome::stuck) << v;
    if (v <= 3.0) EXPECT_EQ(rk4_eps(c, v, r.contact_time_s / 4e5), 0.0) << v;
  }
}

TEST(AdhesionSjkr, EqualSpheresByDefault) {
  auto c = soft({1e-3, 1e-3, 2500.0}, 1e5, 2e4);
  const double given = restitution::solve_adhesive(c, 0.05).eps;
  c.sphere_radius_1_m = c.sphere_radius_2_m = 0.0;
  EXPECT_EQ(restitution::solve_adhesive(c, 0.05).eps, given);
}

TEST(AdhesionSjkr, BadInputNamesTheProblem) {
  auto c = soft({1e-3, 1e-3, 2500.0}, 0.0, 0.0);
  EXPECT_THROW((void)restitution::solve_adhesive(c, 0.1), restitution::InvalidInput);
  c.cohesion_energy_density_j_per_m3 = 1e5;
  c.sphere_radius_2_m = 2e-3;  // R no longer 0.5 mm
  EXPECT_THROW((void)restitution::solve_adhesive(c, 0.1), restitution::InvalidInput);
  EXPECT_EQ(restitution::adhesive_model_from_name("sjkr"), AdhesiveModel::sjkr);
}

}  // namespace
