// SPDX-License-Identifier: BSD-3-Clause
// One output-path policy for every command (issue 45, items 1 and 5), through the real program on the real
// file system: an output never replaces an input (by name, symlink or hard link), temporaries are never
// written through a planted link, a device is written in place or refused (never a sibling file), two outputs
// of one command never share a path, and a file name cannot shift the columns of a CSV.
#include <fmt/core.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "haff_log.hpp"

namespace restitution {
namespace {
namespace fs = std::filesystem;
using test_support::kHaffGas;
using test_support::run_cli;
using test_support::slurp;
using test_support::TempFolder;
using test_support::write_haff_log;

const std::string& kCurve = kHaffGas;

std::string quoted(const fs::path& p) {
  return "'" + p.string() + "'";
}

// The names in `folder` (none of a run may be left behind: temporaries, sibling figures).
std::vector<std::string> names_in(const fs::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(OutputPolicy, ADeckOverItsOwnCompareLogIsRefusedBeforeAnythingIsWritten) {
  const TempFolder dir;
  const fs::path log = dir.path / "my.log";
  ASSERT_TRUE(write_haff_log(log));
  const std::string before = slurp(log.string());
  fs::create_symlink(log, dir.path / "link.log");
  fs::create_hard_link(log, dir.path / "hard.log");
  // The log by its own name, through a symlink, and through a hard link; each a refusal naming both options.
  for (const std::string& deck : {"my.log", "link.log", "hard.log"}) {
    const auto r =
        run_cli(kHaffGas + "--particles 20 --deck " + quoted(dir.path / deck) + " --compare " + quoted(log));
    EXPECT_EQ(r.status, 2) << deck << ": " << r.err;
    EXPECT_NE(r.err.find("--deck"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("is the input --compare"), std::string::npos) << r.err;
    EXPECT_EQ(slurp(log.string()), before) << deck;
  }
  EXPECT_EQ(names_in(dir.path), (std::vector<std::string>{"hard.log", "link.log", "my.log"}));
  // The deck's data file is an output too: `my.log` as STEM.data.
  const auto r = run_cli(kHaffGas + "--particles 20 --deck " + quoted(dir.path / "my.in") + " --compare " +
                         quoted(dir.path / "my.data"));
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("its data file"), std::string::npos) << r.err;
}

TEST(OutputPolicy, APlantedTemporaryLinkNeverReachesItsVictim) {
  const TempFolder dir;
  const fs::path victim = dir.path / "victim";
  std::ofstream(victim) << "precious\n";
  // The fixed temporary names of earlier versions, planted as links to the victim.
  for (const char* planted : {"result.csv.tmp", "gas.csv.tmp", "deck.data.tmp", "deck.in.tmp"})
    fs::create_symlink(victim, dir.path / planted);
  const auto out = run_cli(kCurve + "--out " + quoted(dir.path / "result.csv"));
  ASSERT_EQ(out.status, 0) << out.err;
  const auto deck = run_cli(kHaffGas + "--particles 20 --deck " + quoted(dir.path / "deck.in"));
  ASSERT_EQ(deck.status, 0) << deck.err;
  EXPECT_EQ(slurp(victim.string()), "precious\n");
  for (const char* written : {"result.csv", "deck.in", "deck.data", "deck_constant_eps.in"}) {
    EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(dir.path / written))) << written << " is no link";
  }
  EXPECT_NE(slurp((dir.path / "result.csv").string()).find("time_s"), std::string::npos);
  for (const std::string& name : names_in(dir.path)) {
    const bool planted = fs::is_symlink(fs::symlink_status(dir.path / name));
    EXPECT_TRUE(name.find(".tmp") == std::string::npos || planted) << "left behind: " << name;
  }
}

TEST(OutputPolicy, AFigureOnADeviceIsRefusedAndNoSiblingFileAppears) {
  ASSERT_TRUE(fs::exists("/dev/full"));
  const bool existed = fs::exists("/dev/full.png");
  const auto r = run_cli(kCurve + "--plot /dev/full");
  EXPECT_EQ(r.status, 2) << r.err;
  // Refused by name (no figure format) before the device check could say it is a device: either names it.
  EXPECT_NE(r.err.find("'/dev/full'"), std::string::npos) << r.err;
  EXPECT_EQ(fs::exists("/dev/full.png"), existed) << "a figure written beside the device";
  if (!existed) fs::remove("/dev/full.png");  // what the old code made, not to mislead the next run
}

TEST(OutputPolicy, ATableOnADeviceIsWrittenInPlaceAndItsFailureSaid) {
  const auto r = run_cli(kCurve + "--out /dev/full");
  EXPECT_EQ(r.status, 3) << r.err;
  EXPECT_NE(r.err.find("/dev/full"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists("/dev/full.tmp"));
}

TEST(OutputPolicy, TwoOutputsOfOneCommandOnOnePathAreRefused) {
  const TempFolder dir;
  const fs::path x = dir.path / "x.png";
  fs::create_symlink(x, dir.path / "y.png");
  for (const std::string& plot : {"x.png", "y.png"}) {
    const auto r = run_cli(kCurve + "--out " + quoted(x) + " --plot " + quoted(dir.path / plot));
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find("are the same file"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(x)) << "nothing written";
  }
}

// A link whose target's folder is missing: writing would create folders where the link points, somewhere the
// user never named. Every command's file output refuses it before any work, and nothing is created.
TEST(OutputPolicy, NoCommandCreatesFoldersThroughALink) {
  const TempFolder dir;
  const fs::path link = dir.path / "link.csv";
  fs::create_symlink(dir.path / "elsewhere" / "deep" / "out.csv", link);
  const std::string steel =
      " --eps 0.9 --velocity 1 --young-modulus 2.1e11 --poisson-ratio 0.3 --radius 0.005 --density 7850";
  for (const std::string& command :
       {"sweep --zeta-range 0.1:1:3 --out " + quoted(link), kCurve + "--out " + quoted(link),
        "dem --code lammps --deck " + quoted(link) + steel,
        "oblique --friction 0.3 --angle 30" + steel + " --out " + quoted(link)}) {
    const auto r = run_cli(command);
    EXPECT_EQ(r.status, 2) << command << "\n" << r.err;
    EXPECT_NE(r.err.find("whose folder does not exist"), std::string::npos) << command << "\n" << r.err;
    EXPECT_FALSE(fs::exists(dir.path / "elsewhere")) << command;
  }
}

TEST(OutputPolicy, ALogNameHoldingQuotesAndControlsKeepsTheColumns) {
  const TempFolder dir;
  const std::string name = "a\"b,c\x1b[2Jd.log";  // a quote, a comma and an escape sequence
  ASSERT_TRUE(write_haff_log(dir.path / name));
  const auto r = run_cli(kHaffGas + "--compare " + quoted(dir.path / name) + " --compare-output " +
                         quoted(dir.path / "out"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.find('\x1b'), std::string::npos) << "printed raw: " << r.out;
  EXPECT_NE(r.out.find("\\x1b[2J"), std::string::npos) << r.out;
  std::istringstream csv(slurp((dir.path / "out" / "gas_compare.csv").string()));
  std::string line;
  std::getline(csv, line);
  int rows = 0;
  while (std::getline(csv, line)) {
    ++rows;
    // The run field: quoted, its inner quote doubled, nothing raw; then six fields after it.
    ASSERT_EQ(line.rfind("\"", 0), 0U) << line;
    const std::size_t end = line.find("\",", 1 + line.find("\"\"") + 2);
    ASSERT_NE(end, std::string::npos) << line;
    EXPECT_NE(line.substr(0, end).find("a\"\"b,c\\x1b[2Jd.log"), std::string::npos) << line;
    EXPECT_EQ(std::count(line.begin() + static_cast<long>(end), line.end(), ','), 6) << line;
  }
  EXPECT_GT(rows, 10);
}

}  // namespace
}  // namespace restitution
