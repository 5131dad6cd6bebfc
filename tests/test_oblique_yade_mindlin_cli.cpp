// SPDX-License-Identifier: BSD-3-Clause
// `restitution dem --code yade --friction MU` on YADE 2023.02a's betan lines: the oblique outputs are the
// library's yade_mindlin solve with the lines' own numbers (kno, kso of Ip2_FrictMat_FrictMat_MindlinPhys,
// the printed betan, betas = betan, tan(frictionAngle)) and YADE's arms; frictionless lines print none;
// what YADE's lines cannot model (--target-et, the 2024.02a (en, vn) lines at --angle) exits 2 naming it;
// --deck adds one restitution-oblique-check line per angle (tests/dem/oblique_yade_mindlin.cpp runs it).
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>

#include "cli_runner.hpp"
#include "oblique/oblique_contact.hpp"

namespace {

using namespace restitution;
using namespace restitution::oblique;
using restitution::test_support::run_cli;
using restitution::test_support::slurp;
using restitution::test_support::TempFolder;

constexpr double kYoung = 2e11;  // Pa
constexpr double kPoisson = 0.3;
constexpr double kRadius = 1e-3;  // m
constexpr double kDensity = 7800.0;
const std::string kSteel =
    "dem --code yade --young-modulus 2e11 --poisson-ratio 0.3 --radius 1e-3 --density 7800 "
    "--dissipative-constant 1e-7";

double parameter(const nlohmann::json& j, const std::string& name) {
  return j["parameters"][name].get<double>();
}

TEST(ObliqueYadeMindlinCli, DemOutputsAreTheLibrarysSolve) {
  const auto r = run_cli(kSteel + " --yade-version 2023.02a --friction 0.3 --angle 5,20,45,70 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("oblique")) << r.out;
  const auto& o = j["oblique"];
  EXPECT_EQ(o["tangential_model"], "yade_mindlin");
  // Ip2_FrictMat_FrictMat_MindlinPhys::go for two spheres of one material.
  const double r_star = kRadius / 2.0;
  const double kno = 4.0 / 3.0 * kYoung / (2.0 * (1.0 - kPoisson * kPoisson)) * std::sqrt(r_star);
  const double kso = 2.0 * std::sqrt(4.0 * r_star) * kYoung / (2.0 * (1.0 + kPoisson)) / (2.0 - kPoisson);
  EXPECT_NEAR(o["tangential_stiffness"].get<double>(), kso, 1e-12 * kso);
  const double mass = 4.0 / 3.0 * std::numbers::pi * kRadius * kRadius * kRadius * kDensity;
  ObliqueGeometry g{solid_sphere(kRadius, mass), solid_sphere(kRadius, mass),
                    TorqueArm::radius_minus_half_overlap};
  const double betan = parameter(j, "betan");
  const NormalForce normal{LawKind::tsuji_hertz, kno, 2.0 * betan * std::sqrt(1.5 * mass / 2.0 * kno)};
  const TangentialForce tangential{TangentialKind::yade_mindlin, kso, std::sqrt(kso / (1.5 * kno)),
                                   std::tan(parameter(j, "frictionAngle"))};
  EXPECT_NEAR(tangential.friction, 0.3, 1e-15);
  ObliqueOptions options;
  options.end = CollisionEnd::delayed_recovery;
  options.relative_tolerance = 1e-12;
  ASSERT_EQ(o["impacts"].size(), 4U);
  for (const auto& impact : o["impacts"]) {
    const double a = impact["angle_deg"].get<double>() * std::numbers::pi / 180.0;
    const ObliqueResult x =
        solve_oblique(g, normal, tangential, {std::cos(a), std::sin(a), 0.0, 0.0}, options);
    const std::string where = std::to_string(impact["angle_deg"].get<double>()) + " deg";
    EXPECT_NEAR(impact["tangential_restitution"].get<double>(), x.tangential_restitution, 1e-9) << where;
    EXPECT_NEAR(impact["spin_rad_s"].get<double>(), x.spin_first_rad_s, 1e-9 * std::abs(x.spin_first_rad_s))
        << where;
    EXPECT_NEAR(impact["normal_restitution"].get<double>(), x.normal_restitution, 1e-9) << where;
  }
  EXPECT_EQ(o["yade_steps"]["error_coefficient"].get<double>(), 3.0);
}

TEST(ObliqueYadeMindlinCli, FrictionlessLinesPrintNoObliqueImpacts) {
  const auto r = run_cli(kSteel + " --yade-version 2023.02a --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_FALSE(nlohmann::json::parse(r.out).contains("oblique"));
}

TEST(ObliqueYadeMindlinCli, WhatYadesLinesCannotModelExits2) {
  const auto inverse =
      run_cli(kSteel + " --yade-version 2023.02a --friction 0.3 --target-et 0.2 --reference-angle 20");
  EXPECT_EQ(inverse.status, 2);
  EXPECT_NE(inverse.err.find("--target-et"), std::string::npos) << inverse.err;
  const auto en_vn = run_cli(kSteel + " --yade-version 2024.02a --friction 0.3 --angle 10");
  EXPECT_EQ(en_vn.status, 2);
  EXPECT_NE(en_vn.err.find("2024.02a"), std::string::npos) << en_vn.err;
  // Without --angle the (en, vn) lines print as before, with no oblique impacts.
  const auto plain = run_cli(kSteel + " --yade-version 2024.02a --friction 0.3 --json");
  ASSERT_EQ(plain.status, 0) << plain.err;
  EXPECT_FALSE(nlohmann::json::parse(plain.out).contains("oblique"));
}

// The deck's oblique section: one check line per listed angle, in order, each carrying the printed e_t;
// frictionless lines give a head-on deck.
TEST(ObliqueYadeMindlinCli, DeckHasOneObliqueCheckLinePerAngle) {
  TempFolder folder;
  const auto deck = (folder.path / "check.py").string();
  const auto r =
      run_cli(kSteel + " --yade-version 2023.02a --friction 0.3 --angle 5,20,45,70 --json --deck " + deck);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto out = nlohmann::json::parse(r.out);
  const auto& impacts = out["oblique"]["impacts"];
  std::istringstream text(slurp(deck));
  std::size_t found = 0;
  const std::string prefix = "    'restitution-oblique-check code=yade contact=pair angle=";
  for (std::string line; std::getline(text, line);) {
    if (line.rfind(prefix, 0) != 0) continue;
    ASSERT_LT(found, impacts.size()) << line;
    EXPECT_EQ(std::stod(line.substr(prefix.size())), impacts[found]["angle_deg"].get<double>()) << line;
    const std::size_t et = line.find(" et_restitution=");
    ASSERT_NE(et, std::string::npos) << line;
    EXPECT_EQ(std::stod(line.substr(et + 16)), impacts[found]["tangential_restitution"].get<double>())
        << line;
    EXPECT_NE(line.find(" diff=%.15g"), std::string::npos) << line;
    ++found;
  }
  EXPECT_EQ(found, 4U);
  const auto frictionless = (folder.path / "frictionless.py").string();
  ASSERT_EQ(run_cli(kSteel + " --yade-version 2023.02a --deck " + frictionless).status, 0);
  EXPECT_EQ(slurp(frictionless).find("restitution-oblique-check"), std::string::npos);
}

// At 0 degrees e_t is nan (no slip to restitute): the deck must spell it as Python reads it, not `nan`.
TEST(ObliqueYadeMindlinCli, DeckSpellsAHeadOnAnglesNanForPython) {
  TempFolder folder;
  const auto deck = (folder.path / "check.py").string();
  ASSERT_EQ(run_cli(kSteel + " --yade-version 2023.02a --friction 0.3 --angle 0,30 --deck " + deck).status,
            0);
  const std::string text = slurp(deck);
  EXPECT_NE(text.find("OBLIQUE_ET_RESTITUTION = [float('nan'), "), std::string::npos) << text;
  EXPECT_NE(text.find("if s0 != 0 else float('nan')"), std::string::npos) << text;
}

// `restitution oblique` models viscoelastic Hertz; YADE's Mindlin comes with the Tsuji force.
TEST(ObliqueYadeMindlinCli, ObliqueCommandRefusesItNamingWhy) {
  const auto r = run_cli(
      "oblique --young-modulus 2e11 --poisson-ratio 0.3 --radius 1e-3 --density 7800 --dissipative-constant "
      "1e-7 --friction 0.3 --tangential yade_mindlin --angle 10");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("Tsuji"), std::string::npos) << r.err;
}

}  // namespace
