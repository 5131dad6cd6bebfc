// SPDX-License-Identifier: BSD-3-Clause
// Issue 33, items 8 and 9, through the command a user types: a number that underflows to 0 is refused (every
// number option, list options item by item, scene files), ζ below the smallest normal double is refused
// everywhere (1 - ε would be a subnormal double, too coarse for any tolerance), ζ = 0 answers ε = 1 for every
// member of the law family, and a scene sweep names its columns as `sweep --out` does.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "reference_values.hpp"

namespace restitution {
namespace {

using test_support::run_cli;
using test_support::slurp;
using test_support::TempFolder;

void expect_refused(const std::string& arguments, const std::string& words) {
  const auto r = run_cli(arguments);
  EXPECT_EQ(r.status, 2) << arguments << ": " << r.err;
  EXPECT_NE(r.err.find(words), std::string::npos) << arguments << ": " << r.err;
}

nlohmann::json eps_json(const std::string& arguments) {
  const auto r = run_cli("eps " + arguments + " --end both --json");
  EXPECT_EQ(r.status, 0) << arguments << ": " << r.err;
  return r.status == 0 ? nlohmann::json::parse(r.out) : nlohmann::json{};
}

std::vector<std::string> header_of(const std::string& csv_text) {
  std::istringstream in(csv_text);
  std::string line;
  while (std::getline(in, line) && line.rfind('#', 0) == 0) {
  }
  std::vector<std::string> names;
  std::istringstream fields(line);
  for (std::string name; std::getline(fields, name, ',');) names.push_back(name);
  return names;
}

constexpr const char* kUnderflow =
    "is nonzero but below the smallest double (4.9e-324): it would be read as 0";
constexpr const char* kNotServed = "is below the smallest zeta served";

TEST(NumberEdges, LiteralsThatUnderflowToZeroAreRefused) {
  expect_refused("eps --zeta 1e-400", std::string("--zeta: '1e-400' ") + kUnderflow);
  expect_refused("eps --zeta -1e-400", std::string("'-1e-400' ") + kUnderflow);
  expect_refused("eps --zeta 1 --tolerance 1e-999", std::string("--tolerance: '1e-999' ") + kUnderflow);
  expect_refused(
      "sweep --zeta-range 1e-400:1:3 --out /tmp/restitution-never.csv",
      std::string("--zeta-range must be FROM:TO:N (zeta, N >= 1 points), got '1e-400:1:3': '1e-400' ") +
          kUnderflow);
  // A list option, item by item.
  expect_refused(
      "dem --code lammps --young-modulus 2.1e11 --poisson-ratio 0.3 --density 7850 --radius "
      "0.001,1e-400 --eps 0.9 --velocity 1",
      std::string("'1e-400' ") + kUnderflow);
  // Zero written as zero stays zero: ε = 1 exactly.
  for (const std::string zero : {"0", "0.0", "0e-400", "-0"}) {
    const nlohmann::json j = eps_json("--zeta " + zero);
    EXPECT_EQ(j["delayed_recovery"]["eps"], 1.0) << zero;
  }
}

TEST(NumberEdges, ZetaBelowTheSmallestNormalDoubleIsRefusedByEveryFrontEnd) {
  expect_refused("eps --zeta 1e-320", std::string("zeta = 1e-320 ") + kNotServed);
  expect_refused("eps --zeta 2.225073858507201e-308", kNotServed);                // the largest subnormal
  expect_refused("eps --law linear-dashpot --damping-ratio 1e-308", kNotServed);  // ζ = 2r = 2e-308
  expect_refused("eps --law tsuji-hertz --zeta 4.9e-324 --method taylor", kNotServed);
  expect_refused("sweep --zeta-range 0:1e-310:2 --out /tmp/restitution-never.csv", kNotServed);
  expect_refused("series eval --kind naive --zeta 1e-315", kNotServed);
  expect_refused("reference --zeta 1e-315", kNotServed);
  EXPECT_FALSE(std::filesystem::exists("/tmp/restitution-never.csv"));
  // From the smallest normal double on, 1 - ε = C1 ζ to the tolerance (C1 in closed form, both ends).
  for (const std::string method : {"auto", "bdf", "taylor"}) {
    const nlohmann::json j = eps_json("--zeta 2.2250738585072014e-308 --method " + method);
    for (const char* end : {"naive", "delayed_recovery"}) {
      const double ratio = j[end]["one_minus_eps"].get<double>() / DBL_MIN;
      EXPECT_NEAR(ratio / test_support::c1_closed_form(), 1.0, 1e-10) << method << " " << end;
    }
  }
}

TEST(NumberEdges, ScenesRefuseUnderflowingAndSubnormalNumbers) {
  TempFolder folder;
  const auto scene_with = [&](const std::string& zetas) {
    const std::filesystem::path path = folder.path / "s.toml";
    std::ofstream(path) << "output = \"out\"\n"
                        << "# zeta = 1e-400 in a comment is no number\n[[sweep]]\nname = \"tiny\"\nzeta = ["
                        << zetas << "]\n";
    return run_cli("run " + path.string() + " --out " + (folder.path / "out").string());
  };
  auto r = scene_with("0.1, 1e-400");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find(":5: '1e-400' is nonzero but below the smallest double"), std::string::npos) << r.err;
  r = scene_with("0.1, 1e-320");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find(kNotServed), std::string::npos) << r.err;
  r = scene_with("0.0, 0e-400, 0.1");
  EXPECT_EQ(r.status, 0) << r.err;
}

TEST(NumberEdges, ZetaZeroIsTheUndampedOscillatorForEveryMember) {
  for (const std::string law :
       {"viscoelastic-hertz", "linear-dashpot", "tsuji-hertz", "hertz-constant-damping"}) {
    std::vector<std::string> methods = {"auto", "bdf", "adams"};
    if (law == "viscoelastic-hertz" || law == "linear-dashpot") methods.emplace_back("taylor");
    for (const std::string& method : methods) {
      const nlohmann::json j = eps_json("--law " + law + " --zeta 0 --method " + method);
      for (const char* end : {"naive", "delayed_recovery"}) {
        EXPECT_EQ(j[end]["eps"], 1.0) << law << " " << method << " " << end;
        EXPECT_EQ(j[end]["one_minus_eps"], 0.0) << law << " " << method << " " << end;
      }
    }
  }
  const nlohmann::json ratio = eps_json("--law linear-dashpot --damping-ratio 0");
  EXPECT_EQ(ratio["naive"]["eps"], 1.0);
  // The undamped dash-pot's half period is π in natural time.
  EXPECT_NEAR(ratio["naive"]["tau"].get<double>(), M_PI, 1e-9);
  expect_refused("eps --law linear-dashpot --damping-ratio -1", "damping-ratio must be finite and >= 0");
}

TEST(NumberEdges, SceneSweepAndSweepOutNameTheirColumnsAlike) {
  TempFolder folder;
  const std::filesystem::path csv = folder.path / "sweep.csv";
  ASSERT_EQ(run_cli("sweep --zeta-range 0.1:1:2 --out " + csv.string()).status, 0);
  const std::vector<std::string> sweep_columns = header_of(slurp(csv.string()));
  const std::filesystem::path scene = folder.path / "s.toml";
  std::ofstream(scene)
      << "output = \"out\"\n[[sweep]]\nname = \"z\"\nzeta = [0.1, 1.0]\nquantities = [\"eps\", "
         "\"one_minus_eps\", \"duration\", \"max_compression\"]\n";
  const auto r = run_cli("run " + scene.string() + " --out " + (folder.path / "out").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<std::string> scene_columns = header_of(slurp((folder.path / "out" / "z.csv").string()));
  ASSERT_GE(scene_columns.size(), 8U);
  for (const std::string& name : scene_columns) {
    EXPECT_NE(std::find(sweep_columns.begin(), sweep_columns.end(), name), sweep_columns.end())
        << "scene column " << name << " is not a column of sweep --out";
  }
}

}  // namespace
}  // namespace restitution
