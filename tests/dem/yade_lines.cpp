// SPDX-License-Identifier: BSD-3-Clause
// Runs Debian's YADE (`yade -n -x`, 2023.02a) on the lines `restitution dem --code yade` prints for the YADE
// on PATH, unchanged (each line exec'd / eval'd verbatim), in head-on collisions of two steel beads at three
// speeds, and checks that YADE measures the ε the output says these lines give, within 1e-5 relative.
// YADE's leap-frog integrator is first order in dt for this velocity-dependent force: each speed runs at
// dt = T/n and T/(10 n) (n = 5000, T the natural time of that speed) and ε is Richardson-extrapolated; the
// Tsuji force's x^{1/4} leaves a remainder that converges slowly (measured at eps = 0.5: 1.6e-6 after
// extrapolating from n = 1000, 2e-7 from n = 5000), as in the LAMMPS Tsuji checks.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "dem/deck.hpp"
#include "dem/steel_beads.hpp"
#include "dem/yade_runner.hpp"
#include "restitution/material.hpp"

namespace {

using nlohmann::json;
using restitution::test_support::run_json;
using restitution::test_support::steel;

const std::string kMaterial = " --young-modulus 2.1e11 --poisson-ratio 0.3 --radius 0.005 --density 7850";

class YadeLines : public testing::TestWithParam<double> {};

TEST_P(YadeLines, YadeMeasuresTheEpsTheOutputStates) {
  const std::string program = restitution::dem::yade_program();
  ASSERT_FALSE(program.empty()) << "yade not found on PATH: scripts/setup installs Debian's yade";
  const double target = GetParam();
  std::ostringstream args;
  args << "dem --code yade --eps " << target << " --velocity 1 --json" << kMaterial;
  const json out = run_json(args.str());
  // The YADE on PATH is Debian's 2023.02a: no vn, so the lines carry the Tsuji-type betan and the output
  // states a constant ε, with the exact law's lines only as a labelled alternative.
  EXPECT_EQ(out.at("yade_version"), "2023.02a");
  EXPECT_EQ(out.at("yade_version_source"), "yade on PATH");
  ASSERT_TRUE(out.contains("yade_exact_law"));
  const auto lines = out.at("lines").get<std::vector<std::string>>();
  for (const auto& line : lines) EXPECT_EQ(line.find("vn="), std::string::npos) << line;
  std::vector<double> speeds, stated;
  for (const auto& e : out.at("eps")) {
    speeds.push_back(e.at("velocity_m_s").get<double>());
    stated.push_back(e.at("eps").get<double>());
  }
  ASSERT_EQ(speeds.size(), 3U);
  restitution::dem::Deck deck;
  deck.code = restitution::dem::Code::yade;
  deck.lines = lines;
  const auto m = restitution::dem::measure_yade_eps(program, deck, steel(), speeds, 5000);
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    ASSERT_TRUE(std::isfinite(m.extrapolated[i])) << m.output;
    EXPECT_GT(m.gap_m[i], 0.0) << "still in contact at v = " << speeds[i];
    const double measured = m.extrapolated[i];
    const double relative = (measured - stated[i]) / stated[i];
    EXPECT_LT(std::abs(relative), 1e-5)
        << "v = " << speeds[i] << ": coarse " << m.coarse[i] << ", fine " << m.fine[i] << ", extrapolated "
        << measured << ", stated " << stated[i];
    std::ostringstream text;
    text << std::scientific << relative;
    testing::Test::RecordProperty("relative_difference_" + std::to_string(i), text.str());
  }
}

INSTANTIATE_TEST_SUITE_P(Eps, YadeLines, testing::Values(0.5, 0.8),
                         [](const testing::TestParamInfo<double>& p) {
                           return p.param == 0.5 ? "eps05" : "eps08";
                         });

// --yade-version names another YADE: 2024.02a takes vn, so the lines are the exact law's (en, vn) and no
// alternative is printed; an unknown version is refused naming the option.
TEST(YadeLinesVersion, OptionTargetsTheNamedVersion) {
  const json exact =
      run_json("dem --code yade --eps 0.8 --velocity 1 --yade-version 2024.02a --json" + kMaterial);
  EXPECT_EQ(exact.at("yade_version"), "2024.02a");
  EXPECT_FALSE(exact.contains("yade_exact_law"));
  EXPECT_NE(exact.at("lines").at(1).get<std::string>().find("vn="), std::string::npos);
  const json old =
      run_json("dem --code yade --eps 0.8 --velocity 1 --yade-version 2023.02a --json" + kMaterial);
  // The old version's lines state one ε at every speed; the exact law's ε(v) sits under yade_exact_law only.
  for (const auto& e : old.at("eps")) EXPECT_NEAR(e.at("eps").get<double>(), 0.8, 1e-9);
  EXPECT_EQ(old.at("yade_exact_law").at("eps"), exact.at("eps"));
  const auto bad =
      restitution::test_support::run_cli("dem --code yade --eps 0.8 --yade-version 7" + kMaterial);
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("--yade-version"), std::string::npos) << bad.err;
}

// A scene's [[dem]] section targets the YADE on PATH as `dem --code yade` does: on Debian's 2023.02a the
// report shows the lines that run there and the one ε they give, never the 2024.02a lines next to the law's
// ε(v).
TEST(YadeLinesVersion, SceneSectionTargetsTheYadeOnPath) {
  const auto folder =
      std::filesystem::temp_directory_path() / ("restitution-yade-scene-" + std::to_string(::getpid()));
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  const auto scene = folder / "yade.toml";
  std::ofstream(scene) << "title = \"yade\"\noutput = \"out\"\n[materials.steel]\nyoung_modulus = "
                          "2.1e11\npoisson_ratio = 0.3\n"
                          "density = 7850.0\nradius = 0.005\ndissipative_constant = 5.8e-7\n"
                          "[[dem]]\nname = \"steel_yade\"\ncode = \"yade\"\nmaterial = \"steel\"\n"
                          "eps = 0.8\nvelocity = 1.0\nspeeds = [0.1, 1.0, 10.0]\n";
  setenv("RESTITUTION_PYTHON", "/nonexistent/python3", 1);  // the plots are not what is tested here
  const auto out = folder / "out";
  const auto r =
      restitution::test_support::run_cli("run " + scene.string() + " --quick --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string report = restitution::test_support::slurp((out / "report.md").string());
  EXPECT_NE(report.find("The yade lines are for YADE 2023.02a (yade on PATH)"), std::string::npos) << report;
  // The lines the report shows for this YADE take betan, not vn (the 2024.02a lines follow, labelled).
  const std::string shown = report.substr(0, report.find("The yade lines are for"));
  EXPECT_NE(shown.find("MindlinPhys(betan=MatchMaker(algo='val'"), std::string::npos) << shown;
  EXPECT_EQ(shown.find("vn="), std::string::npos) << shown;
  const json cli =
      run_json("dem --code yade --eps 0.8 --velocity 1 --impact-velocity 0.1 1 10 --json" + kMaterial);
  const std::string csv = restitution::test_support::slurp((out / "steel_yade.csv").string());
  std::istringstream rows(csv);
  std::string row;
  std::getline(rows, row);  // the header
  std::size_t i = 0;
  for (; std::getline(rows, row); ++i) {
    const double eps = std::stod(row.substr(row.find(',') + 1));
    EXPECT_NEAR(eps, cli.at("eps").at(i).at("eps").get<double>(), 1e-9) << row;
    EXPECT_NEAR(eps, 0.8, 1e-9) << row;  // 2023.02a: one ε at every speed
  }
  EXPECT_EQ(i, 3U);
  std::filesystem::remove_all(folder);
}

}  // namespace
