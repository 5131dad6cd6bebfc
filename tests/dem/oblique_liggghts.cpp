// SPDX-License-Identifier: BSD-3-Clause
// Debian's LIGGGHTS (3.8.0+repack1) on oblique impacts against `restitution oblique --tangential
// liggghts_history`: the lines `restitution dem --code liggghts --friction 0.3` prints (hertz/stiffness with
// `tangential history`, kt = 8 G*, gammat = gamman), with `tangential_damping on` (as printed) and `off`; a
// sphere on a `fix wall/gran` primitive wall and two equal spheres, nine impact angles from nearly head-on
// (1°) to grazing (85°), with and without initial spin (300 rad/s). One deck holds one collision per angle
// (10 mm apart); it runs at dt = t_c/n and t_c/(10 n) and every output is Richardson-extrapolated (fix
// nve/sphere is first order in dt for these forces). n = 20000: with damping LIGGGHTS decides stick or slip
// on the elastic force once per step while the damped stick force may exceed the cap, and at n = 2000 the
// extrapolation is off by up to 2e-5 in e_t (1.5e-4 deg in the rebound angle). e_t, the rebound angle and
// the spins agree within 1e-4 relative (1e-5 absolute where e_t is near 0); measured |Δe_t| <= 4.6e-9
// without tangential damping, <= 1.7e-6 with it. At A = 1e-6 s (ObliqueLiggghtsCap) the impacts that slide on
// the cap are flagged and off LIGGGHTS; the others agree.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "dem/code_runner.hpp"
#include "dem/oblique_runs.hpp"

namespace {

using namespace restitution;
using restitution::test_support::run_cli;
using restitution::test_support::run_liggghts_oblique;

constexpr double kRadius = restitution::test_support::kObliqueRunRadius;
const std::string kMaterial =
    "--young-modulus 2e11 --poisson-ratio 0.3 --radius 1e-3 --density 7800 --dissipative-constant 1e-7 "
    "--friction 0.3";
const std::vector<double>& kAnglesDeg = restitution::test_support::kObliqueAnglesDeg;
// The LIGGGHTS wall carries the pair's kn: a wall of the sphere's own material (`oblique --wall` alone is
// rigid).
const std::string kOwnWall = " --wall --wall-young-modulus 2e11 --wall-poisson-ratio 0.3";
constexpr int kCoarseSteps = 20000;

using Outcome = restitution::test_support::ObliqueOutcome;

std::string angle_list() {
  std::string list;
  for (const double a : kAnglesDeg) list += (list.empty() ? "" : ",") + std::to_string(a);
  return list;
}

nlohmann::json cli_json(const std::string& arguments) {
  const auto outcome = run_cli(arguments + " --json");
  EXPECT_EQ(outcome.status, 0) << arguments << "\n" << outcome.err;
  return nlohmann::json::parse(outcome.out);
}

// gamman and gammat carry 1/m_eff (the note of the lines): on a wall m_eff is the sphere's mass, twice the
// pair's, so the wall's lines take half the numbers to model the same A.
void halve_damping_for_the_wall(const nlohmann::json& dem, std::vector<std::string>& lines) {
  for (const auto& [index, name] : {std::pair{2, "gamman"}, std::pair{3, "gammat"}}) {
    std::ostringstream line;
    line.precision(17);
    line << "fix dem_" << name << " all property/global " << name << " peratomtypepair 1 "
         << 0.5 * dem.at("parameters").at(name).get<double>();
    lines[static_cast<std::size_t>(index)] = line.str();
  }
}

// (wall, tangential damping on, initial spin [rad/s])
class ObliqueLiggghts : public ::testing::TestWithParam<std::tuple<bool, bool, double>> {};

TEST_P(ObliqueLiggghts, ImpactsAgreeWithin1e4) {
  const auto [wall, damped, spin] = GetParam();
  const std::string program = dem::dem_program(dem::Code::liggghts);
  ASSERT_FALSE(program.empty()) << "liggghts not found on PATH: scripts/setup installs Debian's liggghts";
  const nlohmann::json dem = cli_json("dem --code liggghts " + kMaterial);
  std::vector<std::string> lines = dem.at("lines").get<std::vector<std::string>>();
  ASSERT_EQ(lines.size(), 7U);
  ASSERT_EQ(lines[5], "pair_style gran model hertz/stiffness tangential history limitForce on");
  // gamman and gammat carry 1/m_eff (the note of the lines): on a wall m_eff is the sphere's mass, twice the
  // pair's, so the wall's lines take half the numbers to model the same A.
  if (wall) halve_damping_for_the_wall(dem, lines);
  if (!damped) {
    lines[5] =
        "pair_style gran model hertz/stiffness tangential history tangential_damping off limitForce on";
  }
  const nlohmann::json predicted =
      cli_json("oblique " + kMaterial + " --tangential liggghts_history --tangential-damping " +
               (damped ? "1" : "0") + (wall ? kOwnWall : "") + " --angle " + angle_list() + " --spin " +
               std::to_string(spin) + " --tolerance 1e-10");
  const auto& impacts = predicted.at("impacts");
  ASSERT_EQ(impacts.size(), kAnglesDeg.size());
  double shortest = 1.0;
  double longest = 0.0;
  for (const auto& impact : impacts) {
    shortest = std::min(shortest, impact.at("contact_time_s").get<double>());
    longest = std::max(longest, impact.at("contact_time_s").get<double>());
  }
  const double dt = shortest / kCoarseSteps;
  const auto coarse = run_liggghts_oblique(program, lines, wall, spin, dt, 1.1 * longest, kAnglesDeg);
  const auto fine = run_liggghts_oblique(program, lines, wall, spin, dt / 10.0, 1.1 * longest, kAnglesDeg);
  const auto extrapolate = restitution::test_support::extrapolate_first_order;
  double largest = 0.0;
  for (std::size_t i = 0; i < kAnglesDeg.size(); ++i) {
    const auto& p = impacts[i];
    const double et_predicted = p.at("tangential_restitution").get<double>();
    const double et = extrapolate(coarse[i].et, fine[i].et);
    const double rebound = extrapolate(coarse[i].rebound_deg, fine[i].rebound_deg);
    const double omega = extrapolate(coarse[i].spin, fine[i].spin);
    const std::string label = std::string(wall ? "wall" : "pair") + (damped ? ", damped" : ", undamped") +
                              " at " + std::to_string(kAnglesDeg[i]) + " deg, spin " + std::to_string(spin) +
                              ": coarse e_t " + std::to_string(coarse[i].et) + ", fine " +
                              std::to_string(fine[i].et);
    EXPECT_NEAR(et, et_predicted, std::max(1e-4 * std::abs(et_predicted), 1e-5)) << label;
    largest = std::max(largest, std::abs(et - et_predicted));
    const double rebound_deg = p.at("rebound_angle_deg").get<double>();
    EXPECT_NEAR(rebound, rebound_deg, 1e-4 * std::abs(rebound_deg) + 1e-5) << label;
    const double spin1 = p.at("spin_rad_s").get<double>();
    EXPECT_NEAR(omega, spin1, 1e-4 * std::abs(spin1) + 1e-5 / kRadius) << label;
    if (!wall) {
      const double spin2 = p.at("spin2_rad_s").get<double>();
      EXPECT_NEAR(extrapolate(coarse[i].spin2, fine[i].spin2), spin2, 1e-4 * std::abs(spin2) + 1e-5 / kRadius)
          << label;
    }
  }
  restitution::test_support::record_largest_et_difference(largest);
}

INSTANTIATE_TEST_SUITE_P(Cases, ObliqueLiggghts,
                         ::testing::Combine(::testing::Bool(), ::testing::Bool(),
                                            ::testing::Values(0.0, 300.0)));

// A = 1e-6 s (ε ≈ 0.52), 300 rad/s, damping as printed, near 45°: where the contact slides on the cap
// (LIGGGHTS alternating capped and uncapped steps) the oblique outputs are flagged as not modelled, and
// LIGGGHTS indeed differs there; every impact not flagged agrees with LIGGGHTS within 1e-4.
TEST(ObliqueLiggghtsCap, ImpactsSlidingOnTheCapAreFlaggedAndTheOthersAgree) {
  const std::string program = dem::dem_program(dem::Code::liggghts);
  ASSERT_FALSE(program.empty()) << "liggghts not found on PATH: scripts/setup installs Debian's liggghts";
  std::string material = kMaterial;
  material.replace(material.find("--dissipative-constant 1e-7"), 27, "--dissipative-constant 1e-6");
  const std::vector<double> angles{40.0, 44.0, 45.0, 46.0, 48.0};
  std::string list;
  for (const double a : angles) list += (list.empty() ? "" : ",") + std::to_string(a);
  for (const bool wall : {false, true}) {
    const nlohmann::json dem = cli_json("dem --code liggghts " + material);
    std::vector<std::string> lines = dem.at("lines").get<std::vector<std::string>>();
    if (wall) halve_damping_for_the_wall(dem, lines);
    const auto outcome =
        run_cli("oblique " + material + " --tangential liggghts_history --tangential-damping 1" +
                (wall ? kOwnWall : "") + " --angle " + list + " --spin 300 --json");
    ASSERT_EQ(outcome.status, 0) << outcome.err;
    const nlohmann::json predicted = nlohmann::json::parse(outcome.out);
    const auto& impacts = predicted.at("impacts");
    double shortest = 1.0;
    double longest = 0.0;
    for (const auto& impact : impacts) {
      shortest = std::min(shortest, impact.at("contact_time_s").get<double>());
      longest = std::max(longest, impact.at("contact_time_s").get<double>());
    }
    const double dt = shortest / kCoarseSteps;
    const auto coarse = run_liggghts_oblique(program, lines, wall, 300.0, dt, 1.1 * longest, angles);
    const auto fine = run_liggghts_oblique(program, lines, wall, 300.0, dt / 10.0, 1.1 * longest, angles);
    std::size_t flagged = 0;
    for (std::size_t i = 0; i < angles.size(); ++i) {
      const double et = fine[i].et + (fine[i].et - coarse[i].et) / 9.0;
      const double predicted = impacts[i].at("tangential_restitution").get<double>();
      const std::string conditioning = impacts[i].at("conditioning").get<std::string>();
      const std::string label = std::string(wall ? "wall" : "pair") + " at " + std::to_string(angles[i]) +
                                " deg: LIGGGHTS e_t " + std::to_string(et) + ", printed " +
                                std::to_string(predicted) + ", " + conditioning;
      std::cout << label << "\n";
      if (conditioning.find("slides on the Coulomb cap") != std::string::npos) {
        ++flagged;
        EXPECT_GT(std::abs(et - predicted), 1e-3) << label;  // the flag is needed there
      } else {
        EXPECT_NEAR(et, predicted, std::max(1e-4 * std::abs(predicted), 1e-5)) << label;
      }
    }
    EXPECT_EQ(flagged, wall ? 1U : 2U);  // pair: 45° and 46°; wall: 46°
  }
}

}  // namespace
