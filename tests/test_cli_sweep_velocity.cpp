// SPDX-License-Identifier: BSD-3-Clause
// `restitution sweep` over impact speeds (issue 12, item 19): with β or a material, ζ = β v^{1/5}, the
// speeds the user gave at both ends, and the SI columns scene sweeps write, equal to a scene's numbers.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cli/scene/scene_tables.hpp"
#include "cli_runner.hpp"
#include "restitution/units.hpp"
#include "scene/scene.hpp"
#include "scene/scene_plan.hpp"
#include "scene/scene_run.hpp"
#include "scene/scene_sections.hpp"

namespace restitution {
namespace {
namespace fs = std::filesystem;
using test_support::run_cli;
using test_support::slurp;

using test_support::TempFolder;

// A CSV file as a header and rows of fields.
struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  [[nodiscard]] std::size_t column(const std::string& name) const {
    for (std::size_t i = 0; i < header.size(); ++i) {
      if (header[i] == name) return i;
    }
    ADD_FAILURE() << "no column " << name;
    return 0;
  }
  [[nodiscard]] double number(std::size_t row, const std::string& name) const {
    return std::stod(rows.at(row).at(column(name)));
  }
};

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  for (std::string field; std::getline(in, field, ',');) out.push_back(field);
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

Csv read_csv(const fs::path& path) {
  std::stringstream in(slurp(path.string()));
  Csv csv;
  std::string line;
  std::getline(in, line);
  csv.header = fields(line);
  while (std::getline(in, line)) csv.rows.push_back(fields(line));
  return csv;
}

TEST(CliSweepVelocity, BetaFormGivesZetaFromBetaAndTheSpeedsAsGiven) {
  const TempFolder dir;
  const fs::path out = dir.path / "v.csv";
  const auto outcome =
      run_cli("sweep --beta 0.2 --velocity-range 0.01:100:5 --log --tolerance 1e-8 --out " + out.string());
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  EXPECT_EQ(outcome.err, "");  // stderr is not a terminal: no progress line
  const Csv csv = read_csv(out);
  ASSERT_EQ(csv.rows.size(), 5U);
  EXPECT_EQ(csv.header[0], "zeta");
  EXPECT_EQ(csv.header[1], "velocity_m_s");
  EXPECT_EQ(csv.header[2], "beta");
  EXPECT_EQ(csv.rows.front()[1], "0.01");  // the numbers given, not exp(log(...))
  EXPECT_EQ(csv.rows.back()[1], "100");
  // Without a material there is no time or length scale: no SI columns.
  EXPECT_EQ(std::count(csv.header.begin(), csv.header.end(), "naive_duration_s"), 0);
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    const double v = csv.number(i, "velocity_m_s");
    EXPECT_EQ(csv.number(i, "zeta"), zeta_from(0.2, v));
    EXPECT_EQ(csv.number(i, "beta"), 0.2);
    EXPECT_EQ(csv.rows[i].at(csv.column("status")), "ok");
  }
}

TEST(CliSweepVelocity, MaterialFormWritesTheSameNumbersAsASceneSweep) {
  const TempFolder dir;
  const fs::path out = dir.path / "m.csv";
  const auto outcome = run_cli(
      "sweep --young-modulus 7e9 --poisson-ratio 0.3 --density 917 --radius 0.01 --dissipative-constant 1e-4 "
      "--velocity-range 0.01:10:4 --log --tolerance 1e-8 --out " +
      out.string());
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  const Csv csv = read_csv(out);

  // The same material and speeds (as the CLI wrote them, 17 digits) in a scene sweep.
  std::string speeds;
  for (const auto& row : csv.rows)
    speeds += (speeds.empty() ? "" : ", ") + row.at(csv.column("velocity_m_s"));
  const scene::Scene s = scene::parse_scene(
      "output = \"o\"\ntolerance = 1e-8\n[materials.ice]\nyoung_modulus = 7e9\npoisson_ratio = 0.3\n"
      "density = 917\nradius = 0.01\ndissipative_constant = 1e-4\n[[sweep]]\nmaterial = \"ice\"\nvelocity = "
      "[" +
          speeds + "]\n",
      "t");
  const scene::SceneResults results = scene::run_scene(s, scene::plan_scene(s));
  const cli::Table scene_table =
      cli::sweep_table(*scene::tasks_of<scene::Sweep>(s, "sweep")[0],
                       *scene::outcomes_of<scene::SweepOutcome>(s, results, "sweep")[0]);
  ASSERT_EQ(csv.rows.size(), scene_table.rows.size());
  // The columns both tables name alike hold the same numbers (same solves, same SI conversion).
  const std::vector<std::string> shared = {"zeta",
                                           "velocity_m_s",
                                           "beta",
                                           "naive_duration_s",
                                           "delayed_recovery_duration_s",
                                           "max_compression_time_s",
                                           "max_compression_m"};
  for (const std::string& name : shared) {
    for (std::size_t i = 0; i < csv.rows.size(); ++i)
      EXPECT_EQ(csv.number(i, name), scene_table.rows[i][scene_table.column(name)]) << name << " row " << i;
  }
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    EXPECT_EQ(csv.number(i, "delayed_recovery_eps"),
              scene_table.rows[i][scene_table.column("delayed_recovery_eps")]);
    EXPECT_EQ(csv.number(i, "naive_eps"), scene_table.rows[i][scene_table.column("naive_eps")]);
  }
}

TEST(CliSweepVelocity, RefusesIncompleteOrMixedFormsBeforeWriting) {
  const TempFolder dir;
  const std::string out = " --out " + (dir.path / "x.csv").string();
  const std::string ice = " --young-modulus 7e9 --poisson-ratio 0.3 --density 917 --radius 0.01";
  const struct {
    std::string arguments, message;
  } cases[] = {
      {"--velocity-range 1:2:2" + ice, "a material sweep needs --dissipative-constant"},
      {"--beta 0.2 --zeta-range 1:2:2", "not both"},
      {"--beta 0.2 --velocity-min 1 --points 2", "needs --velocity-min and --velocity-max"},
      {"--velocity-range 1:2:2", "exactly one of --beta and a material"},
      {"--beta 0.2 --velocity-range 1:2:2 --dissipative-constant 1e-4" + ice,
       "exactly one of --beta and a material"},
      {"--beta 1000 --velocity-range 1:1e20:3", "outside the checked range"},
      {"--beta 0.2 --velocity-range 0:1:3", "velocity must be finite and > 0"},
      {"--beta 0.2 --velocity-range 2:1:3", "velocity-min (2) must not exceed"},
      {"--points 3", "give --zeta-range FROM:TO:N, or --velocity-range FROM:TO:N"},
  };
  for (const auto& c : cases) {
    const auto outcome = run_cli("sweep " + c.arguments + out);
    EXPECT_EQ(outcome.status, 2) << c.arguments;
    EXPECT_NE(outcome.err.find(c.message), std::string::npos) << c.arguments << ": " << outcome.err;
    EXPECT_TRUE(fs::is_empty(dir.path)) << c.arguments;
  }
}

}  // namespace
}  // namespace restitution
