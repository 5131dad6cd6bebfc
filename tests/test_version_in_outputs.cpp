// SPDX-License-Identifier: BSD-3-Clause
// Every machine-readable output names the code that computed it (issue 36, docs/release.md): the JSON of
// every command that has --json, and a scene's summary.json and report.md, carry restitution's version, equal
// to what `restitution --version` prints, and its commit, next to the SUNDIALS build.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "reference/reference_solution.hpp"
#include "restitution/restitution.hpp"

namespace {

namespace fs = std::filesystem;
using restitution::test_support::lines_of;
using restitution::test_support::run_cli;
using restitution::test_support::slurp;
using restitution::test_support::subcommands_in;
using restitution::test_support::TempFolder;

const std::string kMaterial = " --young-modulus 1e7 --poisson-ratio 0.45 --radius 0.01 --density 1100";

// One quick invocation of each command that has --json, by the command's path ("series eval").
std::map<std::string, std::string> json_invocations(const fs::path& folder) {
  return {
      {"eps", "eps --zeta 1 --json"},
      {"fit", "fit --end naive --zeta-range 1:10:5 --json"},
      {"fit-data",
       std::string("fit-data ") + RESTITUTION_SOURCE_DIR + "/examples/fit/rubber_drop.csv --json"},
      {"stability", "stability --tolerance 1e-7 --json --out " + (folder / "stability").string()},
      {"calibrate", "calibrate --eps 0.8 --velocity 1 --json"},
      {"series coefficients", "series coefficients --kind naive --count 3 --json"},
      {"series eval", "series eval --kind naive-series --zeta 0.1 --json"},
      {"dem", "dem --code lammps --eps 0.6 --velocity 2 --json" + kMaterial},
      {"damping-check", "damping-check --recipe lammps-tsuji --eps 0.5 --json"},
      {"gas",
       "gas --radius 0.005 --density 920 --packing-fraction 0.1 --rms-speed 1 --eps 0.8 --velocity 2 "
       "--haff-times 100 --points-per-decade 4 --json"},
      {"oblique",
       "oblique --young-modulus 2e11 --poisson-ratio 0.3 --radius 1e-3 --density 7800 "
       "--dissipative-constant 1e-7 --tangential mindlin --friction 0.3 --angle 30 --json"},
  };
}

// Every command path whose --help offers --json, found from the program itself.
std::vector<std::string> commands_with_json() {
  std::vector<std::string> found;
  const auto visit = [&found](const std::string& path, const auto& self) -> void {
    const auto help = run_cli(path + " --help");
    const std::vector<std::string> subcommands = subcommands_in(help.out);
    for (const std::string& sub : subcommands) self(path.empty() ? sub : path + " " + sub, self);
    if (!path.empty() && subcommands.empty() && help.out.find("--json") != std::string::npos) {
      found.push_back(path);
    }
  };
  visit("", visit);
  return found;
}

std::string version_flag_version() {
  const auto r = run_cli("--version");
  const std::string first = r.out.substr(0, r.out.find('\n'));
  const std::string prefix = "restitution ";
  return first.rfind(prefix, 0) == 0 ? first.substr(prefix.size()) : "(--version printed: " + r.out + ")";
}

void expect_names_the_code(const nlohmann::json& json, const std::string& where) {
  ASSERT_TRUE(json.contains("restitution")) << where << ": no \"restitution\" key";
  EXPECT_EQ(json["restitution"]["version"], version_flag_version()) << where;
  EXPECT_EQ(json["restitution"]["commit"], restitution::library_version().commit) << where;
  ASSERT_TRUE(json.contains("sundials")) << where;
  EXPECT_EQ(json["sundials"]["version"], restitution::sundials_build().version) << where;
}

TEST(VersionInOutputs, VersionFlagNamesVersionAndCommit) {
  const auto r = run_cli("--version");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<std::string> lines = lines_of(r.out);
  ASSERT_GE(lines.size(), 3U) << r.out;
  EXPECT_EQ(lines[0], std::string("restitution ") + restitution::library_version().version);
  EXPECT_EQ(lines[1], std::string("commit ") + restitution::library_version().commit);
}

TEST(VersionInOutputs, EveryJsonCommandNamesTheCode) {
  TempFolder folder;
  const auto invocations = json_invocations(folder.path);
  const std::vector<std::string> commands = commands_with_json();
  ASSERT_GE(commands.size(), invocations.size()) << "fewer commands with --json than this test knows";
  for (const std::string& command : commands) {
    const auto invocation = invocations.find(command);
    ASSERT_NE(invocation, invocations.end())
        << "`" << command << "` has --json: add a quick invocation of it to json_invocations()";
    const auto r = run_cli(invocation->second);
    ASSERT_EQ(r.status, 0) << invocation->second << ": " << r.err;
    expect_names_the_code(nlohmann::json::parse(r.out), invocation->second);
  }
}

TEST(VersionInOutputs, SceneSummaryAndReportNameTheCode) {
  TempFolder folder;
  const fs::path scene = folder.path / "version.toml";
  std::ofstream(scene)
      << "output = \"unused\"\n[[sweep]]\nname = \"s\"\nzeta = { from = 0.1, to = 1.0, points = 3 }\n";
  setenv("RESTITUTION_PYTHON", "/nonexistent/python3", 1);  // no plots: the files are what is checked
  const auto r = run_cli("run " + scene.string() + " --out " + (folder.path / "out").string());
  unsetenv("RESTITUTION_PYTHON");
  ASSERT_EQ(r.status, 0) << r.err;
  expect_names_the_code(nlohmann::json::parse(slurp((folder.path / "out" / "summary.json").string())),
                        "summary.json");
  const std::string report = slurp((folder.path / "out" / "report.md").string());
  EXPECT_NE(report.find("restitution " + version_flag_version() + " (commit " +
                        restitution::library_version().commit + ")"),
            std::string::npos)
      << report;
  EXPECT_NE(report.find(std::string("SUNDIALS ") + restitution::sundials_build_description()),
            std::string::npos)
      << report;
}

TEST(VersionInOutputs, ReferenceCsvHeaderNamesTheCode) {
  const std::vector<std::string> lines = lines_of(restitution::reference_csv({}));
  ASSERT_GE(lines.size(), 3U);
  EXPECT_EQ(lines[1], "# Computed by restitution " + version_flag_version() + " (commit " +
                          restitution::library_version().commit + ").");
  // The reader skips comment lines: the header does not change what is read.
  EXPECT_EQ(lines[2].rfind("zeta,", 0), 0U) << lines[2];
}

}  // namespace
