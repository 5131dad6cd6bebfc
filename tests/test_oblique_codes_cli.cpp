// SPDX-License-Identifier: BSD-3-Clause
// `restitution oblique --tangential liggghts_history` end to end: the material, LIGGGHTS's arms (R - δ/2 in
// the torque and the contact-point velocity, on a wall too) and the default k_t = 8 G* reach the solve (the
// CLI's numbers are the library's with those inputs); `--tangential yade_viscel` exits 2 naming why.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "cli_runner.hpp"
#include "oblique/oblique_contact.hpp"

namespace {

using namespace restitution;
using namespace restitution::oblique;
using restitution::test_support::run_cli;

constexpr double kYoung = 2e11;  // Pa
constexpr double kPoisson = 0.3;
constexpr double kRadius = 1e-3;  // m
constexpr double kDensity = 7800.0;
constexpr double kDissipativeConstant = 1e-7;  // s
const std::string kSteel =
    "oblique --young-modulus 2e11 --poisson-ratio 0.3 --radius 1e-3 --density 7800 --dissipative-constant "
    "1e-7";

TEST(ObliqueCodesCli, LiggghtsHistoryOnAWallIsTheLibrarysWithLiggghtsArms) {
  const auto r =
      run_cli(kSteel +
              " --wall --wall-young-modulus 2e11 --wall-poisson-ratio 0.3 --tangential liggghts_history "
              "--tangential-damping 1 --friction 0.3 "
              "--angle 5,20,60 --spin 300 --tolerance 1e-10 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["tangential_model"], "liggghts_history");
  // 8 G* of one material: 2E/((2 - ν)(1 + ν)).
  const double kt = 2.0 * kYoung / ((2.0 - kPoisson) * (1.0 + kPoisson));
  EXPECT_NEAR(j["tangential_stiffness"].get<double>(), kt, 1e-12 * kt);
  const double mass = 4.0 / 3.0 * std::numbers::pi * kRadius * kRadius * kRadius * kDensity;
  // A wall of the sphere's material: E* = E/(2(1 - ν²)), R* = R; k = (4/3) E* sqrt(R), γ = (3/2) A k.
  const double k = 4.0 / 3.0 * kYoung / (2.0 * (1.0 - kPoisson * kPoisson)) * std::sqrt(kRadius);
  ObliqueGeometry geometry{solid_sphere(kRadius, mass), std::nullopt, TorqueArm::radius_minus_half_overlap};
  geometry.contact_point_arm = TorqueArm::radius_minus_half_overlap;
  ObliqueOptions options;
  options.relative_tolerance = 1e-13;  // the command's rtol for its contract at T = 1e-10
  ASSERT_EQ(j["impacts"].size(), 3U);
  for (const auto& impact : j["impacts"]) {
    const double angle = impact["angle_deg"].get<double>() * std::numbers::pi / 180.0;
    const ObliqueResult expected =
        solve_oblique(geometry, {LawKind::viscoelastic_hertz, k, 1.5 * kDissipativeConstant * k},
                      {TangentialKind::liggghts_history, kt, 1.0, 0.3},
                      {std::cos(angle), std::sin(angle), 300.0, 0.0}, options);
    EXPECT_NEAR(impact["tangential_restitution"].get<double>(), expected.tangential_restitution, 1e-9);
    EXPECT_NEAR(impact["spin_rad_s"].get<double>(), expected.spin_first_rad_s,
                1e-9 * std::abs(expected.spin_first_rad_s));
  }
  // The arms matter: LAMMPS's (R on a wall) give another spin.
  geometry.torque_arm = geometry.contact_point_arm = TorqueArm::radius;
  const double angle = 20.0 * std::numbers::pi / 180.0;
  const ObliqueResult lammps_arms =
      solve_oblique(geometry, {LawKind::viscoelastic_hertz, k, 1.5 * kDissipativeConstant * k},
                    {TangentialKind::liggghts_history, kt, 1.0, 0.3},
                    {std::cos(angle), std::sin(angle), 300.0, 0.0}, options);
  EXPECT_GT(std::abs(j["impacts"][1]["spin_rad_s"].get<double>() - lammps_arms.spin_first_rad_s), 1e-3);
}

TEST(ObliqueCodesCli, TableNamesLiggghts) {
  const auto r = run_cli(kSteel + " --tangential liggghts_history --friction 0.3 --angle 30");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("LIGGGHTS tangential history"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("N/m^2 (times sqrt(R* delta))"), std::string::npos) << r.out;
}

TEST(ObliqueCodesCli, YadeViscelIsRefusedNamingItsLinearNormalForce) {
  const auto r =
      run_cli(kSteel + " --tangential yade_viscel --tangential-stiffness 2e6 --friction 0.3 --angle 30");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("yade_viscel"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("linear normal force"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

}  // namespace
