// SPDX-License-Identifier: BSD-3-Clause
// `restitution dem --code lammps --wall --deck FILE`, run as a user runs it (`lmp -in FILE` in a fresh
// folder): spheres moving onto a `fix wall/gran granular` wall with the printed wall line at three speeds,
// two time steps Richardson-extrapolated, give the ε(v) the JSON states within 1e-6 · min(ε, 1 − ε): the
// wall's own convention (hertz/material E read as (4/3) E/(2(1 − ν)), fix_wall_gran.cpp:160) is the one the
// lines use. And the pair's `pair_coeff` string pasted into the same wall gives another ε (steel: 0.856
// against 0.900 at 1 m/s), which is why the wall needs its own numbers.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "dem/check_deck.hpp"
#include "dem/code_runner.hpp"
#include "dem/process_output.hpp"

namespace {

using nlohmann::json;
using restitution::dem::CheckLine;
using restitution::test_support::slurp;
using restitution::test_support::TempFolder;

const std::string kSteel = " --young-modulus 2e11 --poisson-ratio 0.3 --radius 0.001 --density 7800";
const std::string kRubber = " --young-modulus 1e7 --poisson-ratio 0.45 --radius 0.01 --density 1100";

struct Case {
  std::string name;
  std::string arguments;  // after `dem --code lammps --wall`
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.name;
}

std::string run_in(const std::string& folder, const std::string& command) {
  return restitution::dem::output_of("cd " + folder + " && " + command + " 2>&1");
}

class WallDeck : public testing::TestWithParam<Case> {};

TEST_P(WallDeck, LammpsWallGivesTheLawsEps) {
  const Case& c = GetParam();
  ASSERT_FALSE(restitution::dem::dem_program(restitution::dem::Code::lammps).empty())
      << "lmp not found on PATH: scripts/setup installs Debian's lammps";
  const TempFolder folder;
  const std::string deck = (folder.path / "wall.in").string();
  const auto cli =
      restitution::test_support::run_cli("dem --code lammps --wall" + c.arguments + " --json --deck " + deck);
  ASSERT_EQ(cli.status, 0) << cli.err;
  const json out = json::parse(cli.out);
  EXPECT_EQ(out.at("contact"), "sphere-wall");
  const std::string output = run_in(folder.path.string(), out.at("deck").at("run").get<std::string>());
  const std::vector<CheckLine> lines = restitution::dem::read_check_lines(output);
  ASSERT_EQ(lines.size(), 3U) << output;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const CheckLine& l = lines[i];
    const double stated = out.at("eps")[i].at("eps").get<double>();
    EXPECT_EQ(l.type2, 0) << "the wall";
    EXPECT_EQ(l.speed_m_s, out.at("eps")[i].at("velocity_m_s").get<double>());
    EXPECT_EQ(l.eps_restitution, stated);
    EXPECT_GT(l.gap_m, 0.0) << "the sphere at v = " << l.speed_m_s << " m/s still touches the wall";
    EXPECT_NEAR(l.eps_code, (10.0 * l.eps_dt - l.eps_10dt) / 9.0, 1e-14);
    EXPECT_NEAR(l.eps_code, stated, 1e-6 * std::min(stated, 1.0 - stated)) << "v = " << l.speed_m_s;
    testing::Test::RecordProperty(
        "error_over_tolerance_" + std::to_string(i),
        std::to_string((l.eps_code - stated) / (1e-6 * std::min(stated, 1.0 - stated))));
  }
}

const std::vector<Case> kCases = {
    {"steel_rigid_wall_delayed", " --eps 0.9 --velocity 1" + kSteel},
    {"rubber_on_steel_wall_naive",
     " --eps 0.6 --velocity 2 --end naive --impact-velocity 0.5 2 8 --wall-young-modulus 2e11 "
     "--wall-poisson-ratio "
     "0.3" +
         kRubber},
    {"steel_on_steel_wall_friction",
     " --dissipative-constant 1e-7 --friction 0.3 --wall-young-modulus 2e11 --wall-poisson-ratio 0.3" +
         kSteel},
};

INSTANTIATE_TEST_SUITE_P(Walls, WallDeck, testing::ValuesIn(kCases),
                         [](const testing::TestParamInfo<Case>& info) { return info.param.name; });

// The pair's string in the wall: `dem --code lammps` (two equal steel spheres) calibrated to ε = 0.9 at 1
// m/s, its pair_coeff model pasted into the wall deck in place of the wall's own line. The wall reads it in
// its convention and gives another ε: the deck must see the difference the wall lines remove.
TEST(WallConvention, PairStringOnAWallGivesAnotherEps) {
  ASSERT_FALSE(restitution::dem::dem_program(restitution::dem::Code::lammps).empty()) << "lmp not found";
  const TempFolder folder;
  const std::string deck = (folder.path / "wall.in").string();
  const std::string common = " --eps 0.9 --velocity 1 --impact-velocity 1" + kSteel + " --json";
  const auto wall = restitution::test_support::run_cli("dem --code lammps --wall --deck " + deck + common);
  ASSERT_EQ(wall.status, 0) << wall.err;
  const auto pair = restitution::test_support::run_cli("dem --code lammps" + common);
  ASSERT_EQ(pair.status, 0) << pair.err;
  const std::string wall_line = json::parse(wall.out).at("lines").at(0).get<std::string>();
  const std::string pair_line = json::parse(pair.out).at("lines").at(1).get<std::string>();
  const std::string any_pair = "pair_coeff * * ";
  ASSERT_EQ(pair_line.rfind(any_pair, 0), 0U) << pair_line;
  const std::string swapped_line =
      "fix wall all wall/gran granular " + pair_line.substr(any_pair.size()) + " zplane 0 NULL";
  std::string text = slurp(deck);
  for (std::size_t at = text.find(wall_line); at != std::string::npos; at = text.find(wall_line, at)) {
    text.replace(at, wall_line.size(), swapped_line);
    at += swapped_line.size();
  }
  std::ofstream(folder.path / "pair_string.in") << text;
  const std::vector<CheckLine> lines =
      restitution::dem::read_check_lines(run_in(folder.path.string(), "lmp -in pair_string.in"));
  ASSERT_EQ(lines.size(), 1U);
  testing::Test::RecordProperty("pair_string_wall_eps", std::to_string(lines[0].eps_code));
  EXPECT_LT(lines[0].eps_code, 0.9 - 0.02) << "the pair's numbers on a wall";
}

}  // namespace
