// SPDX-License-Identifier: BSD-3-Clause
// The ε a DEM code's velocity-Verlet makes of the viscoelastic Hertz law at a finite time step
// (dem/integrator_eps.hpp): first order in dt towards the law's ε, the contact duration of the law, and the
// largest dt for an ε error bound.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "dem/integrator_eps.hpp"
#include "restitution/collision_solver.hpp"
#include "restitution/errors.hpp"
#include "restitution/material.hpp"

namespace {

using restitution::CollisionEnd;
namespace dem = restitution::dem;

// The gas of issue 35: Y = 1e8 Pa, nu = 0.4, rho = 920 kg/m3, R = 5 mm; A gives eps = 0.8 at 2 m/s.
constexpr double kDissipativeConstantS = 9.559975442e-06;

dem::Pair gas_pair() {
  restitution::Material m;
  m.young_modulus_pa = 1e8;
  m.poisson_ratio = 0.4;
  m.density_kg_m3 = 920.0;
  m.radius1_m = m.radius2_m = 0.005;
  return dem::pair_of(m);
}

TEST(IntegratorEps, ConvergesToTheLawAtFirstOrder) {
  restitution::CollisionSolver solver;
  for (CollisionEnd end : {CollisionEnd::delayed_recovery, CollisionEnd::naive}) {
    const auto coarse =
        dem::integrator_error(gas_pair(), kDissipativeConstantS, end, 2.0, 2e-6, 1e-10, solver);
    const auto fine = dem::integrator_error(gas_pair(), kDissipativeConstantS, end, 2.0, 2e-7, 1e-10, solver);
    EXPECT_GT(std::abs(coarse.mean_error), 1e-5);
    // First order: ten times smaller a step, about ten times smaller an error.
    EXPECT_NEAR(coarse.mean_error / fine.mean_error, 10.0, 2.0);
    EXPECT_LE(std::abs(fine.worst_error), 0.2 * std::abs(coarse.worst_error));
    EXPECT_GE(std::abs(coarse.worst_error), std::abs(coarse.mean_error));
  }
}

TEST(IntegratorEps, ElasticContactLastsHertzsDuration) {
  // A = 0: Hertz's duration. In natural units x'' = -x^{3/2} lasts 2 x_max (2/5) B(2/5, 1/2) with
  // x_max = (5/4)^{2/5}; the natural time is k^{-2/5} v^{-1/5}, k = (4/3) E* sqrt(R_eff) / m_eff.
  // Velocity-Verlet keeps eps = 1 up to its small phase error.
  restitution::CollisionSolver solver;
  const dem::Pair p = gas_pair();
  const double v = 2.0;
  const auto e = dem::integrator_error(p, 0.0, CollisionEnd::naive, v, 1e-6, 1e-10, solver);
  const double beta = std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);
  const double natural_duration = 2.0 * std::pow(1.25, 0.4) * 0.4 * beta;
  const double k = 4.0 / 3.0 * p.effective_modulus_pa * std::sqrt(p.effective_radius_m) / p.effective_mass_kg;
  const double hertz = natural_duration * std::pow(k, -0.4) * std::pow(v, -0.2);
  EXPECT_NEAR(e.contact_duration_s / hertz, 1.0, 1e-4);
  EXPECT_NEAR(e.eps_law, 1.0, 1e-9);
  EXPECT_LT(std::abs(e.worst_error), 1e-3);
}

TEST(IntegratorEps, LargestStepMeetsTheBoundAndNoMore) {
  restitution::CollisionSolver solver;
  const CollisionEnd end = CollisionEnd::delayed_recovery;
  for (double bound : {1e-4, 1e-3}) {
    const double dt =
        dem::largest_time_step_s(gas_pair(), kDissipativeConstantS, end, 6.0, bound, 1e-10, solver);
    const auto at = dem::integrator_error(gas_pair(), kDissipativeConstantS, end, 6.0, dt, 1e-10, solver);
    EXPECT_LE(std::abs(at.worst_error), bound);
    const auto above =
        dem::integrator_error(gas_pair(), kDissipativeConstantS, end, 6.0, 1.3 * dt, 1e-10, solver);
    EXPECT_GT(std::abs(above.worst_error), bound) << "dt = " << dt;
  }
  // Slower impacts last longer: a larger step meets the same bound.
  EXPECT_GT(dem::largest_time_step_s(gas_pair(), kDissipativeConstantS, end, 0.5, 1e-3, 1e-10, solver),
            dem::largest_time_step_s(gas_pair(), kDissipativeConstantS, end, 6.0, 1e-3, 1e-10, solver));
}

TEST(IntegratorEps, RefusesStepsOutOfRange) {
  restitution::CollisionSolver solver;
  const CollisionEnd end = CollisionEnd::delayed_recovery;
  for (double dt : {0.0, -1e-6, 1e-3, std::nan("")}) {
    try {
      dem::integrator_error(gas_pair(), kDissipativeConstantS, end, 2.0, dt, 1e-10, solver);
      ADD_FAILURE() << "dt = " << dt << " accepted";
    } catch (const restitution::InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find("--timestep"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(dem::largest_time_step_s(gas_pair(), kDissipativeConstantS, end, 2.0, 0.5, 1e-10, solver),
               restitution::InvalidInput);
}

}  // namespace
