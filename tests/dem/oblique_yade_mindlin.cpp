// SPDX-License-Identifier: BSD-3-Clause
// Debian's YADE (2023.02a) on oblique impacts against src/oblique/'s yade_mindlin: FrictMat (Y, ν, ρ,
// frictionAngle) under Ip2_FrictMat_FrictMat_MindlinPhys(betan) and Law2_ScGeom_MindlinPhys_Mindlin, the
// lines `restitution dem --code yade --friction MU` prints: the Tsuji normal force kno δ^{3/2} + 2 betan
// sqrt(m* kn) δ' (kn = 1.5 kno sqrt(δ)) clamped at 0 and the incremental shear spring ks = kso sqrt(δ),
// capped at tan(frictionAngle) F_n, cs = 2 betas sqrt(m* ks) added below the cap (betas = betan). A 1 mm
// steel sphere on a `utils.wall` and two equal spheres, the oblique angles from 1° to 85°, spin 0 and 300
// rad/s. Each scene holds one collision per angle (10 mm apart) and runs at dt = t_c/n and t_c/(10 n), n =
// 20000; the outputs are Richardson-extrapolated (YADE's leap-frog is first order in dt here). e_t, the
// rebound angle and the spins agree within 1e-4 relative (1e-5 absolute near 0); measured |Δe_t| <= 3.6e-6.
// What the runs pin down (each alone moves e_t by 1e-3 or more): the delayed-recovery end (the naive one is
// 5.8e-2 off), betas = betan, the incremental spring, the torque arm to ScGeom's contact point (R - δ/2 for
// two spheres, R - δ for the wall) and the contact-point velocity of getIncidentVel's ratcheting-free form:
// the spins at the arm R, the centres' relative velocity times (R1 + R2)/(R1 + R2 - δ), a wall's radius
// counting as the sphere's (without that gain e_t was up to 2.2e-3 off where the contact sticks).
// ObliqueYadeMindlinDemLines runs the lines `dem --code yade --friction` prints (steel, glass, steel at ε =
// 0.98) as printed, at the printed timestep and a tenth of it, against the printed outputs; it also measures
// YADE's e_t error coefficient C (N |Δe_t| <= C, the yade_mindlin row's et_error_coefficient in
// src/oblique/tangential_models.cpp), and runs the check deck `--deck` writes for the same lines.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "dem/oblique_runs.hpp"
#include "dem/yade_runner.hpp"
#include "oblique/oblique_contact.hpp"

namespace {

using namespace restitution;
using namespace restitution::oblique;
using restitution::test_support::slurp;
using restitution::test_support::TempFolder;

constexpr double kRadius = 1e-3;
constexpr double kDensity = 7800.0;
constexpr double kYoung = 2e11;
constexpr double kPoisson = 0.3;
constexpr double kBetan = 0.1;
constexpr double kFriction = 0.3;
const double kMass = 4.0 / 3.0 * std::numbers::pi * kRadius * kRadius * kRadius * kDensity;
const std::vector<double>& kAnglesDeg = restitution::test_support::kObliqueAnglesDeg;
constexpr int kCoarseSteps = 20000;

using Outcome = restitution::test_support::ObliqueOutcome;
using restitution::test_support::impact_at;
using restitution::test_support::run_yade_oblique;

// Ip2_FrictMat_FrictMat_MindlinPhys::go for two bodies of one material: E* = Y/(2(1 - ν²)), G = Y/(2(1 + ν)),
// R* from the geometry's radii (a wall's refR1 is not positive, so both are the sphere's: R* = R/2 there
// too), kno = (4/3) E* sqrt(R*), kso = 2 sqrt(4 R*) G/(2 - ν).
struct Mindlin {
  NormalForce normal;
  TangentialForce tangential;
};
Mindlin mindlin_of(double effective_mass_kg) {
  const double e_star = kYoung / (2.0 * (1.0 - kPoisson * kPoisson));
  const double shear_modulus = kYoung / (2.0 * (1.0 + kPoisson));
  const double r_star = kRadius / 2.0;
  const double kno = 4.0 / 3.0 * e_star * std::sqrt(r_star);
  const double kso = 2.0 * std::sqrt(4.0 * r_star) * shear_modulus / (2.0 - kPoisson);
  Mindlin m;
  m.normal = {LawKind::tsuji_hertz, kno, 2.0 * kBetan * std::sqrt(1.5 * effective_mass_kg * kno)};
  m.tangential = {TangentialKind::yade_mindlin, kso, std::sqrt(kso / (1.5 * kno)), kFriction};
  return m;
}

// The lines as `restitution dem --code yade` prints them: FrictMat, Ip2 and Law2.
std::vector<std::string> printed_style_lines() {
  std::ostringstream material;
  material.precision(17);
  material << "O.materials.append(FrictMat(young=" << kYoung << ", poisson=" << kPoisson
           << ", density=" << kDensity << ", frictionAngle=" << std::atan(kFriction) << "))";
  std::ostringstream ip2;
  ip2.precision(17);
  ip2 << "Ip2_FrictMat_FrictMat_MindlinPhys(betan=MatchMaker(algo='val', val=" << kBetan << "))";
  return {material.str(), ip2.str(), "Law2_ScGeom_MindlinPhys_Mindlin()"};
}

// (wall, initial spin [rad/s])
class ObliqueYadeMindlin : public ::testing::TestWithParam<std::tuple<bool, double>> {};

TEST_P(ObliqueYadeMindlin, ImpactsAgreeWithin1e4) {
  const auto [wall, spin] = GetParam();
  const std::string program = dem::yade_program();
  ASSERT_FALSE(program.empty()) << "yade not found on PATH: scripts/setup installs Debian's yade";
  // The torque reaches ScGeom's contact point; the contact-point velocity takes the spins at R.
  const TorqueArm arm = wall ? TorqueArm::radius_minus_overlap : TorqueArm::radius_minus_half_overlap;
  ObliqueGeometry geometry{solid_sphere(kRadius, kMass), std::nullopt, arm};
  geometry.contact_point_arm = TorqueArm::radius;
  if (!wall) geometry.second = solid_sphere(kRadius, kMass);
  ObliqueOptions options;
  options.relative_tolerance = 1e-12;
  options.end = CollisionEnd::delayed_recovery;
  const Mindlin m = mindlin_of(effective_mass_kg(geometry));
  std::vector<ObliqueResult> predicted;
  double shortest = 1.0;
  double longest = 0.0;
  for (const double angle : kAnglesDeg) {
    predicted.push_back(solve_oblique(geometry, m.normal, m.tangential, impact_at(angle, spin), options));
    shortest = std::min(shortest, predicted.back().contact_time_s);
    longest = std::max(longest, predicted.back().contact_time_s);
  }
  const double dt = shortest / kCoarseSteps;
  const auto coarse =
      run_yade_oblique(program, printed_style_lines(), kAnglesDeg, wall, spin, dt, 1.1 * longest);
  const auto fine =
      run_yade_oblique(program, printed_style_lines(), kAnglesDeg, wall, spin, dt / 10.0, 1.1 * longest);
  double largest = 0.0;
  for (std::size_t i = 0; i < kAnglesDeg.size(); ++i) {
    const std::string label = std::string(wall ? "wall" : "pair") + " at " + std::to_string(kAnglesDeg[i]) +
                              " deg, spin " + std::to_string(spin);
    largest = std::max(largest, restitution::test_support::expect_extrapolated_agreement(
                                    coarse[i], fine[i], predicted[i], !wall, kRadius, label));
  }
  restitution::test_support::record_largest_et_difference(largest);
}

INSTANTIATE_TEST_SUITE_P(Cases, ObliqueYadeMindlin,
                         ::testing::Combine(::testing::Bool(), ::testing::Values(0.0, 300.0)));

// `restitution dem --code yade --friction 0.3 --yade-version 2023.02a` (the betan lines; steel, A = 1e-7 s)
// prints the oblique impacts of its lines at --angle: Debian's YADE, given the lines as printed, agrees.
// At the printed timestep (the steps per contact for e_t within 1e-4) YADE's own e_t is within 1e-4; at a
// tenth of it, extrapolated, within 1e-5, and the rebound angle and the spins within 1e-4 relative.
class ObliqueYadeMindlinDemLines : public ::testing::TestWithParam<const char*> {};

TEST_P(ObliqueYadeMindlinDemLines, YadeGivesThePrintedObliqueOutputs) {
  const std::string program = dem::yade_program();
  ASSERT_FALSE(program.empty()) << "yade not found on PATH: scripts/setup installs Debian's yade";
  const auto r = restitution::test_support::run_cli(
      std::string(
          "dem --code yade --radius 1e-3 --yade-version 2023.02a --angle 1,5,15,30,45,60,75,85 --json ") +
      GetParam());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto out = nlohmann::json::parse(r.out);
  std::vector<std::string> yade_lines;
  for (const auto& line : out["lines"]) yade_lines.push_back(line.get<std::string>());
  const auto& impacts = out["oblique"]["impacts"];
  ASSERT_EQ(out["oblique"]["speed_m_s"].get<double>(), 1.0);
  std::vector<double> angles;
  double longest = 0.0;
  double shortest = HUGE_VAL;
  for (const auto& i : impacts) {
    angles.push_back(i["angle_deg"].get<double>());
    longest = std::max(longest, i["contact_time_s"].get<double>());
    shortest = std::min(shortest, i["contact_time_s"].get<double>());
  }
  const double dt = out["oblique"]["yade_steps"]["timestep_s"].get<double>();
  const double accuracy = out["oblique"]["yade_steps"]["et_accuracy"].get<double>();
  const auto coarse = run_yade_oblique(program, yade_lines, angles, false, 0.0, dt, 1.1 * longest);
  const auto fine = run_yade_oblique(program, yade_lines, angles, false, 0.0, dt / 10.0, 1.1 * longest);
  const auto extrapolate = restitution::test_support::extrapolate_first_order;
  double largest_scaled_error = 0.0;  // N |Δe_t| at N = shortest contact / dt steps per contact
  for (std::size_t i = 0; i < angles.size(); ++i) {
    const auto& p = impacts[i];
    const double et = p["tangential_restitution"].get<double>();
    const std::string where = "at " + std::to_string(angles[i]) + " deg";
    EXPECT_NEAR(coarse[i].et, et, accuracy) << where << ", at the printed timestep";
    largest_scaled_error = std::max(largest_scaled_error, std::abs(coarse[i].et - et) * shortest / dt);
    EXPECT_NEAR(extrapolate(coarse[i].et, fine[i].et), et, 1e-5) << where;
    const double rebound = p["rebound_angle_deg"].get<double>();
    EXPECT_NEAR(extrapolate(coarse[i].rebound_deg, fine[i].rebound_deg), rebound,
                1e-4 * std::abs(rebound) + 1e-5)
        << where;
    const double spin = p["spin_rad_s"].get<double>();
    EXPECT_NEAR(extrapolate(coarse[i].spin, fine[i].spin), spin, 1e-4 * std::abs(spin) + 1e-5 / kRadius)
        << where;
    const double spin2 = p["spin2_rad_s"].get<double>();
    EXPECT_NEAR(extrapolate(coarse[i].spin2, fine[i].spin2), spin2, 1e-4 * std::abs(spin2) + 1e-5 / kRadius)
        << where;
  }
  std::cout << "largest N |e_t(N) - e_t| at the printed timestep: " << largest_scaled_error << "\n";
}

// `--deck FILE` with friction: the check deck, run as `yade -n -x FILE`, prints the head-on check lines and
// one restitution-oblique-check line per listed angle, YADE's e_t extrapolated from t_c/20000 and t_c/200000
// against the printed one: |diff| <= 1e-5 (measured: <= 8.3e-7 for steel at A = 1e-7 s).
TEST_P(ObliqueYadeMindlinDemLines, CheckDeckCoversTheObliqueImpacts) {
  const std::string program = dem::yade_program();
  ASSERT_FALSE(program.empty()) << "yade not found on PATH: scripts/setup installs Debian's yade";
  TempFolder folder;
  const std::string deck = (folder.path / "check.py").string();
  const auto r = restitution::test_support::run_cli(
      std::string("dem --code yade --radius 1e-3 --yade-version 2023.02a --json --deck ") + deck + " " +
      GetParam());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto out = nlohmann::json::parse(r.out);
  const auto& impacts = out["oblique"]["impacts"];
  const std::string output_path = (folder.path / "out.txt").string();
  const std::string command = program + " -n -x " + deck + " > " + output_path + " 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << slurp(output_path);
  std::istringstream text(slurp(output_path));
  std::size_t head_on = 0;
  std::size_t oblique = 0;
  double largest = 0.0;
  for (std::string line; std::getline(text, line);) {
    if (line.rfind("restitution-check ", 0) == 0) ++head_on;
    if (line.rfind("restitution-oblique-check code=yade contact=pair ", 0) != 0) continue;
    ASSERT_LT(oblique, impacts.size()) << line;
    const auto field = [&](const std::string& key) {
      const std::size_t at = line.find(" " + key + "=");
      EXPECT_NE(at, std::string::npos) << key << " in " << line;
      return std::stod(line.substr(at + key.size() + 2));
    };
    const double et = impacts[oblique]["tangential_restitution"].get<double>();
    EXPECT_EQ(field("angle"), impacts[oblique]["angle_deg"].get<double>()) << line;
    EXPECT_EQ(field("et_restitution"), et) << line;
    EXPECT_NEAR(field("et_code"), (10.0 * field("et_dt") - field("et_10dt")) / 9.0, 1e-13) << line;
    EXPECT_NEAR(field("diff"), field("et_code") - et, 1e-13) << line;
    EXPECT_NEAR(field("diff"), 0.0, 1e-5) << line;
    largest = std::max(largest, std::abs(field("diff")));
    ++oblique;
  }
  EXPECT_EQ(head_on, 3U);  // v/10, v, 10 v
  EXPECT_EQ(oblique, impacts.size());
  restitution::test_support::record_largest_et_difference(largest);
}

// Steel at A = 1e-7 s (ε = 0.914), glass at ε = 0.7 and μ = 0.5, steel at ε = 0.98 and μ = 0.1.
INSTANTIATE_TEST_SUITE_P(
    Materials, ObliqueYadeMindlinDemLines,
    ::testing::Values("--young-modulus 2e11 --poisson-ratio 0.3 --density 7800 --dissipative-constant 1e-7 "
                      "--friction 0.3",
                      "--young-modulus 6e10 --poisson-ratio 0.25 --density 2500 --eps 0.7 --velocity 1 "
                      "--friction 0.5",
                      "--young-modulus 2e11 --poisson-ratio 0.3 --density 7800 --eps 0.98 --velocity 1 "
                      "--friction 0.1"));

}  // namespace
