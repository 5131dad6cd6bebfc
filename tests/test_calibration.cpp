// SPDX-License-Identifier: BSD-3-Clause
// Calibration: β from a measured ε by root finding on ζ. Checked against the 2008 paper's example, by
// round trips through the solver, and at the command line.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <optional>

#include "cli_runner.hpp"
#include "material_examples.hpp"
#include "restitution/calibration.hpp"
#include "restitution/errors.hpp"
#include "restitution/material.hpp"
#include "restitution/series.hpp"

namespace restitution {
namespace {

double eps_at(double zeta, CollisionEnd end) {
  CollisionSolver solver;
  SolveOptions o;
  o.ends = EndSet{end};
  const CollisionResult r = solver.solve(ContactLaw::hertz_natural(zeta), o);
  return end == CollisionEnd::naive ? r[CollisionEnd::naive]->eps : r[CollisionEnd::delayed_recovery]->eps;
}

Calibration calibrated(double eps, double velocity_m_s, std::optional<double> k = std::nullopt) {
  CollisionSolver solver;
  CalibrationRequest request;
  request.eps = eps;
  request.velocity_m_s = velocity_m_s;
  request.k = k;
  return calibrate(request, solver);
}

TEST(Calibration, PaperExampleRubberSphere) {
  // 2008 paper, Sec. VI: ε = 0.8 at v = 1 m/s gives β = 0.2 s^{1/5} m^{-1/5} (delayed recovery). The solver
  // has ε(ζ = 0.2) = 0.80097 > 0.8, so the exact β lies a little above 0.2.
  const Calibration c = calibrated(0.8, 1.0);
  EXPECT_GT(c.beta, 0.2);
  EXPECT_LT(c.beta, 0.205);
  EXPECT_NEAR(c.eps_at_zeta, 0.8, 1e-9);
  EXPECT_NEAR(eps_at(c.zeta, CollisionEnd::delayed_recovery), 0.8, 1e-9);
  EXPECT_NEAR(c.characteristic_velocity_m_s, std::pow(series::c1_closed_form() * c.beta, -5.0), 1e-9);
}

TEST(Calibration, RootReproducesEpsAtBothEndsAndManyTargets) {
  CollisionSolver solver;
  SolveOptions o;
  for (const CollisionEnd end : {CollisionEnd::naive, CollisionEnd::delayed_recovery}) {
    for (const double eps : {0.999, 0.9, 0.5, 0.05, 1e-4}) {
      const double zeta = zeta_for_eps(eps, end, o, solver);
      EXPECT_NEAR(eps_at(zeta, end) / eps, 1.0, 1e-8) << end_name(end) << " eps " << eps;
    }
  }
}

// Small ε (issue 12, item 1): the root finder must work on log ε itself, since 1 - ε rounds to 1 and
// log1p(-(1 - ε)) loses every digit of ε below about 1e-8. ε(ζ) re-solved at the root must hold the
// tolerance.
TEST(Calibration, SmallNaiveTargetsHoldTheTolerance) {
  CollisionSolver solver;
  SolveOptions o;
  for (const double eps : {1e-8, 1e-12, 1e-16, 1e-25}) {
    const double zeta = zeta_for_eps(eps, CollisionEnd::naive, o, solver);
    EXPECT_NEAR(eps_at(zeta, CollisionEnd::naive) / eps, 1.0, 5e-10) << "eps " << eps;
  }
}

TEST(Calibration, BetaScalesWithTheFifthRootOfVelocity) {
  const Calibration at_1 = calibrated(0.7, 1.0);
  const Calibration at_32 = calibrated(0.7, 32.0);
  EXPECT_NEAR(at_32.zeta, at_1.zeta, 1e-10);
  EXPECT_NEAR(at_32.beta, at_1.beta / 2.0, 1e-10);  // 32^{1/5} = 2
}

TEST(Calibration, RecoversTheDissipativeConstantOfAMaterial) {
  const MaterialConstants c = material_constants(test_support::rubber_like());
  const double v = 2.5;
  const Calibration back =
      calibrated(eps_at(zeta_from(c.hertz.beta, v), CollisionEnd::delayed_recovery), v, c.hertz.k);
  ASSERT_TRUE(back.dissipative_constant_s.has_value());
  EXPECT_NEAR(*back.dissipative_constant_s / 5.8e-5, 1.0, 1e-8);
}

TEST(Calibration, RejectsTargetsOutsideTheRange) {
  CollisionSolver solver;
  SolveOptions o;
  EXPECT_THROW((void)zeta_for_eps(1.0, CollisionEnd::naive, o, solver), InvalidInput);
  EXPECT_THROW((void)zeta_for_eps(0.0, CollisionEnd::naive, o, solver), InvalidInput);
  // Below ε at the largest checked ζ (delayed recovery: ε(1e6) ~ 1.3e-10; naive: ε(1e6) ~ 5e-30).
  EXPECT_THROW((void)zeta_for_eps(1e-12, CollisionEnd::delayed_recovery, o, solver), InvalidInput);
  EXPECT_THROW((void)zeta_for_eps(1e-31, CollisionEnd::naive, o, solver), InvalidInput);
  CalibrationRequest request;
  request.eps = 0.5;
  request.velocity_m_s = -1.0;
  EXPECT_THROW((void)calibrate(request, solver), InvalidInput);
}

TEST(CalibrateCommand, JsonWithMaterial) {
  const auto r = test_support::run_cli(
      "calibrate --eps 0.8 --velocity 1 --young-modulus 1e7 --poisson-ratio 0.45 --radius 0.01 --density "
      "1100 "
      "--json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["end"], "delayed-recovery");
  EXPECT_NEAR(j["beta"].get<double>(), 0.2011, 1e-3);
  EXPECT_NEAR(j["dissipative_constant_s"].get<double>(), 5.8e-5, 1e-6);  // the rubber-like material's A
  EXPECT_GT(j["characteristic_velocity_m_s"].get<double>(), 0.0);
}

TEST(CalibrateCommand, BadInputExitsWithStatus2NamingIt) {
  auto r = test_support::run_cli("calibrate --eps 1.5 --velocity 1");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("eps"), std::string::npos);
  r = test_support::run_cli(
      "calibrate --eps 0.5 --velocity 1 --young-modulus 1e7 --poisson-ratio 0.7 --radius 0.01 "
      "--density 1000");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("poisson_ratio"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace restitution
