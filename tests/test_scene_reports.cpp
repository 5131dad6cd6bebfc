// SPDX-License-Identifier: BSD-3-Clause
// What report.md says about a scene's sweeps: an approximation compared at no point says "not compared"
// (never a difference of 0), a compared one names the points and the ζ range its largest difference is taken
// over, and a table that shows only some rows says so.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli_runner.hpp"

namespace restitution {
namespace {

namespace fs = std::filesystem;
using test_support::run_cli;
using test_support::slurp;

class SceneReport : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() / ("restitution-report-" + std::to_string(::getpid()) + "-" +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(folder_);
    fs::create_directories(folder_);
    setenv("RESTITUTION_PYTHON", "/nonexistent/python3", 1);  // no plots: the report text is what is tested
  }
  void TearDown() override { fs::remove_all(folder_); }

  // Writes the scene (output = folder/out) and runs it; returns report.md.
  std::string run(const std::string& body) {
    const fs::path scene = folder_ / "scene.toml";
    std::ofstream(scene) << "output = \"unused\"\n" << body;
    const auto r = run_cli("run " + scene.string() + " --out " + (folder_ / "out").string());
    EXPECT_EQ(r.status, 0) << r.err;
    return slurp((folder_ / "out" / "report.md").string());
  }
  fs::path folder_;
};

TEST_F(SceneReport, ApproximationWithoutAComparableEndIsNotCompared) {
  const std::string report = run(
      "[[sweep]]\nname = \"s\"\nzeta = { from = 0.1, to = 1.0, points = 3 }\nends = \"delayed-recovery\"\n"
      "approximations = [\"naive-series\", \"simple-theory-1999\"]\n");
  EXPECT_NE(report.find("`naive_series`"), std::string::npos) << report;
  EXPECT_NE(report.find("not compared"), std::string::npos) << report;
  EXPECT_EQ(report.find("over this sweep: 0"), std::string::npos) << report;
}

TEST_F(SceneReport, DifferencesNameTheirRangeAndHiddenRowsAreCounted) {
  const std::string report =
      run("[[sweep]]\nname = \"s\"\nzeta = { from = 0.01, to = 1.0, points = 12, spacing = \"log\" }\n"
          "ends = \"naive\"\napproximations = [\"naive-series\"]\n");
  EXPECT_NE(report.find("over 12 of 12 points, 0.01 <= zeta <= 1"), std::string::npos) << report;
  EXPECT_NE(report.find("9 of 12 rows shown"), std::string::npos) << report;
}

// Two tasks writing the same file are a scene error naming the line, before anything runs (item 10); a
// failed run leaves no output folder (item 11).
TEST_F(SceneReport, OutputNameCollisionsAndFailuresLeaveNoFolder) {
  const fs::path scene = folder_ / "clash.toml";
  std::ofstream(scene) << "output = \"unused\"\n"
                       << "[[sweep]]\nname = \"wp_summary\"\nzeta = [1.0]\n"
                       << "[[work_precision]]\nname = \"wp\"\n";
  auto r = run_cli("run " + scene.string() + " --out " + (folder_ / "out").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("clash.toml:6: work_precision[0].name: work_precision \"wp\" would write "
                       "wp_summary.csv, which sweep"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(folder_ / "out"));
  std::ofstream(scene) << "output = \"unused\"\n"
                       << "[[sweep]]\nname = \"" << std::string(5000, 'a') << "\"\nzeta = [1.0]\n";
  r = run_cli("run " + scene.string() + " --out " + (folder_ / "out").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("at most 100 characters"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(folder_ / "out"));
  // A calibration outside the checked range fails after planning: still no folder.
  std::ofstream(scene) << "output = \"unused\"\n"
                       << "[[calibration]]\neps = 1e-40\nvelocity = 1.0\nend = \"naive\"\n";
  r = run_cli("run " + scene.string() + " --out " + (folder_ / "out").string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("outside the checked range"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(folder_ / "out"));
}

}  // namespace
}  // namespace restitution
