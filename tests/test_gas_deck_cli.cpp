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
#include "haff_log.hpp"

namespace {

using restitution::test_support::run_cli;
using restitution::test_support::slurp;
using restitution::test_support::TempFolder;

const std::string& kGas = restitution::test_support::kHaffGas;

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
  ASSERT_TRUE(restitution::test_support::write_haff_log(folder.path / "c.log"));
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
