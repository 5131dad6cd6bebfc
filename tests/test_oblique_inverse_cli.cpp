// SPDX-License-Identifier: BSD-3-Clause
// `restitution dem --code lammps --friction MU` with oblique outputs (src/dem/oblique_lines.cpp, worded by
// src/cli/dem/dem_oblique.cpp): the impacts it reports are `restitution oblique`'s for the same material,
// damping and LAMMPS's mindlin NULL; the stiffness --target-et finds, fed back into `restitution oblique`,
// gives the target at the reference angle; an unreachable target and the options outside LAMMPS exit with
// status 2 naming the problem.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.hpp"

namespace {

using restitution::test_support::run_cli;

const std::string kSteel = "--young-modulus 2e11 --poisson-ratio 0.3 --radius 1e-3 --density 7800";
const std::string kLines = "dem --code lammps " + kSteel + " --eps 0.9 --velocity 1 --friction 0.3";

nlohmann::json json_of(const std::string& args) {
  const auto r = run_cli(args);
  EXPECT_EQ(r.status, 0) << args << "\n" << r.err;
  return nlohmann::json::parse(r.out);
}

// `restitution oblique` for the lines' pair (or wall) with A from the lines, at `angles`.
nlohmann::json oblique_of(const nlohmann::json& lines, const std::string& contact, double stiffness,
                          const std::string& angles) {
  return json_of(fmt::format(
      "oblique {} --dissipative-constant {:.17g} {} --tangential mindlin --tangential-stiffness {:.17g} "
      "--tangential-damping 1 --friction 0.3 --angle {} --json",
      kSteel, lines["dissipative_constant_s"].get<double>(), contact, stiffness, angles));
}

TEST(DemOblique, PairImpactsAreTheObliqueCommandsAtTheLinesNumbers) {
  const auto lines = json_of(kLines + " --json");
  const auto& oblique = lines["oblique"];
  EXPECT_EQ(oblique["tangential"], "mindlin NULL 1 0.3");
  const auto& impacts = oblique["impacts"];
  ASSERT_EQ(impacts.size(), 6U);  // 5, 15, 30, 45, 60, 80
  // LAMMPS's pair NULL: 8 G*, 1/G* = 4 (2 - nu)(1 + nu)/E.
  const double null_stiffness = 8.0 * 2e11 / (4.0 * 1.7 * 1.3);
  EXPECT_NEAR(oblique["tangential_stiffness"].get<double>(), null_stiffness, 1e-6 * null_stiffness);
  const auto direct = oblique_of(lines, "", null_stiffness, "5,15,30,45,60,80");
  for (std::size_t i = 0; i < impacts.size(); ++i) {
    const auto& want = direct["impacts"][i];
    EXPECT_EQ(impacts[i]["angle_deg"], want["angle_deg"]);
    EXPECT_NEAR(impacts[i]["tangential_restitution"].get<double>(),
                want["tangential_restitution"].get<double>(), 2e-10);
    EXPECT_NEAR(impacts[i]["normal_restitution"].get<double>(), want["normal_restitution"].get<double>(),
                2e-10);
    EXPECT_NEAR(impacts[i]["spin_rad_s"].get<double>(), want["spin_rad_s"].get<double>(),
                2e-10 * std::max(1.0, std::abs(want["spin_rad_s"].get<double>())) + 1e-6);
    EXPECT_EQ(impacts[i]["conditioning"], "well-conditioned");
  }
  const auto& steps = oblique["lammps_steps"];
  EXPECT_EQ(steps["steps_per_contact"].get<double>(), 10000.0);  // C = 1 for mindlin, over 1e-4
  EXPECT_GT(steps["timestep_s"].get<double>(), 0.0);
}

TEST(DemOblique, TargetStiffnessFedBackGivesTheTarget) {
  for (const bool wall : {false, true}) {
    // `oblique --wall` is a wall of the sphere's material.
    const std::string own_wall = " --wall --wall-young-modulus 2e11 --wall-poisson-ratio 0.3";
    const auto lines =
        json_of(kLines + (wall ? own_wall : "") + " --target-et 0.25 --reference-angle 20 --json");
    const auto& inverse = lines["oblique"]["inverse"];
    EXPECT_EQ(inverse["parameter"], "tangential_stiffness");
    const double k = inverse["value"].get<double>();
    const std::string line = inverse["lines"][0];
    EXPECT_NE(line.find(fmt::format("tangential mindlin {} 1 0.3", k)), std::string::npos) << line;
    // The same stiffness through `restitution oblique`, which knows nothing of the inverse.
    const auto again = oblique_of(lines, wall ? own_wall : "", k, "20");
    EXPECT_NEAR(again["impacts"][0]["tangential_restitution"].get<double>(), 0.25, 1e-10)
        << (wall ? "wall" : "pair");
  }
}

TEST(DemOblique, RefusesWhatItCannotDo) {
  const auto unreachable = run_cli(kLines + " --target-et 0.99 --reference-angle 20");
  EXPECT_EQ(unreachable.status, 2);
  EXPECT_NE(unreachable.err.find("out of reach"), std::string::npos) << unreachable.err;
  EXPECT_NE(unreachable.err.find("gives e_t in [-0.6"), std::string::npos) << unreachable.err;
  EXPECT_TRUE(unreachable.out.empty());
  for (const std::string& bad :
       {kLines + " --target-et 0.3", kLines + " --reference-angle 20", kLines + " --angle 95",
        kLines + " --target-et 0.3 --reference-angle 0", kLines + " --et-accuracy 0",
        "dem --code mercurydpm " + kSteel + " --eps 0.9 --velocity 1 --friction 0.3 --angle 10",
        "dem --code lammps " + kSteel + " --eps 0.9 --velocity 1 --target-et 0.3 --reference-angle 20"}) {
    const auto r = run_cli(bad);
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_NE(r.err.find("error:"), std::string::npos) << bad << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << bad;
  }
}

}  // namespace
