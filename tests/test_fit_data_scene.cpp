// SPDX-License-Identifier: BSD-3-Clause
// Scenes' [[fit]] sections: the shipped ice example (the 1999 paper's g* = 0.32 cm/s against a least-squares
// fit of the Bridges et al. formula), inline data with a material, bad data refused before anything is
// written.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "restitution/units.hpp"

namespace restitution {
namespace {

namespace fs = std::filesystem;
using test_support::run_cli;
using test_support::slurp;

fs::path scratch(const std::string& name) {
  const fs::path p =
      fs::temp_directory_path() / ("restitution-fit-scene-" + std::to_string(::getpid()) + "-" + name);
  fs::remove_all(p);
  return p;
}

TEST(FitDataScene, IceExampleGivesGStarWithItsInterval) {
  const fs::path out = scratch("ice");
  const auto r =
      run_cli("run " + std::string(RESTITUTION_SOURCE_DIR) + "/scenes/ice_fit.toml --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto summary = nlohmann::json::parse(slurp((out / "summary.json").string()));
  const auto& fit = summary["fit_ice"];
  EXPECT_TRUE(fit["sigma_estimated"].get<bool>());
  EXPECT_EQ(fit["points"], 31);
  for (const auto& f : fit["fits"]) EXPECT_TRUE(f["converged"].get<bool>()) << f["law"];
  // The paper's theory is the naive end; its g* = 0.32 cm/s gives beta = g*^{-1/5} / C1.
  const auto& naive = fit["fits"][1];
  ASSERT_EQ(naive["end"], "naive");
  const double g = naive["characteristic_velocity_m_s"].get<double>();
  EXPECT_DOUBLE_EQ(g, characteristic_velocity_m_s(naive["value"].get<double>()));
  EXPECT_LT(naive["characteristic_velocity_ci95"][0].get<double>(), g);
  EXPECT_GT(naive["characteristic_velocity_ci95"][1].get<double>(), g);
  std::printf(
      "ice: naive g* = %.4g cm/s, 95 %% [%.4g, %.4g] cm/s (paper: 0.32 cm/s); delayed recovery g* = %.4g "
      "cm/s\n",
      100 * g, 100 * naive["characteristic_velocity_ci95"][0].get<double>(),
      100 * naive["characteristic_velocity_ci95"][1].get<double>(),
      100 * fit["fits"][0]["characteristic_velocity_m_s"].get<double>());
  // A power law is no viscoelastic eps(v): the residual tests say the data leave every law.
  EXPECT_NE(naive["residual_tests"]["verdict"], "none");
  const std::string report = slurp((out / "report.md").string());
  EXPECT_NE(report.find("0.32 cm/s"), std::string::npos);
  EXPECT_TRUE(fs::exists(out / "ice.csv"));
  EXPECT_TRUE(fs::exists(out / "ice_curves.csv"));
  fs::remove_all(out);
}

TEST(FitDataScene, InlineDataWithAMaterialGiveA) {
  const fs::path out = scratch("inline");
  const fs::path scene =
      fs::temp_directory_path() / ("restitution-fit-inline-" + std::to_string(::getpid()) + ".toml");
  std::ofstream(scene) << "title = \"t\"\noutput = \"fit-out\"\n"
                       << "[materials.rubber]\nyoung_modulus = 1e7\npoisson_ratio = 0.45\ndensity = 1100.0\n"
                          "radius = 0.01\ndissipative_constant = 5.8e-5\n"
                          "[[fit]]\nname = \"drops\"\nv = [0.2, 0.5, 1.0, 2.0, 5.0]\n"
                          "eps = [0.85, 0.82, 0.80, 0.78, 0.74]\nsigma = [0.01, 0.01, 0.01, 0.01, 0.01]\n"
                          "material = \"rubber\"\nlaws = [\"viscoelastic-hertz\"]\n";
  setenv("RESTITUTION_PYTHON", "/nonexistent/python3", 1);  // no plot needed here
  const auto r = run_cli("run " + scene.string() + " --out " + out.string());
  unsetenv("RESTITUTION_PYTHON");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto summary = nlohmann::json::parse(slurp((out / "summary.json").string()));
  EXPECT_EQ(summary["fit_drops"]["fits"].size(), 2U);
  EXPECT_TRUE(summary["fit_drops"]["dissipative_constant_s"].contains("ci95"));
  fs::remove_all(out);
  fs::remove(scene);
}

TEST(FitDataScene, BadDataAreRefusedBeforeAnythingIsWritten) {
  const fs::path out = scratch("bad");
  const fs::path scene =
      fs::temp_directory_path() / ("restitution-fit-bad-" + std::to_string(::getpid()) + ".toml");
  std::ofstream(scene) << "title = \"t\"\noutput = \"fit-out\"\n"
                       << "[[fit]]\nname = \"drops\"\nv = [0.2, 0.5]\neps = [0.85, 1.5]\n";
  const auto r = run_cli("run " + scene.string() + " --out " + out.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("fit[0].eps"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("point 1: eps"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  fs::remove(scene);
}

}  // namespace
}  // namespace restitution
