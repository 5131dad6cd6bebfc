// SPDX-License-Identifier: BSD-3-Clause
// `restitution oblique` at its edges (issue 44, items 8, 9, 11, 12, 14): the README's steel with --plot, a
// failed impact that loses none of the others, tangential springs and dampers beyond what the solve resolves,
// the damping required or calibrated from --eps/--velocity, the wall of `dem --wall`, the second spin in the
// table and CSV, angles as given, and `dem`'s frictionless oblique table.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iterator>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>
#include <vector>

#include "cli_runner.hpp"

namespace {

using restitution::test_support::lines_of;
using restitution::test_support::run_cli;
using restitution::test_support::slurp;
using restitution::test_support::TempFolder;

const std::string kMaterial = "--young-modulus 2e11 --poisson-ratio 0.3 --radius 1e-3 --density 7800";
const std::string kSteel = "oblique " + kMaterial + " --dissipative-constant 1e-7";

std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t begin = 0;
  for (std::size_t end; (end = line.find(',', begin)) != std::string::npos; begin = end + 1)
    fields.push_back(line.substr(begin, end - begin));
  fields.push_back(line.substr(begin));
  return fields;
}

// 44.8: the README's own steel with --plot failed (the sticking-limit solve at μ = 1e12), left x.png.data.csv
// behind and lost the table.
TEST(ObliqueEdges, ReadmeSteelPlotsAndLeavesNoScratchFile) {
  TempFolder folder;
  const auto image = folder.path / "x.png";
  for (const std::string model : {"mindlin", "linear_nohistory --tangential-damping 0.5", "mindlin/force"}) {
    const auto r = run_cli(kSteel + " --wall --tangential " + model + " --friction 0.3 --angle 30 --plot " +
                           image.string());
    ASSERT_EQ(r.status, 0) << model << ": " << r.err;
    EXPECT_NE(r.out.find("   30 "), std::string::npos) << r.out;
    // The scratch table the plot read (under a random name) is gone: the image is the folder's one file.
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(folder.path),
                            std::filesystem::directory_iterator()),
              1)
        << model;
    EXPECT_EQ(r.err.find("no oblique plot"), std::string::npos) << model << ": " << r.err;
    EXPECT_TRUE(std::filesystem::exists(image)) << model;
    std::filesystem::remove(image);
  }
}

// 45.5: one command's two outputs on one path, and a figure on a device, are refused before any solve (the
// gas command's rule, tests/test_output_policy.cpp).
TEST(ObliqueEdges, OutAndPlotOnOnePathOrAFigureOnADeviceAreRefused) {
  TempFolder folder;
  const auto x = folder.path / "x.png";
  const auto r =
      run_cli(kSteel + " --wall --friction 0.3 --angle 30 --out " + x.string() + " --plot " + x.string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("are the same file"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(x)) << "nothing written";
  const auto device = run_cli(kSteel + " --wall --friction 0.3 --angle 30 --plot /dev/full");
  EXPECT_EQ(device.status, 2) << device.err;
  EXPECT_NE(device.err.find("'/dev/full'"), std::string::npos) << device.err;
  EXPECT_FALSE(std::filesystem::exists("/dev/full.png"));
}

// 44.8: an impact CVODE cannot solve (μ = 1e12 at 1° on a wall: the switch function of a cap 1e12 times the
// normal force drives it into error-test failures; 85° slides throughout and solves) is marked; the other
// angle is printed and written, and the exit status is 1.
TEST(ObliqueEdges, AFailedImpactLosesNoneOfTheOthers) {
  TempFolder folder;
  const auto csv = folder.path / "impacts.csv";
  const auto r = run_cli(kSteel + " --wall --friction 1e12 --angle 1,85 --out " + csv.string());
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("numerical failure at 1 deg"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("1 of 2 impacts failed"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("failed: "), std::string::npos) << r.out;
  const auto lines = lines_of(slurp(csv.string()));
  ASSERT_EQ(lines.size(), 3U);
  const auto header = fields_of(lines[0]);
  ASSERT_EQ(header.back(), "status");
  const auto first = fields_of(lines[1]);
  const auto second = fields_of(lines[2]);
  EXPECT_EQ(first.back(), "failed");
  EXPECT_EQ(first[2], "nan");
  EXPECT_EQ(second.back(), "solved");
  EXPECT_TRUE(std::isfinite(std::stod(second[2])));
}

// 44.9: a spring or damper faster than the solve resolves is refused up front, naming the option and the
// largest value that works; half that value runs.
TEST(ObliqueEdges, StiffOrDampedSpringsAreRefusedWithTheRangeThatWorks) {
  const std::string base = kSteel + " --wall --friction 0.3 --angle 10,80";
  const struct {
    std::string option, model;
  } cases[] = {{"--tangential-stiffness", "linear_history"},
               {"--tangential-stiffness", "mindlin"},
               {"--tangential-damping", "mindlin"}};
  for (const auto& c : cases) {
    const std::string extra = c.model == "linear_history" && c.option != "--tangential-stiffness"
                                  ? " --tangential-stiffness 2e6"
                                  : "";
    const auto refused = run_cli(base + " --tangential " + c.model + extra + " " + c.option +
                                 (c.option == "--tangential-damping" ? " 1e9" : " 1e30"));
    ASSERT_EQ(refused.status, 2) << c.option << ": " << refused.err;
    const std::regex limit(c.option + " must be at most ([0-9.e+-]+)");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(refused.err, m, limit)) << refused.err;
    EXPECT_EQ(lines_of(refused.err).size(), 1U) << refused.err;
    const double largest = std::stod(m[1].str());
    const auto runs = run_cli(base + " --tangential " + c.model + extra + " " + c.option + " " +
                              std::to_string(0.5 * largest) + " --json");
    EXPECT_EQ(runs.status, 0) << c.option << " at half the limit: " << runs.err;
  }
}

// 44.11: no silent elastic default; --eps/--velocity calibrate A on the contact; the default model runs
// without options; a frictionless linear_history needs no stiffness.
TEST(ObliqueEdges, DampingIsRequiredOrCalibrated) {
  const auto missing = run_cli("oblique " + kMaterial + " --friction 0.3 --angle 30");
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("--dissipative-constant"), std::string::npos) << missing.err;
  EXPECT_NE(missing.err.find("--eps"), std::string::npos) << missing.err;
  const auto no_speed = run_cli("oblique " + kMaterial + " --eps 0.9 --friction 0.3 --angle 30");
  EXPECT_EQ(no_speed.status, 2);
  EXPECT_NE(no_speed.err.find("--velocity"), std::string::npos) << no_speed.err;

  for (const std::string wall : {"", " --wall"}) {
    const auto r = run_cli("oblique " + kMaterial + wall +
                           " --eps 0.85 --velocity 2 --impact-velocity 2 --friction 0.3 --angle 0 --json");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["tangential_model"], "mindlin");  // the default, as dem's
    EXPECT_NEAR(j["impacts"][0]["normal_restitution"].get<double>(), 0.85, 1e-9) << wall;
    EXPECT_GT(j["dissipative_constant_s"].get<double>(), 0.0);
  }
  // On a wall: a pair's turning line of centres moves e_t off -1 even without friction.
  const auto frictionless =
      run_cli(kSteel + " --wall --tangential linear_history --friction 0 --angle 30 --json");
  ASSERT_EQ(frictionless.status, 0) << frictionless.err;
  EXPECT_EQ(nlohmann::json::parse(frictionless.out)["impacts"][0]["tangential_restitution"].get<double>(),
            -1.0);
}

// 44.11: --law takes the Hertz members, damped by --eps/--velocity: Tsuji's ε does not depend on the speed,
// so the calibrated law gives the same ε at another speed; the dash-pot and A for Tsuji are refused by name.
TEST(ObliqueEdges, LawTakesTheHertzMembers) {
  for (const std::string law : {"tsuji-hertz", "hertz-constant-damping"}) {
    const auto r = run_cli("oblique " + kMaterial + " --law " + law +
                           " --eps 0.8 --velocity 1 --wall --friction 0.3 --angle 0,40 --json");
    ASSERT_EQ(r.status, 0) << law << ": " << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["law"], law);
    EXPECT_NEAR(j["impacts"][0]["normal_restitution"].get<double>(), 0.8, 1e-8) << law;
  }
  const auto tsuji = run_cli(
      "oblique " + kMaterial +
      " --law tsuji-hertz --eps 0.8 --velocity 1 --impact-velocity 3 --friction 0.3 --angle 0 --json");
  ASSERT_EQ(tsuji.status, 0) << tsuji.err;
  EXPECT_NEAR(nlohmann::json::parse(tsuji.out)["impacts"][0]["normal_restitution"].get<double>(), 0.8, 1e-8);
  for (const std::string bad :
       {" --law linear-dashpot --eps 0.8 --velocity 1", " --law tsuji-hertz --dissipative-constant 1e-7"}) {
    const auto r = run_cli("oblique " + kMaterial + bad + " --friction 0.3 --angle 10");
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_NE(r.err.find(bad.find("linear") != std::string::npos ? "--law" : "--dissipative-constant"),
              std::string::npos)
        << r.err;
  }
}

// 44.12: `oblique --wall` is `dem --wall`'s wall: rigid, or of the material --wall-young-modulus and
// --wall-poisson-ratio give, the same ε head-on; every output says which.
TEST(ObliqueEdges, WallMeansTheWallOfDem) {
  for (const std::string material : {"", " --wall-young-modulus 7e10 --wall-poisson-ratio 0.22"}) {
    const auto dem = run_cli("dem --code lammps " + kMaterial +
                             " --dissipative-constant 1e-7 --wall --impact-velocity 1 --json" + material);
    ASSERT_EQ(dem.status, 0) << dem.err;
    const auto d = nlohmann::json::parse(dem.out);
    const auto oblique = run_cli(kSteel + " --wall --friction 0.3 --angle 0 --json" + material);
    ASSERT_EQ(oblique.status, 0) << oblique.err;
    const auto o = nlohmann::json::parse(oblique.out);
    EXPECT_EQ(o["rigid_wall"], d["rigid_wall"]);
    EXPECT_EQ(o["rigid_wall"].get<bool>(), material.empty());
    EXPECT_NEAR(o["effective_modulus_pa"].get<double>(), d["effective_modulus_pa"].get<double>(),
                1e-12 * d["effective_modulus_pa"].get<double>());
    EXPECT_NEAR(o["impacts"][0]["normal_restitution"].get<double>(), d["eps"][0]["eps"].get<double>(), 1e-8)
        << material;
    const auto text = run_cli(kSteel + " --wall --friction 0.3 --angle 0" + material);
    EXPECT_NE(
        text.out.find(material.empty() ? "a sphere on a rigid wall" : "a sphere on a wall of Y = 7e+10"),
        std::string::npos)
        << text.out;
  }
}

// 44.14: the second sphere's spin in the table and the CSV; the angle as given; --wall --fixed-normal
// refused; --tangential's help lists the models that run, each of which runs.
TEST(ObliqueEdges, SecondSpinAnglesAsGivenAndOneListOfModels) {
  TempFolder folder;
  const auto csv = folder.path / "pair.csv";
  const auto j = run_cli(kSteel + " --friction 0.3 --angle 30,89.999 --json --out " + csv.string());
  ASSERT_EQ(j.status, 0) << j.err;
  const auto json = nlohmann::json::parse(j.out);
  const auto lines = lines_of(slurp(csv.string()));
  ASSERT_EQ(lines.size(), 3U);
  const auto header = fields_of(lines[0]);
  const auto column = std::find(header.begin(), header.end(), "spin2_rad_s") - header.begin();
  ASSERT_LT(column, static_cast<long>(header.size()));
  EXPECT_EQ(std::stod(fields_of(lines[1])[column]), json["impacts"][0]["spin2_rad_s"].get<double>());
  const auto table = run_cli(kSteel + " --friction 0.3 --angle 30,89.999");
  ASSERT_EQ(table.status, 0) << table.err;
  EXPECT_NE(table.out.find("spin2_rad_s"), std::string::npos) << table.out;
  EXPECT_NE(table.out.find("89.999 "), std::string::npos) << table.out;

  const auto fixed = run_cli(kSteel + " --wall --fixed-normal --friction 0.3 --angle 30");
  EXPECT_EQ(fixed.status, 2);
  EXPECT_NE(fixed.err.find("--fixed-normal"), std::string::npos) << fixed.err;

  const auto help = run_cli("oblique --help");
  const std::regex listed("tangential model: ([a-z_/, ]+) \\(docs");
  std::smatch m;
  const std::string flat = std::regex_replace(help.out, std::regex("\\s+"), " ");
  ASSERT_TRUE(std::regex_search(flat, m, listed)) << help.out;
  const std::string models = m[1].str();
  EXPECT_EQ(models.find("yade"), std::string::npos) << models;
  std::size_t begin = 0;
  int count = 0;
  for (std::size_t end = 0; end != std::string::npos; begin = end + 2) {
    end = models.find(", ", begin);
    const std::string model = models.substr(begin, end == std::string::npos ? end : end - begin);
    const std::string stiffness = model == "linear_history" ? " --tangential-stiffness 2e6" : "";
    const auto r = run_cli(kSteel + " --friction 0.3 --angle 30 --tangential " + model + stiffness);
    EXPECT_EQ(r.status, 0) << model << ": " << r.err;
    ++count;
  }
  EXPECT_EQ(count, 7);
}

// 44.14: `dem` prints no cap rule and no steps per contact for a frictionless oblique table.
TEST(ObliqueEdges, DemFrictionlessTableHasNoCapRuleOrSteps) {
  const auto r = run_cli("dem --code lammps " + kMaterial + " --dissipative-constant 1e-7 --angle 30,89.999");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.find("rule:"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("steps per contact (|error|"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("frictionless lines"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("89.999 "), std::string::npos) << r.out;
  const auto j = nlohmann::json::parse(
      run_cli("dem --code lammps " + kMaterial + " --dissipative-constant 1e-7 --angle 30 --json").out);
  EXPECT_FALSE(j["oblique"].contains("cap_rule"));
  EXPECT_FALSE(j["oblique"].contains("lammps_steps"));
}

}  // namespace
