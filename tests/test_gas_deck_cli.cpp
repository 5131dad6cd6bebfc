// SPDX-License-Identifier: BSD-3-Clause
// `restitution gas --deck` and `--compare` end to end: the three files of the deck, the comparison of a log
// (here a synthetic one: Haff's law with a known collision-rate factor) and the exit codes of bad requests.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli_runner.hpp"

namespace {

using restitution::test_support::run_cli;
using restitution::test_support::slurp;
using restitution::test_support::TempFolder;

const std::string kGas =
    "gas --young-modulus 1e8 --poisson-ratio 0.4 --density 920 --radius 0.005 --eps 0.8 --velocity 2 "
    "--packing-fraction 0.1 --rms-speed 1 --haff-times 30 ";

TEST(GasDeckCli, WritesTheDeckItsCompanionAndTheData) {
  TempFolder folder;
  const auto r = run_cli(kGas + "--particles 300 --seed 5 --json --deck " + (folder.path / "g.in").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out).at("deck");
  EXPECT_EQ(j.at("data_file").get<std::string>(), (folder.path / "g.data").string());
  const std::string law = slurp((folder.path / "g.in").string());
  const std::string companion = slurp((folder.path / "g_constant_eps.in").string());
  EXPECT_NE(law.find("read_data g.data\n"), std::string::npos);
  EXPECT_NE(law.find("damping viscoelastic"), std::string::npos);
  EXPECT_NE(companion.find("damping tsuji"), std::string::npos);
  EXPECT_NE(slurp((folder.path / "g.data").string()).find("300 atoms"), std::string::npos);
  // Reproducible: the same seed writes the same data.
  TempFolder again;
  ASSERT_EQ(run_cli(kGas + "--particles 300 --seed 5 --deck " + (again.path / "g.in").string()).status, 0);
  EXPECT_EQ(slurp((again.path / "g.data").string()), slurp((folder.path / "g.data").string()));
}

TEST(GasDeckCli, ComparesALogWithTheTheory) {
  TempFolder folder;
  // T0 = m rms^2 with rms 1 m/s; Haff's law at 0.9 of Enskog's rate, tau0 from `gas --json` of a constant
  // eps.
  const auto theory = run_cli(
      "gas --radius 0.005 --density 920 --law tsuji-hertz --eps 0.8 --velocity 2 --packing-fraction 0.1 "
      "--rms-speed 1 --haff-times 30 --json");
  ASSERT_EQ(theory.status, 0) << theory.err;
  const double tau0 = nlohmann::json::parse(theory.out).at("tau0_s").get<double>();
  const double t0 = 920.0 * 4.0 / 3.0 * M_PI * std::pow(0.005, 3);
  // The run begins with the setup line its deck prints (the gas, which --compare checks against its own).
  ASSERT_EQ(run_cli(kGas + "--particles 20 --deck " + (folder.path / "g.in").string()).status, 0);
  const std::string input = slurp((folder.path / "g_constant_eps.in").string());
  const auto setup = input.find("restitution-gas-setup ");
  ASSERT_NE(setup, std::string::npos);
  std::ofstream log(folder.path / "c.log");
  log.precision(15);
  log << "LAMMPS (29 Sep 2021 - Update 2)\n" << input.substr(setup, input.find('"', setup) - setup) << "\n";
  for (int i = 0; i <= 30; ++i) {
    const double t = i == 0 ? 0.0 : 0.1 * tau0 * std::pow(10.0, (i - 1) / 10.0);
    log << "restitution-gas law=constant-eps time_s=" << t
        << " temperature_j=" << t0 / std::pow(1.0 + 0.9 * t / tau0, 2) << " timestep_s=5e-06 step=" << i
        << "\n";
  }
  log.close();
  const auto r = run_cli(kGas + "--json --compare " + (folder.path / "c.log").string() +
                         " --compare-output " + (folder.path / "out").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j.at("collision_rate_factor").get<double>(), 0.9, 1e-6);
  ASSERT_EQ(j.at("runs").size(), 1U);
  EXPECT_LT(j.at("runs")[0].at("max_relative_deviation").get<double>(), 1e-6);
  EXPECT_TRUE(std::filesystem::exists(folder.path / "out" / "gas_compare.csv"));
}

TEST(GasDeckCli, BadRequestsExitWithTheirCode) {
  TempFolder folder;
  EXPECT_EQ(run_cli(kGas + "--compare " + (folder.path / "missing.log").string()).status, 2);
  std::ofstream(folder.path / "empty.log") << "nothing here\n";
  EXPECT_EQ(run_cli(kGas + "--compare " + (folder.path / "empty.log").string()).status, 2);
  EXPECT_EQ(run_cli(kGas + "--particles 1 --deck " + (folder.path / "d.in").string()).status, 2);
  EXPECT_EQ(run_cli(kGas + "--law tsuji-hertz --deck " + (folder.path / "d.in").string()).status, 2);
  EXPECT_FALSE(std::filesystem::exists(folder.path / "d.in"));
  EXPECT_FALSE(std::filesystem::exists(folder.path / "d.data"));
}

}  // namespace
