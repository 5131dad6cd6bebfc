// SPDX-License-Identifier: BSD-3-Clause
// The [[dem]] scene section runs the DEM code found on PATH without a shell, and says when its run failed.
// A fake `lmp` (a shell script printing the deck's EPS line, or failing) in a PATH folder whose name holds a
// `;` or a space: the folder is a folder, never a command line; a code that exits 1 or prints no ε is a
// warning, a `failed` row in the CSV and `code_run = "failed"` in summary.json, never a silent nan.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli_runner.hpp"

namespace {

namespace fs = std::filesystem;
using restitution::test_support::slurp;
using restitution::test_support::TempFolder;

const char* const kScene = R"(title = "fake lmp"
output = "out"
[materials.steel]
young_modulus = 2.1e11
poisson_ratio = 0.3
density = 7850.0
radius = 0.005
dissipative_constant = 5.8e-7

[[dem]]
name = "steel_lammps"
title = "LAMMPS"
code = "lammps"
material = "steel"
speeds = [1.0]
)";

struct SceneRun {
  int status = -1;
  std::string err, csv;
  nlohmann::json summary;
};

// Runs the scene in `folder` (its working folder) with PATH = `bin`:/usr/bin:/bin, `bin` holding an `lmp`
// script of `body`.
SceneRun run_with_fake_lmp(const fs::path& folder, const std::string& bin_name, const std::string& body) {
  const fs::path bin = folder / bin_name;
  fs::create_directories(bin);
  std::ofstream(bin / "lmp") << "#!/bin/sh\n" << body;
  fs::permissions(bin / "lmp", fs::perms::owner_all);
  std::ofstream(folder / "scene.toml") << kScene;
  // The shell here only starts the test; the quoting is the test's, the program is what is tested. No
  // plots (a python that fails at once): the report without figures is enough here.
  const std::string command = "cd '" + folder.string() + "' && PATH='" + bin.string() +
                              ":/usr/bin:/bin' RESTITUTION_PYTHON=/bin/false " + RESTITUTION_EXE +
                              " run scene.toml --out out >/dev/null 2>err.txt";
  const int raw = std::system(command.c_str());
  SceneRun r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128;
  r.err = slurp((folder / "err.txt").string());
  r.csv = slurp((folder / "out" / "steel_lammps.csv").string());
  if (fs::exists(folder / "out" / "summary.json"))
    r.summary = nlohmann::json::parse(slurp((folder / "out" / "summary.json").string()));
  return r;
}

// A fake lmp that prints the deck's one EPS row (speed 0) as the real code would.
const std::string kPrintsEps = "echo 'LAMMPS (fake)'\necho 'EPS 0 0.875 0.001'\n";

TEST(DemRunnerCli, APathFolderWithASemicolonIsAFolderNotACommand) {
  TempFolder folder;
  const SceneRun r = run_with_fake_lmp(folder.path, "a;touch PWNED;b", kPrintsEps);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_FALSE(fs::exists(folder.path / "PWNED")) << "the PATH folder's name ran as a command";
  EXPECT_NE(r.csv.find(",0.875,"), std::string::npos) << r.csv;
  EXPECT_NE(r.csv.find(",ok\n"), std::string::npos) << r.csv;
  EXPECT_EQ(r.summary.at("dem_steel_lammps").at("code_run"), "ok");
}

TEST(DemRunnerCli, APathFolderWithASpaceRuns) {
  TempFolder folder;
  const SceneRun r = run_with_fake_lmp(folder.path, "my codes", kPrintsEps);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.csv.find("velocity_m_s,eps_restitution,eps_lammps,rel_diff,lammps_run\n"), std::string::npos)
      << r.csv;
  EXPECT_NE(r.csv.find(",0.875,"), std::string::npos) << r.csv;
  EXPECT_EQ(r.err.find("run failed"), std::string::npos) << r.err;
}

TEST(DemRunnerCli, ACodeThatFailsIsAWarningAndMarked) {
  TempFolder folder;
  const SceneRun r =
      run_with_fake_lmp(folder.path, "bin", "echo 'LAMMPS (fake)'\necho 'ERROR: fake failure' >&2\nexit 1\n");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("warning: steel_lammps: the lammps run failed"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("exited with status 1"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("ERROR: fake failure"), std::string::npos) << r.err;
  EXPECT_NE(r.csv.find(",failed\n"), std::string::npos) << r.csv;
  EXPECT_EQ(r.summary.at("dem_steel_lammps").at("code_run"), "failed");
  EXPECT_NE(r.summary.at("dem_steel_lammps").at("code_failure").get<std::string>().find("status 1"),
            std::string::npos);
}

TEST(DemRunnerCli, ACodeThatPrintsNoEpsIsAWarningAndMarked) {
  TempFolder folder;
  const SceneRun r = run_with_fake_lmp(folder.path, "bin", "echo 'LAMMPS (fake)'\n");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("printed no eps for 1 of its 1 collisions"), std::string::npos) << r.err;
  EXPECT_NE(r.csv.find(",failed\n"), std::string::npos) << r.csv;
  EXPECT_EQ(r.summary.at("dem_steel_lammps").at("code_run"), "failed");
}

}  // namespace
