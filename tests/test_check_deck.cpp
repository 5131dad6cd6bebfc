// SPDX-License-Identifier: BSD-3-Clause
// `restitution dem --deck FILE` without running a DEM code (tests/dem/check_decks.cpp runs the decks): the
// refusals and their exit statuses, the output unchanged but for the deck's line or field, the deck's text
// (the lines verbatim, two time steps ten apart, one check line per type pair and speed) and the reading of
// check lines.
#include <fmt/core.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "dem/check_deck.hpp"
#include "dem/deck.hpp"
#include "restitution/errors.hpp"
#include "restitution/material.hpp"

namespace restitution {
namespace {

using nlohmann::json;
using test_support::run_cli;
using test_support::slurp;
using test_support::TempFolder;

const std::string kSteel =
    " --eps 0.9 --velocity 1 --young-modulus 2.1e11 --poisson-ratio 0.3 --radius 0.005 --density 7850";

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(CheckDeckCli, BadDeckRequestsAreRefusedBeforeAnyWork) {
  const TempFolder folder;
  const auto empty = run_cli("dem --code lammps --deck ''" + kSteel);
  EXPECT_EQ(empty.status, 2);
  EXPECT_NE(empty.err.find("--deck"), std::string::npos) << empty.err;
  for (const char* code : {"mercurydpm", "chrono"}) {
    const std::string file = (folder.path / "deck.txt").string();
    const auto r = run_cli(fmt::format("dem --code {} --deck {}{}", code, file, kSteel));
    EXPECT_EQ(r.status, 2) << code;
    EXPECT_NE(r.err.find(code), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("no runnable deck"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_FALSE(std::filesystem::exists(file));
  }
  // YADE runs `yade -n -x FILE` only for a FILE ending in .py; another name would run nothing and exit 0.
  for (const char* name : {"check.in", "check", "check.py.txt"}) {
    const std::string file = (folder.path / name).string();
    const auto r = run_cli("dem --code yade --deck " + file + kSteel);
    EXPECT_EQ(r.status, 2) << name;
    EXPECT_NE(r.err.find("ends in .py"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("name it " + file + ".py"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_FALSE(std::filesystem::exists(file)) << name;
  }
  const auto unwritable = run_cli("dem --code lammps --deck /proc/restitution-deck.in" + kSteel);
  EXPECT_EQ(unwritable.status, 3);
  EXPECT_NE(unwritable.err.find("/proc/restitution-deck.in"), std::string::npos) << unwritable.err;
  EXPECT_TRUE(unwritable.out.empty());
  const auto folder_path = run_cli("dem --code lammps --deck " + folder.path.string() + kSteel);
  EXPECT_EQ(folder_path.status, 2);
  EXPECT_NE(folder_path.err.find("folder"), std::string::npos) << folder_path.err;
}

TEST(CheckDeckCli, OutputIsTodaysPlusTheDeck) {
  const TempFolder folder;
  const std::string file = (folder.path / "sub" / "check.in").string();
  const auto plain = run_cli("dem --code liggghts" + kSteel);
  const auto with_deck = run_cli("dem --code liggghts --deck " + file + kSteel);
  ASSERT_EQ(with_deck.status, 0) << with_deck.err;
  EXPECT_EQ(with_deck.out,
            plain.out + "# check deck written to " + file + ": run `liggghts -in " + file + "`\n");
  EXPECT_TRUE(std::filesystem::exists(file));

  json plain_json = json::parse(run_cli("dem --code yade --json" + kSteel).out);
  json deck_json = json::parse(run_cli("dem --code yade --json --deck " + file + ".py" + kSteel).out);
  EXPECT_EQ(deck_json.at("deck").at("file"), file + ".py");
  EXPECT_EQ(deck_json.at("deck").at("run"), "yade -n -x " + file + ".py");
  deck_json.erase("deck");
  EXPECT_EQ(deck_json, plain_json);
}

TEST(CheckDeckCli, DeckHoldsTheLinesVerbatimAndStatesItsTimeSteps) {
  const TempFolder folder;
  const std::string file = (folder.path / "check.in").string();
  const auto r = run_cli("dem --code lammps --json --impact-velocity 0.5 1 2 --deck " + file + kSteel);
  ASSERT_EQ(r.status, 0) << r.err;
  const json out = json::parse(r.out);
  const std::string deck = slurp(file);
  // Two passes, each pasting the lines unchanged.
  for (const auto& line : out.at("lines")) EXPECT_EQ(count(deck, line.get<std::string>() + "\n"), 2U) << line;
  const std::regex timestep("timestep (\\S+)\n");
  const std::regex run("\nrun (\\d+)\n");
  std::vector<double> dt;
  std::vector<long> steps;
  for (auto it = std::sregex_iterator(deck.begin(), deck.end(), timestep); it != std::sregex_iterator(); ++it)
    dt.push_back(std::stod((*it)[1]));
  for (auto it = std::sregex_iterator(deck.begin(), deck.end(), run); it != std::sregex_iterator(); ++it)
    steps.push_back(std::stol((*it)[1]));
  ASSERT_EQ(dt.size(), 2U);
  ASSERT_EQ(steps.size(), 2U);
  EXPECT_NEAR(dt[0] / dt[1], 10.0, 1e-12);
  EXPECT_EQ(steps[1], 10 * steps[0]);
  // One check line per speed, carrying the stated ε as the output's shortest form.
  EXPECT_EQ(count(deck, "print \"restitution-check code=lammps types=1,1 speed="), 3U);
  for (const auto& e : out.at("eps")) {
    const std::string stated = fmt::format("eps_restitution={} ", e.at("eps").get<double>());
    EXPECT_EQ(count(deck, stated), 1U) << stated;
  }
}

TEST(CheckDeckCli, YadeDeckNamesTheVersionItsLinesAreFor) {
  const TempFolder folder;
  const std::string file = (folder.path / "check.py").string();
  const auto r = run_cli("dem --code yade --yade-version 2024.02a --json --deck " + file + kSteel);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string deck = slurp(file);
  EXPECT_NE(deck.find("TARGET = '2024.02a'"), std::string::npos);
  const json out = json::parse(r.out);  // named: a range-for over parse(...).at() would outlive the parse
  for (const auto& line : out.at("lines")) {
    EXPECT_NE(deck.find(line.get<std::string>()), std::string::npos) << line;
  }
}

dem::CheckDeckRequest one_pair(dem::Code code) {
  Material steel;
  steel.young_modulus_pa = 2.1e11;
  steel.poisson_ratio = 0.3;
  steel.radius1_m = steel.radius2_m = 0.005;
  steel.density_kg_m3 = 7850.0;
  dem::CheckDeckRequest r;
  r.code = code;
  r.lines = {"a", "b", "c"};
  r.speeds_m_s = {1.0, 2.0};
  r.pairs = {{1, 1, dem::pair_of(steel), {0.9, 0.8}}};
  return r;
}

TEST(CheckDeckText, RefusesWhatItCannotCollide) {
  EXPECT_THROW(dem::check_deck(one_pair(dem::Code::mercurydpm)), InvalidInput);
  EXPECT_THROW(dem::check_deck(one_pair(dem::Code::chrono)), InvalidInput);
  auto r = one_pair(dem::Code::lammps);
  EXPECT_NO_THROW(dem::check_deck(r));
  r.pairs[0].eps_restitution.pop_back();
  EXPECT_THROW(dem::check_deck(r), InvalidInput);
  r = one_pair(dem::Code::lammps);
  r.pairs[0].type2 = 2;  // one type only
  EXPECT_THROW(dem::check_deck(r), InvalidInput);
  r = one_pair(dem::Code::lammps);
  r.speeds_m_s[1] = 0.0;
  EXPECT_THROW(dem::check_deck(r), InvalidInput);
  r = one_pair(dem::Code::yade);
  r.lines.pop_back();  // YADE's deck places exactly three lines
  EXPECT_THROW(dem::check_deck(r), InvalidInput);
}

TEST(CheckDeckText, EveryTypePairGetsOneLinePerSpeed) {
  auto r = one_pair(dem::Code::lammps);
  r.type_count = 2;
  r.pairs.push_back({1, 2, r.pairs[0].pair, {0.7, 0.6}});
  r.pairs.push_back({2, 2, r.pairs[0].pair, {0.5, 0.4}});
  const std::string deck = dem::check_deck(r);
  EXPECT_NE(deck.find("create_box 2 box"), std::string::npos);
  EXPECT_EQ(count(deck, "print \"restitution-check"), 6U);
  EXPECT_EQ(count(deck, "types=1,2 speed=2 "), 1U);
  EXPECT_EQ(count(deck, "eps_restitution=0.4 "), 1U);
}

TEST(CheckDeckText, ReadsCheckLinesAmongTheCodesOwnOutput) {
  const auto lines = dem::read_check_lines(
      "LAMMPS banner\n"
      "restitution-check code=lammps types=1,2 speed=0.5 eps_10dt=0.81 eps_dt=0.82 eps_code=0.8211 "
      "eps_restitution=0.8212 rel_diff=-1e-4 gap_m=3e-5\n"
      "restitution-check-warning: the lines are for YADE 2024.02a\n"
      "restitution-check code=yade types=1,1 speed=2.0 eps_code=0.5\n");
  ASSERT_EQ(lines.size(), 2U);
  EXPECT_EQ(lines[0].code, "lammps");
  EXPECT_EQ(lines[0].type1, 1);
  EXPECT_EQ(lines[0].type2, 2);
  EXPECT_EQ(lines[0].speed_m_s, 0.5);
  EXPECT_EQ(lines[0].eps_10dt, 0.81);
  EXPECT_EQ(lines[0].eps_dt, 0.82);
  EXPECT_EQ(lines[0].eps_code, 0.8211);
  EXPECT_EQ(lines[0].eps_restitution, 0.8212);
  EXPECT_EQ(lines[0].rel_diff, -1e-4);
  EXPECT_EQ(lines[0].gap_m, 3e-5);
  EXPECT_EQ(lines[1].code, "yade");
  EXPECT_EQ(lines[1].speed_m_s, 2.0);
  EXPECT_TRUE(std::isnan(lines[1].eps_dt));
}

}  // namespace
}  // namespace restitution
