// SPDX-License-Identifier: BSD-3-Clause
// `restitution dem --code liggghts --friction MU` with oblique outputs (src/dem/oblique_lines.cpp, worded by
// src/cli/dem/dem_oblique.cpp): the impacts it reports are `restitution oblique --tangential
// liggghts_history`'s for the same material and damping (gammat = gamman: damping factor 1; kt = 8 G*, the
// oblique command's default); the kt --target-et finds, fed back into `restitution oblique`, gives the target
// at the reference angle; --tangential, a frictionless line and a LIGGGHTS wall exit with status 2 naming
// why; an impact sliding on the cap is reported; the check deck holds one oblique check line per angle.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_runner.hpp"

namespace {

using restitution::test_support::run_cli;
using restitution::test_support::slurp;
using restitution::test_support::TempFolder;

const std::string kSteel = "--young-modulus 2e11 --poisson-ratio 0.3 --radius 1e-3 --density 7800";
const std::string kLines = "dem --code liggghts " + kSteel + " --eps 0.9 --velocity 1 --friction 0.3";

nlohmann::json json_of(const std::string& args) {
  const auto r = run_cli(args);
  EXPECT_EQ(r.status, 0) << args << "\n" << r.err;
  return nlohmann::json::parse(r.out);
}

// `restitution oblique --tangential liggghts_history` for the lines' pair with A from the lines.
nlohmann::json oblique_of(const nlohmann::json& lines, const std::string& stiffness,
                          const std::string& angles) {
  return json_of(fmt::format(
      "oblique {} --dissipative-constant {:.17g} --tangential liggghts_history {} --tangential-damping 1 "
      "--friction 0.3 --angle {} --json",
      kSteel, lines["dissipative_constant_s"].get<double>(), stiffness, angles));
}

TEST(DemObliqueLiggghts, ImpactsAreTheObliqueCommandsAtTheLinesNumbers) {
  const auto lines = json_of(kLines + " --json");
  ASSERT_TRUE(lines.contains("oblique"));
  const auto& oblique = lines["oblique"];
  EXPECT_EQ(oblique["code"], "liggghts");
  EXPECT_EQ(oblique["tangential_model"], "liggghts_history");
  EXPECT_NE(oblique["cap_rule"].get<std::string>().find("elastic force alone"), std::string::npos);
  EXPECT_EQ(oblique["tangential_damping_factor"].get<double>(), 1.0);  // gammat = gamman
  EXPECT_EQ(oblique["tangential_stiffness"].get<double>(), lines["parameters"]["kt"].get<double>());
  ASSERT_TRUE(oblique.contains("liggghts_steps"));
  EXPECT_FALSE(oblique.contains("lammps_steps"));
  EXPECT_EQ(oblique["liggghts_steps"]["steps_per_contact"].get<double>(), 10000.0);  // 1/1e-4
  const auto& impacts = oblique["impacts"];
  ASSERT_EQ(impacts.size(), 6U);  // 5, 15, 30, 45, 60, 80 degrees
  const auto reference = oblique_of(lines, "", "5,15,30,45,60,80")["impacts"];
  ASSERT_EQ(reference.size(), impacts.size());
  for (std::size_t i = 0; i < impacts.size(); ++i) {
    const auto& got = impacts[i];
    const auto& want = reference[i];
    EXPECT_EQ(got["angle_deg"], want["angle_deg"]);
    EXPECT_EQ(got["conditioning"], "well-conditioned");
    for (const char* key : {"normal_restitution", "tangential_restitution"}) {
      EXPECT_NEAR(got[key].get<double>(), want[key].get<double>(), 1e-9) << key << " at " << got["angle_deg"];
    }
    for (const char* key : {"rebound_angle_deg", "spin_rad_s", "spin2_rad_s", "contact_time_s"}) {
      EXPECT_NEAR(got[key].get<double>(), want[key].get<double>(), 1e-9 * std::abs(want[key].get<double>()))
          << key << " at " << got["angle_deg"];
    }
  }
}

TEST(DemObliqueLiggghts, TargetEtPrintsTheKtLineThatGivesIt) {
  const auto lines = json_of(kLines + " --target-et 0.25 --reference-angle 20 --json");
  const auto& inverse = lines["oblique"]["inverse"];
  EXPECT_EQ(inverse["parameter"], "tangential_stiffness");
  const double kt = inverse["value"].get<double>();
  EXPECT_EQ(inverse["lines"][0].get<std::string>(),
            fmt::format("fix dem_kt all property/global kt peratomtypepair 1 {}", kt));
  const auto again = oblique_of(lines, fmt::format("--tangential-stiffness {:.17g}", kt), "20");
  EXPECT_NEAR(again["impacts"][0]["tangential_restitution"].get<double>(), 0.25, 1e-9);
  // And the text says whose rule and whose steps, and prints the changed line.
  const auto text = run_cli(kLines + " --target-et 0.25 --reference-angle 20");
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("# LIGGGHTS's rule: the cap tests the elastic force alone"), std::string::npos);
  EXPECT_NE(text.out.find("a bound over Debian's LIGGGHTS measured"), std::string::npos);
  EXPECT_NE(text.out.find("\n" + inverse["lines"][0].get<std::string>() + "\n"), std::string::npos);
}

TEST(DemObliqueLiggghts, RefusesWhatItCannotModel) {
  for (const auto& [arguments, named] :
       {std::pair<std::string, std::string>{kLines + " --tangential linear_history", "are for --code lammps"},
        {kLines + " --tangential-damping 0.5", "one tangential model"},
        {"dem --code liggghts " + kSteel + " --eps 0.9 --velocity 1 --angle 30", "need --friction MU > 0"},
        {kLines + " --wall --angle 30", "--wall does not support liggghts"}}) {
    const auto r = run_cli(arguments);
    EXPECT_EQ(r.status, 2) << arguments;
    EXPECT_NE(r.err.find(named), std::string::npos) << arguments << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << arguments;
  }
}

// A = 1e-6 s: at 55° the pair's contact slides on the cap (LIGGGHTS alternates capped and uncapped steps),
// which the solve does not model; the impact is printed flagged and warned about, as LAMMPS's ill-conditioned
// ones, and 50° is not.
TEST(DemObliqueLiggghts, ImpactsSlidingOnTheCapAreReported) {
  const std::string arguments =
      "dem --code liggghts " + kSteel + " --dissipative-constant 1e-6 --friction 0.3 --angle 50,55";
  const auto r = run_cli(arguments + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto impacts = nlohmann::json::parse(r.out)["oblique"]["impacts"];
  ASSERT_EQ(impacts.size(), 2U);
  EXPECT_EQ(impacts[0]["conditioning"], "well-conditioned");
  const std::string flagged = impacts[1]["conditioning"].get<std::string>();
  EXPECT_EQ(flagged.rfind("not modelled: ", 0), 0U) << flagged;
  EXPECT_NE(flagged.find("slides on the Coulomb cap"), std::string::npos) << flagged;
  EXPECT_NE(r.err.find("warning: oblique impact at 55 deg, not modelled"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("at 50 deg"), std::string::npos) << r.err;
  const auto text = run_cli(arguments);
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find("  (not modelled: "), std::string::npos) << text.out;
}

// The check deck adds the oblique section (dem/oblique_check_deck.hpp) after the head-on collisions: one
// restitution-oblique-check line per listed angle, in order, at LIGGGHTS's dt = t_c/10000 and t_c/100000.
TEST(DemObliqueLiggghts, CheckDeckHasOneObliqueLinePerAngle) {
  TempFolder folder;
  const auto deck = folder.path / "check.liggghts";
  const auto r = run_cli(kLines + " --angle 10,35,70 --deck " + deck.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string text = slurp(deck.string());
  EXPECT_NE(text.find("restitution-check"), std::string::npos);
  const std::string head = "print \"restitution-oblique-check code=liggghts contact=pair angle=";
  std::vector<std::string> angles;
  for (std::size_t at = text.find(head); at != std::string::npos; at = text.find(head, at + 1)) {
    const std::size_t from = at + head.size();
    angles.push_back(text.substr(from, text.find(' ', from) - from));
  }
  EXPECT_EQ(angles, (std::vector<std::string>{"10", "35", "70"}));
  EXPECT_LT(text.find("restitution-check"), text.find(head));  // after the head-on section
  EXPECT_NE(text.find("dt = t_c/10000 and t_c/100000"), std::string::npos);
  EXPECT_EQ(text.find("$("), std::string::npos);  // LIGGGHTS 3.8.0 has no immediate $(...) variables
}

// A head-on angle has no slip at impact (e_t undefined): it is left out of the deck with a comment saying so,
// instead of a formula dividing by 0 that stopped LAMMPS; one angle left is read as fix ave/time's scalar (of
// several, its vector). Both were found running such decks (`--angle 0,30`) in LAMMPS and LIGGGHTS.
TEST(DemObliqueLiggghts, CheckDeckLeavesOutAHeadOnAngleAndReadsOneAngleAsAScalar) {
  for (const std::string code : {"lammps", "liggghts"}) {
    TempFolder folder;
    const auto deck = folder.path / "check.in";
    const auto r = run_cli("dem --code " + code + " " + kSteel +
                           " --eps 0.9 --velocity 1 --friction 0.3 --angle 0,30 --deck " + deck.string());
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string text = slurp(deck.string());
    EXPECT_NE(text.find("angle 0 deg has no slip at impact (e_t undefined): not checked"), std::string::npos)
        << code;
    EXPECT_EQ(text.find("angle=0 "), std::string::npos) << code;
    EXPECT_NE(text.find("angle=30 "), std::string::npos) << code;
    EXPECT_EQ(text.find("nan"), std::string::npos) << code;
    EXPECT_NE(text.find("equal f_rc_oblique_hold\n"), std::string::npos) << code;
    EXPECT_EQ(text.find("f_rc_oblique_hold["), std::string::npos) << code;
  }
}

}  // namespace
