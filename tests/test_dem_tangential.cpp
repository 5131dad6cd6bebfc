// SPDX-License-Identifier: BSD-3-Clause
// `restitution dem --code lammps --friction MU --tangential MODEL`: the printed LAMMPS line carries the
// chosen tangential model (mindlin NULL 1 MU stays the default), the oblique outputs are that line's, the
// same as `restitution oblique` gives for the model with the same parameters, and bad choices exit 2 naming
// the option.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <utility>

#include "cli_runner.hpp"

namespace {

using restitution::test_support::run_cli;

const std::string kSteel =
    "--young-modulus 2e11 --poisson-ratio 0.3 --radius 1e-3 --density 7800 --dissipative-constant 1e-7 "
    "--friction 0.3";

nlohmann::json json_of(const std::string& arguments) {
  const auto outcome = run_cli(arguments + " --json");
  EXPECT_EQ(outcome.status, 0) << arguments << "\n" << outcome.err;
  return nlohmann::json::parse(outcome.out);
}

struct Choice {
  std::string options;  // after --tangential
  std::string words;    // in the printed line
  std::string oblique;  // `restitution oblique`'s options for the same model
};

TEST(DemTangential, PrintsTheChosenModelsLineAndItsObliqueOutputs) {
  for (const Choice& c :
       {Choice{"linear_history --tangential-stiffness 1e6", "tangential linear_history 1000000 1 0.3 ",
               "linear_history --tangential-stiffness 1e6 --tangential-damping 1"},
        Choice{"linear_nohistory --tangential-damping 0.5", "tangential linear_nohistory 0.5 0.3 ",
               "linear_nohistory --tangential-damping 0.5"},
        Choice{"mindlin --tangential-stiffness 5e10 --tangential-damping 0.25",
               "tangential mindlin 50000000000 0.25 0.3 ",
               "mindlin --tangential-stiffness 5e10 --tangential-damping 0.25"},
        // LAMMPS's incremental variants; NULL kept (the pair's 8 G*, also `oblique`'s default).
        Choice{"mindlin_rescale", "tangential mindlin_rescale NULL 1 0.3 ",
               "mindlin_rescale --tangential-damping 1"},
        Choice{"mindlin/force --tangential-stiffness 5e10", "tangential mindlin/force 50000000000 1 0.3 ",
               "mindlin/force --tangential-stiffness 5e10 --tangential-damping 1"},
        Choice{"mindlin_rescale/force --tangential-damping 0.25",
               "tangential mindlin_rescale/force NULL 0.25 0.3 ",
               "mindlin_rescale/force --tangential-damping 0.25"}}) {
    const nlohmann::json dem =
        json_of("dem --code lammps " + kSteel + " --angle 20,45,70 --tangential " + c.options);
    const std::string line = dem.at("lines").at(1).get<std::string>();
    EXPECT_NE(line.find(c.words), std::string::npos) << line;
    EXPECT_EQ(line.find("mindlin NULL"), std::string::npos) << line;
    const auto& impacts = dem.at("oblique").at("impacts");
    const nlohmann::json alone =
        json_of("oblique " + kSteel + " --tangential " + c.oblique + " --angle 20,45,70 --tolerance 1e-10");
    ASSERT_EQ(impacts.size(), 3U);
    for (std::size_t i = 0; i < impacts.size(); ++i) {
      EXPECT_NEAR(impacts[i].at("tangential_restitution").get<double>(),
                  alone.at("impacts").at(i).at("tangential_restitution").get<double>(), 1e-9)
          << c.options << " at " << impacts[i].at("angle_deg");
    }
  }
}

TEST(DemTangential, MindlinNullStaysTheDefaultAndTheWallTakesTheChoice) {
  const nlohmann::json dem = json_of("dem --code lammps " + kSteel);
  EXPECT_NE(dem.at("lines").at(1).get<std::string>().find("tangential mindlin NULL 1 0.3 "),
            std::string::npos);
  const nlohmann::json wall = json_of("dem --code lammps " + kSteel +
                                      " --wall --tangential linear_history --tangential-stiffness 2e6");
  const std::string line = wall.at("lines").at(0).get<std::string>();
  EXPECT_NE(line.find("tangential linear_history 2000000 1 0.3 "), std::string::npos) << line;
  EXPECT_EQ(wall.at("oblique").at("tangential_model").get<std::string>(), "linear_history");
}

TEST(DemTangential, TargetEtFindsTheChosenModelsParameter) {
  const nlohmann::json dem =
      json_of("dem --code lammps " + kSteel +
              " --tangential linear_history --tangential-stiffness 1e6 --target-et 0.5 "
              "--reference-angle 30");
  const auto& inverse = dem.at("oblique").at("inverse");
  EXPECT_NEAR(inverse.at("tangential_restitution").get<double>(), 0.5, 1e-8);
  const std::string line = inverse.at("lines").at(0).get<std::string>();
  EXPECT_NE(line.find("tangential linear_history "), std::string::npos) << line;
  EXPECT_EQ(line.find("linear_history 1000000 "), std::string::npos) << line;
}

TEST(DemTangential, BadChoicesExit2NamingTheOption) {
  for (const auto& [options, named] :
       {std::pair<std::string, std::string>{"--code lammps --tangential linear_history",
                                            "--tangential-stiffness"},
        {"--code lammps --tangential linear_nohistory --tangential-stiffness 3", "--tangential-stiffness"},
        {"--code lammps --tangential mindlin --tangential-damping -1", "--tangential-damping"},
        {"--code lammps --tangential mindlin --tangential-stiffness 0", "--tangential-stiffness"},
        {"--code lammps --tangential foo", "--tangential"},
        {"--code liggghts --tangential linear_history --tangential-stiffness 1e6", "--tangential"}}) {
    std::string arguments = "dem " + kSteel;
    arguments += " " + options;
    const auto outcome = run_cli(arguments);
    EXPECT_EQ(outcome.status, 2) << options;
    EXPECT_NE(outcome.err.find(named), std::string::npos) << options << ": " << outcome.err;
  }
  const auto frictionless = run_cli(
      "dem --code lammps --young-modulus 2e11 --poisson-ratio 0.3 --radius 1e-3 --density 7800 "
      "--dissipative-constant 1e-7 --tangential linear_nohistory");
  EXPECT_EQ(frictionless.status, 2);
  EXPECT_NE(frictionless.err.find("--friction"), std::string::npos) << frictionless.err;
}

// LAMMPS's error in e_t at N steps per contact is below C/N with C = 1, except for the force histories
// (measured 2.44: src/dem/oblique_lines.cpp), which take C = 3.
TEST(DemTangential, ForceHistoriesNeedThreeTimesTheStepsPerContact) {
  for (const auto& [model, steps] :
       {std::pair{"mindlin", 10000.0}, std::pair{"mindlin_rescale", 10000.0},
        std::pair{"mindlin/force", 30000.0}, std::pair{"mindlin_rescale/force", 30000.0}}) {
    const nlohmann::json dem = json_of("dem --code lammps " + kSteel + " --angle 45 --tangential " + model);
    EXPECT_EQ(dem.at("oblique").at("lammps_steps").at("steps_per_contact").get<double>(), steps) << model;
  }
}

}  // namespace
