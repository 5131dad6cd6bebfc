// SPDX-License-Identifier: BSD-3-Clause
// Every shipped scene runs end to end with CI's small settings (`--quick`), and its outputs say what they
// should. Plots are made for one scene; the others run as on a machine without matplotlib, which must still
// write the data and say so on stderr.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "restitution/series.hpp"
#include "restitution/units.hpp"

namespace restitution {
namespace {

namespace fs = std::filesystem;
using test_support::run_cli;
using test_support::slurp;

struct Csv {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  [[nodiscard]] double at(std::size_t row, const std::string& column) const {
    for (std::size_t i = 0; i < columns.size(); ++i) {
      if (columns[i] == column) return rows.at(row)[i];
    }
    ADD_FAILURE() << "no column " << column;
    return NAN;
  }
};

Csv read_csv(const fs::path& path) {
  std::istringstream in(slurp(path.string()));
  Csv csv;
  std::string line;
  std::getline(in, line);
  std::stringstream header(line);
  for (std::string c; std::getline(header, c, ',');) csv.columns.push_back(c);
  while (std::getline(in, line)) {
    std::stringstream cells(line);
    std::vector<double> row;
    for (std::string c; std::getline(cells, c, ',');) row.push_back(std::strtod(c.c_str(), nullptr));
    csv.rows.push_back(row);
  }
  return csv;
}

class ShippedScene : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() / ("restitution-scene-" + std::to_string(::getpid()) + "-" +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }

  // Runs scenes/<name>.toml with --quick into the test's folder; plots only when asked.
  nlohmann::json run(const std::string& name, bool plots = false) {
    if (plots) {
      unsetenv("RESTITUTION_PYTHON");
    } else {
      setenv("RESTITUTION_PYTHON", "/nonexistent/python3", 1);
    }
    const auto r = run_cli(fmt("run {}/scenes/{}.toml --quick --out {}", name));
    EXPECT_EQ(r.status, 0) << r.err;
    if (!plots && name != "calibration") {  // the calibration scene has no plots
      EXPECT_NE(r.err.find("cannot import matplotlib"), std::string::npos) << r.err;
    }
    EXPECT_TRUE(fs::exists(folder_ / "report.md"));
    return nlohmann::json::parse(slurp((folder_ / "summary.json").string()));
  }
  std::string fmt(const char* pattern, const std::string& name) const {
    std::string out = pattern;
    out.replace(out.find("{}"), 2, RESTITUTION_SOURCE_DIR);
    out.replace(out.find("{}"), 2, name);
    out.replace(out.find("{}"), 2, folder_.string());
    return out;
  }
  fs::path folder_;
};

TEST_F(ShippedScene, DefaultReproducesThe2008Paper) {
  const auto summary = run("default");
  const Csv fig1 = read_csv(folder_ / "fig1_eps_vs_zeta.csv");
  ASSERT_EQ(fig1.rows.size(), 6U);  // --quick
  EXPECT_EQ(fig1.at(0, "zeta"), 0.0);
  EXPECT_EQ(fig1.at(0, "naive_eps"), 1.0);
  for (std::size_t i = 1; i < fig1.rows.size(); ++i) {
    // Delayed recovery ends earlier, so it dissipates less: ε_delayed > ε_naive for ζ > 0 (2008 paper, Fig.
    // 1).
    EXPECT_GT(fig1.at(i, "delayed_recovery_eps"), fig1.at(i, "naive_eps"));
    EXPECT_LT(fig1.at(i, "naive_eps"), fig1.at(i - 1, "naive_eps"));
  }
  // Fig. 2: the naive ε falls as ζ^{-5} at large ζ (2008 paper: ε ~ v^{-1}).
  const Csv fig2 = read_csv(folder_ / "fig2_asymptotics.csv");
  const std::size_t last = fig2.rows.size() - 1;
  const double slope = std::log(fig2.at(last, "naive_eps") / fig2.at(last - 1, "naive_eps")) /
                       std::log(fig2.at(last, "zeta") / fig2.at(last - 1, "zeta"));
  EXPECT_NEAR(slope, -5.0, 1e-3);
  const Csv fig3 = read_csv(folder_ / "fig3_trajectory.csv");
  EXPECT_GT(fig3.rows.size(), 20U);
  EXPECT_LT(summary["fig3_trajectory"]["delayed_recovery"]["tau"].get<double>(),
            summary["fig3_trajectory"]["naive"]["tau"].get<double>());
  // Fig. 2 fits (asymptotics module): naive exponent -5, delayed recovery close to -5/3 (2008 paper: -0.331
  // in v).
  const auto& fits = summary["fig2_asymptotics"]["fits"];
  ASSERT_EQ(fits.size(), 2U);
  EXPECT_NEAR(fits[0]["exponent"].get<double>(), -5.0, 1e-6);
  EXPECT_NEAR(fits[1]["exponent"].get<double>(), -5.0 / 3.0, 0.01);
  // Table V check: where the series converges fast the difference is that of the printed digits (< 1e-9).
  const Csv table5 = read_csv(folder_ / "table5_check.csv");
  for (std::size_t i = 0; i < table5.rows.size(); ++i) {
    if (table5.at(i, "zeta") <= 0.1) {
      EXPECT_LT(std::abs(table5.at(i, "delayed_recovery_series_rel_diff")), 1e-9) << table5.at(i, "zeta");
    }
  }
  EXPECT_GT(std::abs(table5.at(table5.rows.size() - 1, "delayed_recovery_series_rel_diff")),
            1e-3);  // ζ = 0.9
  const std::string report = slurp((folder_ / "report.md").string());
  EXPECT_NE(report.find("## Fig. 1"), std::string::npos);
  EXPECT_NE(report.find("## Table V check"), std::string::npos);
}

TEST_F(ShippedScene, TrajectoryWithPlotsAndSiUnits) {
  const auto summary = run("trajectory", true);
  EXPECT_TRUE(fs::exists(folder_ / "strong_damping.png"));
  EXPECT_NE(slurp((folder_ / "report.md").string()).find("![strong_damping](strong_damping.png)"),
            std::string::npos);
  const Csv rubber = read_csv(folder_ / "rubber_2m_s.csv");
  // time_s / tau is the natural time scale T = k^{-2/5} v^{-1/5}, the same on every row.
  const double ratio = rubber.at(10, "time_s") / rubber.at(10, "tau");
  EXPECT_NEAR(rubber.at(rubber.rows.size() - 1, "time_s") / rubber.at(rubber.rows.size() - 1, "tau"), ratio,
              1e-12 * ratio);
  EXPECT_GT(ratio, 1e-4);  // rubber-like spheres of 1 cm: a collision lasts about a millisecond
  EXPECT_LT(ratio, 1e-3);
}

TEST_F(ShippedScene, MaterialSweepRubberAndIce) {
  run("material_sweep");
  const Csv rubber = read_csv(folder_ / "rubber.csv");
  for (std::size_t i = 0; i < rubber.rows.size(); ++i) {
    EXPECT_NEAR(rubber.at(i, "zeta"), rubber.at(i, "beta") * std::pow(rubber.at(i, "velocity_m_s"), 0.2),
                1e-14);
  }
  EXPECT_NEAR(rubber.at(0, "beta"), 0.201, 1e-3);
  const Csv ice = read_csv(folder_ / "ice.csv");
  for (std::size_t i = 0; i < ice.rows.size(); ++i) {
    // (g/g*)^{1/5} = C1 ζ with g* = 0.32 cm/s.
    EXPECT_NEAR(series::c1_closed_form() * ice.at(i, "zeta"),
                std::pow(ice.at(i, "velocity_m_s") / 0.0032, 0.2), 1e-13);
    EXPECT_NEAR(ice.at(i, "empirical_eps"), 0.32 * std::pow(100.0 * ice.at(i, "velocity_m_s"), -0.234),
                1e-14);
  }
  // Near 1 cm/s the theory with g* = 0.32 cm/s and the measured fit agree to within 10% (1999 paper, Fig. 1).
  std::size_t near_1cm = 0;
  for (std::size_t i = 0; i < ice.rows.size(); ++i) {
    if (std::abs(std::log(ice.at(i, "velocity_m_s") / 0.01)) <
        std::abs(std::log(ice.at(near_1cm, "velocity_m_s") / 0.01))) {
      near_1cm = i;
    }
  }
  EXPECT_NEAR(ice.at(near_1cm, "naive_eps") / ice.at(near_1cm, "empirical_eps"), 1.0, 0.1);
}

TEST_F(ShippedScene, CalibrationGivesThePapersBeta) {
  const auto summary = run("calibration");
  const auto& c = summary["calibrations"][0];
  EXPECT_EQ(c["end"], "delayed-recovery");
  EXPECT_NEAR(c["beta"].get<double>(), 0.2, 0.002);  // 2008 paper: β = 0.2 s^{1/5} m^{-1/5}
  EXPECT_NEAR(c["eps_at_zeta"].get<double>(), 0.8, 1e-7);
  EXPECT_NEAR(c["dissipative_constant_s"].get<double>(), 5.8e-5, 1e-7);  // the material's own A
}

TEST_F(ShippedScene, DashpotMatchesTheClosedForms) {
  const auto summary = run("dashpot");
  // --quick loosens the tolerance to 1e-8: the error relative to min(ε, 1-ε) must stay below it.
  EXPECT_LT(summary["dashpot"]["max_naive_relative_error"].get<double>(), 1e-8);
  EXPECT_LT(summary["dashpot"]["max_delayed_recovery_relative_error"].get<double>(), 1e-8);
  const Csv d = read_csv(folder_ / "dashpot.csv");
  EXPECT_TRUE(std::isnan(d.at(d.rows.size() - 1, "naive_eps")));  // r = 5: no naive end
}

TEST_F(ShippedScene, WorkPrecisionSectionWritesItsPointsAndSummary) {
  fs::create_directories(folder_);
  const fs::path scene = folder_ / "wp.toml";
  std::ofstream(scene) << "output = \"unused\"\n[[work_precision]]\nname = \"wp\"\nengines = [\"taylor\"]\n";
  setenv("RESTITUTION_PYTHON", "/nonexistent/python3", 1);
  const auto r = run_cli("run " + scene.string() + " --quick --out " + folder_.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string report = slurp((folder_ / "report.md").string());
  EXPECT_EQ(report.find("not available"), std::string::npos) << report;
  EXPECT_NE(report.find("* taylor, naive end: best error "), std::string::npos) << report;
  EXPECT_NE(report.find("* taylor, delayed-recovery end: best error "), std::string::npos) << report;
  // The points come from the reference file of the source tree: each within its tolerance (the contract).
  const Csv points = read_csv(folder_ / "wp.csv");
  EXPECT_EQ(points.rows.size(), 10U * (9 + 7));  // as `restitution work-precision --engine taylor`
  for (std::size_t i = 0; i < points.rows.size(); ++i) {
    EXPECT_LE(points.at(i, "error"), points.at(i, "tolerance"));
    EXPECT_GT(points.at(i, "median_us"), 0.0);
  }
  EXPECT_EQ(read_csv(folder_ / "wp_summary.csv").rows.size(), 2U * 10);
  const auto summary = nlohmann::json::parse(slurp((folder_ / "summary.json").string()));
  EXPECT_EQ(summary["studies"].size(), 3U);  // the heading line and one per end
}

TEST(RunCommand, BadScenesExitWithStatus2NamingFileAndLine) {
  const fs::path bad =
      fs::temp_directory_path() / ("restitution-bad-" + std::to_string(::getpid()) + ".toml");
  std::ofstream(bad) << "output = \"o\"\n[[sweep]]\nzeta = 1\nspeed = 3\n";
  const auto r = run_cli("run " + bad.string());
  fs::remove(bad);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "restitution: error: " + bad.string() + ":4: sweep[0].speed: unknown key\n");
  EXPECT_EQ(run_cli("run /nonexistent/scene.toml").status, 2);
}

}  // namespace
}  // namespace restitution
