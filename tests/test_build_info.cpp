// SPDX-License-Identifier: BSD-3-Clause
// Which SUNDIALS build the library runs on is told, and told the same way, by the library, `--version` and
// every JSON output (issue 27: the optimized build from Debian's source package, or the system library).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <regex>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "restitution/restitution.hpp"

namespace {

using restitution::test_support::run_cli;

TEST(BuildInfo, LibraryNamesTheSundialsItWasConfiguredWith) {
  const restitution::SundialsBuild build = restitution::sundials_build();
  EXPECT_EQ(std::string(build.version).rfind("6.", 0), 0U)
      << build.version;  // the API the code is written for
  // RESTITUTION_EXPECTED_SUNDIALS_BUILD is what CMake chose (tests/CMakeLists.txt).
  EXPECT_EQ(build.optimized, std::string(RESTITUTION_EXPECTED_SUNDIALS_BUILD) == "optimized");
  const std::string description = restitution::sundials_build_description();
  EXPECT_EQ(description.rfind(build.version, 0), 0U) << description;
  EXPECT_NE(description.find(build.optimized ? "optimized" : "unoptimized"), std::string::npos)
      << description;
}

TEST(BuildInfo, VersionFlagSaysWhichSundials) {
  const auto r = run_cli("--version");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find(std::string("SUNDIALS ") + restitution::sundials_build_description()),
            std::string::npos)
      << r.out;
}

// cmake/version.cmake: "X.Y.Z" at a release, "X.Y.0.devN+g<12 hex>" between releases; the commit in full.
TEST(BuildInfo, LibraryNamesItsVersionAndCommit) {
  const restitution::LibraryVersion library = restitution::library_version();
  EXPECT_TRUE(
      std::regex_match(library.version, std::regex(R"([0-9]+\.[0-9]+\.[0-9]+(\.dev[0-9]+\+g[0-9a-f]{12})?)")))
      << library.version;
  const std::string commit = library.commit;
  EXPECT_TRUE(std::regex_match(commit, std::regex("[0-9a-f]{40}|unknown"))) << commit;
  const std::string version = library.version;
  const auto hash = version.find("+g");
  if (hash != std::string::npos) {  // the development version names the commit it was built from
    EXPECT_EQ(commit.substr(0, 12), version.substr(hash + 2)) << version << " " << commit;
  }
}

TEST(BuildInfo, VersionFlagSaysTheLibraryVersion) {
  const auto r = run_cli("--version");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.substr(0, r.out.find('\n')),
            std::string("restitution ") + restitution::library_version().version)
      << r.out;
}

TEST(BuildInfo, JsonOutputsCarryTheSundialsBuild) {
  const restitution::SundialsBuild build = restitution::sundials_build();
  for (const std::string& command : std::vector<std::string>{
           "eps --zeta 1 --json", "calibrate --eps 0.8 --velocity 1 --json",
           "series eval --kind naive-series --zeta 0.1 --json",
           "damping-check --recipe lammps-tsuji --eps 0.5 --json",
           std::string("fit-data ") + RESTITUTION_SOURCE_DIR + "/examples/fit/rubber_drop.csv --json"}) {
    const auto r = run_cli(command);
    ASSERT_EQ(r.status, 0) << command << ": " << r.err;
    const auto json = nlohmann::json::parse(r.out);
    ASSERT_TRUE(json.contains("sundials")) << command << ": " << r.out;
    EXPECT_EQ(json["sundials"]["version"], build.version) << command;
    EXPECT_EQ(json["sundials"]["optimized"], build.optimized) << command;
  }
}

}  // namespace
