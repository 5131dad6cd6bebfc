// SPDX-License-Identifier: BSD-3-Clause
// Runs the check decks `restitution dem --deck FILE` writes as a user does (`lmp -in FILE`, `liggghts -in
// FILE`, `yade -n -x FILE`, in a fresh folder) and reads the check lines they print (dem/check_deck.hpp): one
// per speed, each stating the ε the JSON output states, the code's Richardson-extrapolated ε agreeing with it
// within 1e-6 · min(ε, 1 − ε) for LAMMPS and LIGGGHTS, and within 1e-5 relative for YADE (Debian's 2023.02a,
// whose lines give one ε at every speed: the deck's prediction is that ε, not the law's ε(v)). Two materials
// (hard steel, soft rubber), both ends. One more deck, built through the library, collides three type pairs
// of two sizes in one LAMMPS run: the writer's interface for polydisperse sets.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "cli_runner.hpp"
#include "dem/check_deck.hpp"
#include "dem/code_runner.hpp"
#include "dem/deck.hpp"
#include "dem/deck_eps.hpp"
#include "dem/process_output.hpp"
#include "dem/yade_runner.hpp"
#include "restitution/collision_solver.hpp"
#include "restitution/contact_law.hpp"
#include "restitution/material.hpp"

namespace {

using nlohmann::json;
using restitution::dem::CheckLine;
using restitution::test_support::TempFolder;

const std::string kSteel = " --young-modulus 2.1e11 --poisson-ratio 0.3 --radius 0.005 --density 7850";
const std::string kRubber = " --young-modulus 1e7 --poisson-ratio 0.45 --radius 0.01 --density 1100";

struct Case {
  std::string name;
  std::string code;
  std::string arguments;  // after `dem --code CODE`
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.name;
}

std::string program_of(const std::string& code) {
  if (code == "yade") return restitution::dem::yade_program();
  return restitution::dem::dem_program(restitution::dem::code_from_name(code));
}

// The deck run in `folder` (LAMMPS writes log.lammps beside it) exactly as docs/dem.md says.
std::string run_deck(const std::string& folder, const std::string& command) {
  return restitution::dem::output_of("cd " + folder + " && " + command + " 2>&1");
}

void record(const std::string& name, double value) {
  std::ostringstream text;
  text << std::scientific << std::setprecision(2) << value;
  testing::Test::RecordProperty(name, text.str());
}

class CheckDeck : public testing::TestWithParam<Case> {};

TEST_P(CheckDeck, CodeRunsTheDeckAndAgreesWithRestitution) {
  const Case& c = GetParam();
  ASSERT_FALSE(program_of(c.code).empty()) << c.code << " not found on PATH: scripts/setup installs it";
  const TempFolder folder;
  const std::string deck = (folder.path / (c.code == "yade" ? "check.py" : "check.in")).string();
  const auto cli =
      restitution::test_support::run_cli("dem --code " + c.code + c.arguments + " --json --deck " + deck);
  ASSERT_EQ(cli.status, 0) << cli.err;
  const json out = json::parse(cli.out);
  ASSERT_EQ(out.at("deck").at("file"), deck);
  const std::string command = out.at("deck").at("run").get<std::string>();
  const std::string output = run_deck(folder.path.string(), command);
  const std::vector<CheckLine> lines = restitution::dem::read_check_lines(output);
  ASSERT_EQ(lines.size(), out.at("eps").size()) << command << ":\n" << output;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const CheckLine& l = lines[i];
    const double stated = out.at("eps")[i].at("eps").get<double>();
    EXPECT_EQ(l.code, c.code);
    EXPECT_EQ(l.type1, 1);
    EXPECT_EQ(l.type2, 1);
    EXPECT_EQ(l.speed_m_s, out.at("eps")[i].at("velocity_m_s").get<double>());
    // The deck's prediction is the ε the output states for these lines, to the last digit.
    EXPECT_EQ(l.eps_restitution, stated) << "v = " << l.speed_m_s;
    EXPECT_GT(l.gap_m, 0.0) << "the spheres at v = " << l.speed_m_s << " m/s still touch at the end";
    EXPECT_NEAR(l.eps_code, (10.0 * l.eps_dt - l.eps_10dt) / 9.0, 1e-14);
    EXPECT_NEAR(l.rel_diff, (l.eps_code - stated) / stated, 1e-13);
    if (c.code == "yade") {
      EXPECT_LT(std::abs(l.rel_diff), 1e-5) << "v = " << l.speed_m_s << ": " << output;
      record("relative_difference_" + std::to_string(i), l.rel_diff);
    } else {
      const double tolerance = 1e-6 * std::min(stated, 1.0 - stated);
      EXPECT_NEAR(l.eps_code, stated, tolerance) << "v = " << l.speed_m_s;
      // The extrapolation is a correction, not the whole answer: the fine run alone is already close.
      EXPECT_NEAR(l.eps_dt, stated, 100.0 * tolerance) << "v = " << l.speed_m_s;
      record("error_over_tolerance_" + std::to_string(i), (l.eps_code - stated) / tolerance);
    }
  }
}

const std::vector<Case> kCases = {
    {"lammps_steel_delayed", "lammps", " --eps 0.9 --velocity 1" + kSteel},
    {"lammps_rubber_naive", "lammps",
     " --eps 0.6 --velocity 2 --end naive --impact-velocity 0.5 2 8" + kRubber},
    {"liggghts_steel_naive", "liggghts", " --eps 0.9 --velocity 1 --end naive" + kSteel},
    {"liggghts_rubber_delayed", "liggghts", " --eps 0.6 --velocity 2 --impact-velocity 0.5 2 8" + kRubber},
    {"yade_steel", "yade", " --eps 0.8 --velocity 1" + kSteel},
    {"yade_rubber", "yade", " --eps 0.5 --velocity 2 --impact-velocity 0.5 2 8" + kRubber},
};

INSTANTIATE_TEST_SUITE_P(Codes, CheckDeck, testing::ValuesIn(kCases),
                         [](const testing::TestParamInfo<Case>& info) { return info.param.name; });

// Three type pairs of two sizes (R and 2R, types 1 and 2) in one LAMMPS deck, with the single `pair_coeff *
// *` line made for the R pair: each pair gets the ε that line gives it (deck_beta, the code's own reading),
// which differs from pair to pair since eta_n0 contains 1/m_eff. The deck must measure each.
TEST(CheckDeckPairs, EveryTypePairCollidesAndGetsItsOwnEps) {
  namespace dem = restitution::dem;
  const std::string program = dem::dem_program(dem::Code::lammps);
  ASSERT_FALSE(program.empty()) << "lmp not found on PATH";
  restitution::Material steel;
  steel.young_modulus_pa = 2.1e11;
  steel.poisson_ratio = 0.3;
  steel.radius1_m = steel.radius2_m = 0.005;
  steel.density_kg_m3 = 7850.0;
  const double a = 5e-7;  // A [s]
  const auto end = restitution::CollisionEnd::delayed_recovery;
  const dem::Deck lines = dem::make_deck(dem::Code::lammps, end, dem::pair_of(steel), a, 1.0);
  restitution::Material big = steel;
  big.radius2_m = 0.01;
  restitution::Material both_big = big;
  both_big.radius1_m = 0.01;

  dem::CheckDeckRequest request;
  request.code = dem::Code::lammps;
  request.lines = lines.lines;
  request.type_count = 2;
  request.speeds_m_s = {0.3, 3.0};
  restitution::CollisionSolver solver;
  for (const auto& [t1, t2, m] :
       {std::tuple{1, 1, steel}, std::tuple{1, 2, big}, std::tuple{2, 2, both_big}}) {
    dem::CheckPair p{t1, t2, dem::pair_of(m), {}};
    for (const double v : request.speeds_m_s) {
      p.eps_restitution.push_back(
          dem::eps_for(dem::deck_beta(lines, p.pair), v, end, restitution::SolveOptions{}.tolerance, solver));
    }
    request.pairs.push_back(p);
  }
  const TempFolder folder;
  std::ofstream((folder.path / "pairs.in").string()) << dem::check_deck(request);
  const std::string output = run_deck(folder.path.string(), "lmp -in pairs.in");
  const std::vector<CheckLine> read = dem::read_check_lines(output);
  ASSERT_EQ(read.size(), 6U) << output;
  std::size_t i = 0;
  for (const dem::CheckPair& p : request.pairs) {
    for (std::size_t s = 0; s < request.speeds_m_s.size(); ++s, ++i) {
      EXPECT_EQ(read[i].type1, p.type1);
      EXPECT_EQ(read[i].type2, p.type2);
      const double stated = p.eps_restitution[s];
      EXPECT_EQ(read[i].eps_restitution, stated);
      EXPECT_GT(read[i].gap_m, 0.0) << "types " << p.type1 << "," << p.type2;
      EXPECT_NEAR(read[i].eps_code, stated, 1e-6 * std::min(stated, 1.0 - stated))
          << "types " << p.type1 << "," << p.type2 << " v = " << request.speeds_m_s[s];
    }
  }
  // The three pairs really differ: the deck measured three ε, not one three times.
  EXPECT_GT(std::abs(read[0].eps_code - read[2].eps_code), 1e-3);
  EXPECT_GT(std::abs(read[2].eps_code - read[4].eps_code), 1e-3);
}

}  // namespace
