// SPDX-License-Identifier: BSD-3-Clause
// calibrate_adhesive_sticking (restitution/adhesive_calibration.hpp): γ and A from ε at one speed plus the
// sticking speed. Round trip: (γ, A) -> ε(v), v_s by the forward solves -> calibrated back.
#include <gtest/gtest.h>

#include <string>

#include "restitution/adhesive_calibration.hpp"
#include "restitution/adhesive_contact.hpp"
#include "restitution/errors.hpp"

namespace {

using restitution::AdhesiveModel;

// µm water ice (docs/adhesion.md §7), two equal spheres.
restitution::Material ice() {
  restitution::Material m;
  m.young_modulus_pa = 7e9;
  m.poisson_ratio = 0.25;
  m.radius1_m = m.radius2_m = 1.5e-6;
  m.density_kg_m3 = 920.0;
  return m;
}

struct Measured {
  double eps, speed, sticking;
};

// The forward problem at T = 1e-12: what an experiment on this (γ, A) would measure at v = ratio·v_s.
Measured measure(AdhesiveModel model, double gamma, double a_s, double ratio) {
  const auto contact = restitution::adhesive_contact_of(model, ice(), gamma, a_s);
  const double sticking = restitution::sticking_speed(contact, 1e-12).speed_m_per_s;
  const double speed = ratio * sticking;
  return {restitution::solve_adhesive(contact, speed, 1e-12).eps, speed, sticking};
}

TEST(AdhesiveStickingCalibration, RecoversSurfaceEnergyAndDamping) {
  struct Case {
    AdhesiveModel model;
    double gamma, a_s, ratio;
  };
  // Weak to strong damping (ε from 0.97 to 0.01), near and far above v_s, γ on both sides of ice's.
  const Case cases[] = {
      {AdhesiveModel::jkr_lammps, 0.19, 1e-11, 5.0},
      {AdhesiveModel::jkr_lammps, 0.05, 1e-9, 1.2},
      {AdhesiveModel::jkr, 0.19, 3e-10, 1.2},
      {AdhesiveModel::jkr, 0.6, 1e-9, 5.0},
      {AdhesiveModel::dmt, 0.19, 1e-11, 1.2},
      {AdhesiveModel::dmt, 0.05, 3e-10, 5.0},
      // ε ≈ 0.01, near the critical damping above which there is no sticking speed (the bracket in A may
      // pass it: those trials count as ε = 0).
      {AdhesiveModel::jkr_lammps, 0.0016, 6.2e-9, 1.2},
  };
  for (const auto& c : cases) {
    const Measured m = measure(c.model, c.gamma, c.a_s, c.ratio);
    const auto found = restitution::calibrate_adhesive_sticking(c.model, ice(), m.eps, m.speed, m.sticking);
    const std::string what = restitution::adhesive_model_name(c.model) + " gamma " + std::to_string(c.gamma) +
                             " A " + std::to_string(c.a_s);
    EXPECT_NEAR(found.surface_energy_j_per_m2 / c.gamma, 1.0, 1e-7) << what;
    EXPECT_NEAR(found.dissipative_constant_s / c.a_s, 1.0, 1e-7) << what;
    EXPECT_NEAR(found.eps_at_velocity, m.eps, 1e-9) << what;
    EXPECT_NEAR(found.sticking_speed_m_per_s / m.sticking, 1.0, 1e-9) << what;
    EXPECT_LE(found.solves, 250) << what;
    EXPECT_LT(m.eps, found.undamped_eps) << what;
  }
}

// The largest ε reachable is the undamped limit sqrt(1 − (v_s/v)²): the elastic JKR closed form.
TEST(AdhesiveStickingCalibration, UndampedLimitIsTheElasticClosedForm) {
  const Measured elastic = measure(AdhesiveModel::jkr, 0.19, 0.0, 2.0);
  const auto just_below =
      restitution::calibrate_adhesive_sticking(AdhesiveModel::jkr, ice(), 0.999 * elastic.eps, 2.0, 1.0);
  EXPECT_NEAR(just_below.undamped_eps, elastic.eps, 1e-12);
  EXPECT_GT(just_below.dissipative_constant_s, 0.0);
}

TEST(AdhesiveStickingCalibration, RefusalsNameTheProblem) {
  struct Bad {
    AdhesiveModel model;
    double eps, speed, sticking;
    const char* word;
  };
  const Bad cases[] = {
      {AdhesiveModel::jkr, 0.5, 2.0, 2.0, "not below the impact speed"},
      {AdhesiveModel::jkr, 0.5, 2.0, 3.0, "not below the impact speed"},
      {AdhesiveModel::jkr, 0.0, 2.0, 1.0, "(0, 1)"},
      {AdhesiveModel::jkr, 1.0, 2.0, 1.0, "(0, 1)"},
      {AdhesiveModel::jkr, 0.9, 2.0, 1.0, "sqrt(1 - (v_s/v)^2)"},  // limit 0.866
      {AdhesiveModel::dmt, 0.9, 2.0, 1.0, "damping only lowers eps"},
      {AdhesiveModel::jkr, 0.5, 2.0, -1.0, "sticking speed must be finite and positive"},
      {AdhesiveModel::jkr, 0.5, -2.0, 1.0, "impact speed must be finite and positive"},
      {AdhesiveModel::sjkr, 0.5, 2.0, 1.0, "sjkr"},
  };
  for (const auto& c : cases) {
    try {
      (void)restitution::calibrate_adhesive_sticking(c.model, ice(), c.eps, c.speed, c.sticking);
      ADD_FAILURE() << "accepted " << c.word;
    } catch (const restitution::InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find(c.word), std::string::npos) << e.what();
    }
  }
}

}  // namespace
