// SPDX-License-Identifier: BSD-3-Clause
// The largest check decks `restitution dem --deck` writes, run as a user runs them: the most size classes
// (--radius-range RMIN:RMAX:N), the most radii (--radius R1,R2,...) and the most speeds (--impact-velocity)
// one deck allows (dem::kMaxDeckCollisionsLammps collisions), each in `lmp`, in `liggghts` and under `mpirun
// -np 2 lmp`. Every deck must print its last check line, every collision's ε within 1e-6 · min(ε, 1 − ε) of
// the ε the JSON output states, with the spheres apart at the end. One collision more is refused with exit 2
// naming the bound, and no file is written; so is a deck whose collisions differ so much in duration that it
// would take more than dem::kMaxDeckSphereSteps. The decks use narrow size and speed ranges so that every
// collision lasts about as long as the others: the run is then short (about 1e5 steps).
#include <fmt/core.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <ostream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "dem/check_deck.hpp"
#include "dem/code_runner.hpp"
#include "dem/process_output.hpp"

namespace {

namespace dem = restitution::dem;
using nlohmann::json;
using restitution::test_support::run_cli;
using restitution::test_support::TempFolder;

const std::string kSteel =
    " --young-modulus 2.1e11 --poisson-ratio 0.3 --density 7850 --eps 0.9 --velocity 1";

// n numbers from `first` in steps of `step`, joined by `separator`.
std::string series(std::size_t n, double first, double step, const std::string& separator) {
  std::string s;
  for (std::size_t i = 0; i < n; ++i)
    s += (i > 0 ? separator : "") + std::to_string(first + step * static_cast<double>(i));
  return s;
}

// The options of the largest deck of each kind at `extra` more collisions' worth (0: the largest allowed).
std::string classes_options(std::size_t extra) {
  return " --radius-range 0.0045:0.005:" + std::to_string(dem::max_deck_types(dem::Code::lammps, 1) + extra) +
         " --impact-velocity 1";
}
std::string radii_options(std::size_t extra) {
  const std::size_t n = dem::max_deck_types(dem::Code::lammps, 1) + extra;
  return " --radius " + series(n, 0.004, 0.001 / static_cast<double>(n), ",") + " --impact-velocity 1";
}
std::string speeds_options(std::size_t extra) {
  return " --radius 0.005 --impact-velocity " + series(dem::kMaxDeckCollisionsLammps + extra, 1.0, 1e-3, " ");
}

struct Case {
  std::string name;
  std::string code;     // of `dem --code`
  std::string runner;   // the command before `-in FILE`
  std::string options;  // the types and speeds
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << c.name;
}

class LargestDeck : public testing::TestWithParam<Case> {};

TEST_P(LargestDeck, RunsToItsLastCheckLineWithinTolerance) {
  const Case& c = GetParam();
  ASSERT_FALSE(dem::dem_program(dem::code_from_name(c.code)).empty()) << c.code << " not found on PATH";
  // Open MPI as root, on two cores shared with other work.
  setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  setenv("OMPI_MCA_mpi_yield_when_idle", "1", 1);
  setenv("OMPI_MCA_btl", "self,vader", 1);
  setenv("OMPI_MCA_btl_vader_single_copy_mechanism", "none", 1);
  const TempFolder folder;
  const std::string deck = (folder.path / "largest.in").string();
  const auto cli = run_cli("dem --code " + c.code + kSteel + c.options + " --json --deck " + deck);
  ASSERT_EQ(cli.status, 0) << cli.err;
  const json out = json::parse(cli.out);
  // The stated ε, pair by pair and speed by speed: the order of the deck's check lines.
  std::vector<double> stated;
  for (const json& p : out.contains("pairs") ? out.at("pairs") : json::array({out})) {
    for (const json& e : p.at("eps")) stated.push_back(e.at("eps").get<double>());
  }
  const std::size_t most = dem::kMaxDeckCollisionsLammps;
  EXPECT_LE(stated.size(), most);
  EXPECT_GT(stated.size(), most - most / 16) << "not the largest deck the bound allows";
  const auto bytes = std::filesystem::file_size(deck);

  const auto start = std::chrono::steady_clock::now();
  const std::string output =
      dem::output_of("cd " + folder.path.string() + " && " + c.runner + " -in largest.in 2>&1");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::vector<dem::CheckLine> lines = dem::read_check_lines(output);
  ASSERT_EQ(lines.size(), stated.size()) << c.runner << " -in " << deck << ":\n"
                                         << output.substr(output.size() > 3000 ? output.size() - 3000 : 0);
  double worst = 0.0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const double scale = std::min(stated[i], 1.0 - stated[i]);
    EXPECT_EQ(lines[i].eps_restitution, stated[i]) << "line " << i;
    EXPECT_GT(lines[i].gap_m, 0.0) << "line " << i << ": the spheres still touch at the end";
    EXPECT_NEAR(lines[i].eps_code, stated[i], 1e-6 * scale)
        << "types " << lines[i].type1 << "," << lines[i].type2 << " v = " << lines[i].speed_m_s;
    worst = std::max(worst, std::fabs(lines[i].eps_code - stated[i]) / scale);
  }
  std::cout << c.name << ": " << lines.size() << " collisions, deck " << bytes << " bytes, ran in " << seconds
            << " s, worst |eps_code - eps| / min(eps, 1 - eps) = " << worst << " (bound 1e-6)\n";
  RecordProperty("collisions", std::to_string(lines.size()));
  RecordProperty("deck_bytes", std::to_string(bytes));
  RecordProperty("run_seconds", std::to_string(seconds));
}

const std::string kMpi = "mpirun --oversubscribe -np 2 lmp";
const std::vector<Case> kCases = {
    {"lammps_classes", "lammps", "lmp", classes_options(0)},
    {"lammps_radii", "lammps", "lmp", radii_options(0)},
    {"lammps_speeds", "lammps", "lmp", speeds_options(0)},
    {"liggghts_classes", "liggghts", "liggghts", classes_options(0)},
    {"liggghts_radii", "liggghts", "liggghts", radii_options(0)},
    {"liggghts_speeds", "liggghts", "liggghts", speeds_options(0)},
    {"mpi_lammps_classes", "lammps", kMpi, classes_options(0)},
    {"mpi_lammps_radii", "lammps", kMpi, radii_options(0)},
    {"mpi_lammps_speeds", "lammps", kMpi, speeds_options(0)},
};

INSTANTIATE_TEST_SUITE_P(Largest, LargestDeck, testing::ValuesIn(kCases),
                         [](const testing::TestParamInfo<Case>& info) { return info.param.name; });

// One type or speed more than the bound allows: exit 2 naming it, before any work and without a file.
TEST(DeckBound, OneMoreIsRefusedNamingTheBound) {
  const TempFolder folder;
  const std::string deck = (folder.path / "refused.in").string();
  const std::string bound = "at most " + std::to_string(dem::kMaxDeckCollisionsLammps);
  for (const std::string& options :
       {classes_options(1), radii_options(1), speeds_options(1),
        // The default three speeds: one class more than max_deck_types(lammps, 3).
        " --radius-range 0.001:0.01:" + std::to_string(dem::max_deck_types(dem::Code::lammps, 3) + 1)}) {
    for (const std::string code : {"lammps", "liggghts"}) {
      const auto r = run_cli(fmt::format("dem --code {}{}{} --deck {}", code, kSteel, options, deck));
      EXPECT_EQ(r.status, 2) << code << options << ":\n" << r.err;
      EXPECT_NE(r.err.find(bound), std::string::npos) << r.err;
      EXPECT_FALSE(std::filesystem::exists(deck)) << code << options;
    }
  }
  // YADE runs each collision as a scene of its own: its bound is lower.
  const auto yade =
      run_cli("dem --code yade --yade-version 2024.02a" + kSteel + " --radius 0.005 --impact-velocity " +
              series(dem::kMaxDeckCollisionsYade + 1, 1.0, 0.01, " ") + " --deck " + deck + ".py");
  EXPECT_EQ(yade.status, 2) << yade.err;
  EXPECT_NE(yade.err.find("at most " + std::to_string(dem::kMaxDeckCollisionsYade)), std::string::npos)
      << yade.err;
  EXPECT_FALSE(std::filesystem::exists(deck + ".py"));
  // Few collisions are not enough: radii 10 um to 10 mm (collisions 1000 times longer than others) would
  // take about 1e11 sphere-steps.
  std::string radii;
  for (int i = 0; i <= 30; ++i) radii += (i > 0 ? "," : "") + std::to_string(1e-5 * std::pow(1e3, i / 30.0));
  for (const std::string code : {"lammps", "liggghts"}) {
    const auto slow = run_cli(
        fmt::format("dem --code {}{} --radius {} --impact-velocity 1 --deck {}", code, kSteel, radii, deck));
    EXPECT_EQ(slow.status, 2) << slow.err;
    EXPECT_NE(slow.err.find("sphere-steps"), std::string::npos) << slow.err;
    EXPECT_FALSE(std::filesystem::exists(deck)) << code;
  }
  // The bound is the first that fails: the largest allowed deck is written.
  const auto allowed = run_cli("dem --code lammps" + kSteel + " --radius-range 0.001:0.01:" +
                               std::to_string(dem::max_deck_types(dem::Code::lammps, 3)) + " --deck " + deck);
  EXPECT_EQ(allowed.status, 0) << allowed.err;
  EXPECT_TRUE(std::filesystem::exists(deck));
  // Without --deck the same options are no deck's business.
  const auto lines = run_cli("dem --code lammps" + kSteel + speeds_options(1));
  EXPECT_EQ(lines.status, 0) << lines.err;
}

}  // namespace
