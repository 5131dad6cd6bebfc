// SPDX-License-Identifier: BSD-3-Clause
// Issue 25 items 5-8: a scene's `output` stays under the working directory, empty --out/--out is refused,
// `reference --out` is never ignored, and every count option has an upper bound (exit 2, naming the option).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "cli_runner.hpp"

namespace restitution {
namespace {

namespace fs = std::filesystem;
using test_support::run_cli;
using test_support::unwrapped_help;

void expect_refused(const std::string& arguments, const std::string& words) {
  const auto r = run_cli(arguments);
  EXPECT_EQ(r.status, 2) << arguments << ": " << r.err;
  EXPECT_NE(r.err.find(words), std::string::npos) << arguments << ": " << r.err;
}

class SceneOutput : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() / ("restitution-bounds-" + std::to_string(::getpid()));
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }
  std::string scene_with(const std::string& output) {
    const fs::path scene = folder_ / "s.toml";
    std::ofstream(scene) << "output = \"" << output << "\"\n[[dashpot]]\ndamping_ratio = [0.5]\n";
    return scene.string();
  }
  fs::path folder_;
};

TEST_F(SceneOutput, AbsoluteOrClimbingOutputIsRefusedNamingTheKey) {
  for (const std::string output : {"/", "/tmp/elsewhere", "../up", "a/../../b"}) {
    expect_refused("run " + scene_with(output), "output");
  }
  EXPECT_FALSE(fs::exists("/tmp/elsewhere/report.md"));
}

TEST_F(SceneOutput, CommandLineOutputMayNameAnyFolder) {
  const fs::path out = folder_ / "chosen";
  const auto r = run_cli("run " + scene_with("relative/ok") + " --out " + out.string());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(out / "report.md"));
}

TEST(CliBounds, EmptyOutputIsRefusedEverywhere) {
  expect_refused("run scenes/dashpot.toml --out ''", "--out");
  expect_refused("sweep --zeta-range 0:1:2 --out ''", "--out");
  expect_refused("reference --out ''", "--out");
  expect_refused("work-precision --out ''", "--out");
  expect_refused("stability --zeta 1 --out ''", "--out");
  expect_refused("fast-table --out ''", "--out");
  expect_refused("export c-header --out ''", "--out");
}

TEST(CliBounds, ReferenceOutIsNeverIgnored) {
  expect_refused("reference --zeta 1 --out /tmp/restitution-never.csv", "--out");
  EXPECT_FALSE(fs::exists("/tmp/restitution-never.csv"));
}

TEST(CliBounds, CountsHaveUpperBounds) {
  expect_refused("work-precision --repeats 2000000000", "--repeats: expected a whole number in [1, 100]");
  expect_refused("fast-table --out /tmp/restitution-x.h --checks 2000000000", "--checks");
  expect_refused("fast-table --out /tmp/restitution-x.h --seed -1", "--seed");
  expect_refused("sweep --zeta-range 0:1:99999999999999999999 --out /tmp/restitution-x.csv",
                 "got '0:1:99999999999999999999': N must be a whole number in [1, 10000000]");
  EXPECT_NE(unwrapped_help(run_cli("sweep --help").out).find("in [1, 10000000]"), std::string::npos);
}

// Item 12/13: -0 prints as 0; dem prints small ε in significant digits, not %.10f; the help texts say what
// the program does.
TEST(CliWords, NegativeZeroZetaAndHelpTexts) {
  EXPECT_EQ(run_cli("eps --zeta -0 --json").out.rfind("{\"zeta\":0.0,", 0), 0U);
  // --velocity is required with --eps: its help line must not offer a default of 1 m/s.
  const std::string dem_help = unwrapped_help(run_cli("dem --help").out);
  const std::size_t velocity = dem_help.find("--velocity FLOAT");
  ASSERT_NE(velocity, std::string::npos) << dem_help;
  const std::string velocity_line = dem_help.substr(velocity, dem_help.find('\n', velocity) - velocity);
  EXPECT_EQ(velocity_line.find("default 1)"), std::string::npos) << velocity_line;
  EXPECT_NE(velocity_line.find("required with --eps"), std::string::npos) << velocity_line;
  for (const char* command : {"stability", "damping-check", "series eval"}) {
    const std::string help = unwrapped_help(run_cli(std::string(command) + " --help").out);
    EXPECT_EQ(help.find("17 significant"), std::string::npos) << command;
    EXPECT_NE(help.find("shortest form"), std::string::npos) << command;
  }
}

TEST(CliWords, DemPrintsSmallEpsInSignificantDigits) {
  const auto r = run_cli(
      "dem --code lammps --young-modulus 1e7 --poisson-ratio 0.45 --radius 0.01 --density 1100 "
      "--eps 0.01 --velocity 1 --end naive");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.find("eps = 0.0000"), std::string::npos) << r.out;  // %.10f gave 0.0000097903
}

// Item 12: reference --out, work-precision, stability and fast-table say so on Ctrl-C, like sweep and run,
// and neither write nor print a result (stability prints its table only when complete).
TEST(CliWords, SigintStopsLongCommandsSayingSo) {
  const fs::path dir = fs::temp_directory_path() / ("restitution-sigint-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const std::vector<std::pair<std::string, fs::path>> commands = {
      {"reference --out " + (dir / "r.csv").string(), dir / "r.csv"},
      // The signal comes after 1 s: each command is given several seconds of work, so that it arrives while
      // the command computes on a machine a few times faster than ours (7 repeats took 0.8 s here).
      {"work-precision --repeats 50 --out " + (dir / "wp").string(), dir / "wp" / "work_precision.csv"},
      {"stability --points-per-decade 100 --out " + (dir / "st").string(), dir / "st" / "stability.csv"},
      {"fast-table --out " + (dir / "t.h").string(), dir / "t.h"},
  };
  for (const auto& [command, output] : commands) {
    const std::string err = (fs::temp_directory_path() / "restitution-sigint-err").string();
    const std::string out = (fs::temp_directory_path() / "restitution-sigint-out").string();
    const int raw = std::system(("timeout --preserve-status -s INT 1 " + std::string(RESTITUTION_EXE) + " " +
                                 command + " >" + out + " 2>" + err)
                                    .c_str());
    EXPECT_EQ(WEXITSTATUS(raw), 130) << command;
    // Killed by the signal (no handler), timeout reports 130 too: the line is what tells them apart.
    EXPECT_NE(test_support::slurp(err).find("interrupted by signal 2: stopped, nothing half-written"),
              std::string::npos)
        << command << ": " << test_support::slurp(err);
    EXPECT_EQ(test_support::slurp(out), "") << command;
    EXPECT_FALSE(fs::exists(output)) << command;
  }
  fs::remove_all(dir);
}

// Item 12: a number option's text is judged as typed: empty, or beyond the double range (CLI11 alone took
// '' as not given and 1e309 as inf).
TEST(CliWords, NumberTextsAreJudgedAsTyped) {
  expect_refused("eps --zeta ''", "--zeta: the value is empty, expected a number");
  expect_refused("eps --zeta 1e309", "--zeta: '1e309' is beyond the range of a double");
  expect_refused("eps --zeta -1e400", "'-1e400' is beyond the range of a double");
  expect_refused("sweep --zeta-range 0:1e999:3 --out /tmp/restitution-x.csv",
                 "--zeta-range must be FROM:TO:N (zeta, N >= 1 points), got '0:1e999:3': '1e999' is beyond "
                 "the range of a double");
  expect_refused("eps --zeta inf", "got inf");  // spelled inf: the range check names it
  // Subnormal: representable, but 1 - eps would be subnormal too (issue 33, item 8; test_number_edges.cpp).
  expect_refused("eps --zeta 1e-320", "zeta = 1e-320 is below the smallest zeta served");
}

// Item 12: the tolerance range is stated per method; no method accepts the old lower bound 1e-14.
TEST(CliWords, ToleranceRangeIsPerMethod) {
  for (const std::string method : {"bdf", "taylor"}) {
    expect_refused("eps --zeta 1 --method " + method + " --tolerance 1e-15",
                   "tolerance must lie in [1e-11, 1e-2] for bdf, adams, auto (CVODE) or [1e-13, 1e-2] for "
                   "taylor, got 1e-15");
  }
  EXPECT_EQ(run_cli("eps --zeta 1 --method taylor --tolerance 1e-13").status, 0);
  expect_refused("eps --zeta 1 --method taylor --tolerance 1e-14", "(1e-13)");
}

// Item 12: an output the system refuses names the file and the folder; the system's own reason (ENOENT for
// /proc, which reads as if the folder were missing) comes last.
TEST(CliWords, UnwritableOutputNamesTheFileAndTheFolder) {
  const auto r = run_cli("sweep --zeta-range 0:1:3 --out /proc/x.csv");
  EXPECT_EQ(r.status, 3) << r.err;
  EXPECT_NE(
      r.err.find("cannot write '/proc/x.csv': the folder '/proc' does not let this program create files "
                 "in it (the system says: "),
      std::string::npos)
      << r.err;
  const auto folder = run_cli("stability --out /proc --points-per-decade 1");
  EXPECT_EQ(folder.status, 3) << folder.err;
  EXPECT_NE(folder.err.find("cannot write into output folder '/proc'"), std::string::npos) << folder.err;
}

// Item 12: a calibration's eps below the checked range, known only when it runs, is named like every other
// scene error: FILE:LINE: calibration[i].eps.
TEST_F(SceneOutput, CalibrationEpsOutOfRangeNamesFileLineAndKey) {
  const fs::path scene = folder_ / "cal.toml";
  std::ofstream(scene)
      << "output = \"unused\"\n\n[[calibration]]\nname = \"ok\"\neps = 0.5\nvelocity = 1.0\n\n"
      << "[[calibration]]\nname = \"tiny\"\nvelocity = 1.0\neps = 1e-300\n";
  const auto r = run_cli("run " + scene.string() + " --out " + (folder_ / "out").string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find(scene.string() + ":11: calibration[1].eps: eps = 1e-300 is below eps(zeta = 1e+06)"),
            std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace restitution
