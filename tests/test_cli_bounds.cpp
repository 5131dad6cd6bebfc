// Issue 25 items 5-8: a scene's `output` stays under the working directory, empty --out/--output is refused,
// `reference --out` is never ignored, and every count option has an upper bound (exit 2, naming the option).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli_runner.hpp"

namespace restitution {
namespace {

namespace fs = std::filesystem;
using test_support::run_cli;

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
  const auto r = run_cli("run " + scene_with("relative/ok") + " --output " + out.string());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(out / "report.md"));
}

TEST(CliBounds, EmptyOutputIsRefusedEverywhere) {
  expect_refused("run scenes/dashpot.toml --output ''", "--output");
  expect_refused("sweep --zeta-min 0 --zeta-max 1 --points 2 --out ''", "--out");
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
  expect_refused("sweep --zeta-min 0 --zeta-max 1 --points 99999999999999999999 --out /tmp/restitution-x.csv",
                 "got '99999999999999999999'");
  EXPECT_NE(run_cli("sweep --help").out.find("in [1, 10000000]"), std::string::npos);
}

// Item 12/13: -0 prints as 0; dem prints small ε in significant digits, not %.10f; the help texts say what
// the program does.
TEST(CliWords, NegativeZeroZetaAndHelpTexts) {
  EXPECT_EQ(run_cli("eps --zeta -0 --json").out.rfind("{\"zeta\":0.0,", 0), 0U);
  EXPECT_EQ(run_cli("dem --help").out.find("default 1)"), std::string::npos);
  for (const char* command : {"stability", "damping-check", "series eval"}) {
    const std::string help = run_cli(std::string(command) + " --help").out;
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

// Item 12: reference --out and work-precision say so on Ctrl-C, like sweep and run, and write nothing.
TEST(CliWords, SigintStopsReferenceAndWorkPrecisionSayingSo) {
  const fs::path dir = fs::temp_directory_path() / ("restitution-sigint-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  for (const std::string command :
       {"reference --out " + (dir / "r.csv").string(), "work-precision --out " + (dir / "wp").string()}) {
    const std::string err = (fs::temp_directory_path() / "restitution-sigint-err").string();
    const int raw = std::system(
        ("timeout --preserve-status -s INT 1 " + std::string(RESTITUTION_EXE) + " " + command + " 2>" + err)
            .c_str());
    EXPECT_EQ(WEXITSTATUS(raw), 130) << command;
    EXPECT_NE(test_support::slurp(err).find("interrupted by signal 2"), std::string::npos) << command;
    EXPECT_FALSE(fs::exists(dir / "r.csv"));
    EXPECT_FALSE(fs::exists(dir / "wp" / "work_precision.csv"));
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace restitution
