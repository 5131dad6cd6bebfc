// SPDX-License-Identifier: BSD-3-Clause
// `restitution dem --wall` without running a code (tests/dem/wall_lammps.cpp runs LAMMPS): the wall line's
// numbers in LAMMPS's wall convention, the ε they give read back that way, the wall's material, the refusals
// (exit 2) and the check deck's text.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "cli_runner.hpp"
#include "dem/wall_lines.hpp"
#include "restitution/errors.hpp"

namespace {

using namespace restitution;
using namespace restitution::dem;

WallRequest steel_on_wall() {
  WallRequest r;
  r.sphere.young_modulus_pa = 2e11;
  r.sphere.poisson_ratio = 0.3;
  r.sphere.radius1_m = 1e-3;
  r.sphere.density_kg_m3 = 7800.0;
  r.damping.eps = 0.9;
  r.damping.velocity_m_s = 1.0;
  return r;
}

TEST(DemWall, RigidWallLineCarriesTheWallsModulus) {
  const WallResult w = wall_lines(steel_on_wall());
  const double e_star = 2e11 / (1.0 - 0.3 * 0.3);
  EXPECT_NEAR(w.contact.effective_modulus_pa, e_star, 1e-15 * e_star);
  // fix_wall_gran.cpp:160 reads E as (4/3) E/(2 (1 - nu)): E = 2 (1 - nu) E*, not the pair's Young's modulus.
  EXPECT_NEAR(w.deck.parameter("E"), 2.0 * 0.7 * e_star, 1e-15 * e_star);
  const double mass = 4.0 / 3.0 * std::numbers::pi * 1e-9 * 7800.0;
  EXPECT_NEAR(w.contact.effective_mass_kg, mass, 1e-15 * mass);
  EXPECT_NEAR(w.deck.parameter("eta_n0"), 2.0 * w.dissipative_constant_s * e_star / mass,
              1e-13 * w.deck.parameter("eta_n0"));
  ASSERT_EQ(w.deck.lines.size(), 1U);
  EXPECT_EQ(w.deck.lines[0].rfind("fix wall all wall/gran granular hertz/material ", 0), 0U)
      << w.deck.lines[0];
  EXPECT_NE(w.deck.lines[0].find(" limit_damping zplane 0 NULL"), std::string::npos);
  // Read back as the wall reads it, the lines give the calibrated ε at the calibration speed, and ε falls
  // with speed.
  ASSERT_EQ(w.eps.size(), 3U);
  EXPECT_NEAR(w.eps[1].eps, 0.9, 1e-9);
  EXPECT_GT(w.eps[0].eps, w.eps[1].eps);
  EXPECT_GT(w.eps[1].eps, w.eps[2].eps);
}

TEST(DemWall, WallOfItsOwnMaterialHalvesTheCompliance) {
  WallRequest r = steel_on_wall();
  r.wall = WallMaterial{2e11, 0.3};
  r.damping = {1e-7, std::nullopt, std::nullopt};
  r.friction = 0.3;
  const WallResult w = wall_lines(r);
  const double e_star = 2e11 / (2.0 * (1.0 - 0.3 * 0.3));
  EXPECT_NEAR(w.contact.effective_modulus_pa, e_star, 1e-15 * e_star);
  EXPECT_FALSE(w.rigid_wall);
  // Mindlin as a number: 8 G*, 1/G* = 2 (2 - nu)/G, G = Y/(2 (1 + nu)).
  const double g_star = 2e11 / (2.0 * 2.0 * 1.7 * 1.3);
  const std::string expected = "tangential mindlin ";
  const auto at = w.deck.lines[0].find(expected);
  ASSERT_NE(at, std::string::npos) << w.deck.lines[0];
  EXPECT_NEAR(std::stod(w.deck.lines[0].substr(at + expected.size())), 8.0 * g_star, 1e-12 * g_star);
}

TEST(DemWall, CodesWithoutWallLinesAndBadWallsAreRefused) {
  for (const Code code : {Code::liggghts, Code::yade, Code::mercurydpm, Code::chrono}) {
    WallRequest r = steel_on_wall();
    r.code = code;
    try {
      (void)wall_lines(r);
      ADD_FAILURE() << code_name(code) << " accepted";
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find(code_name(code)), std::string::npos) << e.what();
    }
  }
  WallRequest r = steel_on_wall();
  r.wall = WallMaterial{2e11, 0.5};
  EXPECT_THROW((void)wall_lines(r), InvalidInput);
  r.wall = WallMaterial{-1.0, 0.3};
  EXPECT_THROW((void)wall_lines(r), InvalidInput);
}

TEST(DemWall, CheckDeckPastesTheLineAndPrintsOneCheckPerSpeed) {
  const WallResult w = wall_lines(steel_on_wall());
  const std::string deck = wall_check_deck(w);
  std::size_t pasted = 0;
  for (auto at = deck.find(w.deck.lines[0]); at != std::string::npos; at = deck.find(w.deck.lines[0], at + 1))
    ++pasted;
  EXPECT_EQ(pasted, 2U) << "once per pass";
  std::size_t checks = 0;
  for (auto at = deck.find("print \"restitution-check code=lammps types=1,0"); at != std::string::npos;
       at = deck.find("print \"restitution-check", at + 1))
    ++checks;
  EXPECT_EQ(checks, w.eps.size());
}

TEST(DemWall, CommandLineRefusalsExitTwo) {
  const std::string sphere =
      " --young-modulus 2e11 --poisson-ratio 0.3 --radius 1e-3 --density 7800 --eps 0.9 --velocity 1";
  for (const std::string& extra :
       {std::string(" --code lammps --wall --wall-young-modulus 2e11"),
        std::string(" --code lammps --wall --radius2 2e-3"), std::string(" --code liggghts --wall"),
        std::string(" --code lammps --wall-poisson-ratio 0.3 --wall-young-modulus 1e9"),
        std::string(" --code lammps --wall --timestep 1e-7")}) {
    const auto out = test_support::run_cli("dem" + extra + sphere);
    EXPECT_EQ(out.status, 2) << extra << ": " << out.err;
    EXPECT_NE(out.err.find("wall"), std::string::npos) << extra << ": " << out.err;
  }
}

}  // namespace
