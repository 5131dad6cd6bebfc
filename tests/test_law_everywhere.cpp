// SPDX-License-Identifier: BSD-3-Clause
// The contact-law family at every front end: `eps`, `sweep` (ζ and physical units), `calibrate` and a scene
// each compute a Tsuji and a linear dash-pot case, checked against the closed forms of their naive ends
// (docs/contact_laws.md): Tsuji ε = exp(−πζ/√(5−ζ²)), the dash-pot ε = exp(−πr/√(1−r²)), ζ = 2r.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "reference/dashpot_closed_form.hpp"
#include "restitution/calibration.hpp"
#include "restitution/contact_law.hpp"
#include "restitution/sweep.hpp"

namespace restitution {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test_support::run_cli;
using test_support::slurp;

constexpr double kTolerance = 1e-10;

double tsuji_naive_eps(double zeta) {
  return std::exp(-M_PI * zeta / std::sqrt(5.0 - zeta * zeta));
}
double dashpot_naive_eps(double r) {
  return std::exp(-M_PI * r / std::sqrt(1.0 - r * r));
}
// ζ (Tsuji) and r (dash-pot) whose naive ε is eps: the closed forms inverted, L = -ln(ε)/π.
double tsuji_zeta_of(double eps) {
  const double l = -std::log(eps) / M_PI;
  return std::sqrt(5.0 * l * l / (1.0 + l * l));
}
double dashpot_ratio_of(double eps) {
  const double l = -std::log(eps) / M_PI;
  return l / std::sqrt(1.0 + l * l);
}

void expect_eps(double computed, double exact, const std::string& what) {
  // The tolerance holds relative to min(ε, 1 − ε); the margin covers the closed form's own rounding.
  EXPECT_NEAR(computed, exact, 1.5 * kTolerance * std::min(exact, 1.0 - exact)) << what;
}

// A CSV file as columns by name.
std::map<std::string, std::vector<double>> read_csv(const fs::path& path) {
  std::istringstream in(slurp(path.string()));
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  std::stringstream header(line);
  for (std::string name; std::getline(header, name, ',');) names.push_back(name);
  std::map<std::string, std::vector<double>> columns;
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::string field;
    for (std::size_t i = 0; i < names.size() && std::getline(row, field, ','); ++i) {
      if (!field.empty() && field != "ok") columns[names[i]].push_back(std::strtod(field.c_str(), nullptr));
    }
  }
  return columns;
}

class LawEverywhere : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() / ("restitution-laws-" + std::to_string(::getpid()) + "-" +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(folder_);
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }
  fs::path folder_;
};

TEST_F(LawEverywhere, EpsComputesTsujiAndDashpot) {
  const json t = json::parse(run_cli("eps --law tsuji-hertz --zeta 1.5 --end naive --json").out);
  expect_eps(t["naive"]["eps"].get<double>(), tsuji_naive_eps(1.5), "eps tsuji");
  const json d = json::parse(run_cli("eps --law linear-dashpot --damping-ratio 0.4 --json").out);
  expect_eps(d["naive"]["eps"].get<double>(), dashpot_naive_eps(0.4), "eps dash-pot naive");
  expect_eps(d["delayed_recovery"]["eps"].get<double>(), dashpot_eps(0.4, dashpot_delayed_duration(0.4)),
             "eps dash-pot delayed recovery");
}

TEST_F(LawEverywhere, SweepOverZetaComputesTsujiAndDashpot) {
  const fs::path tsuji = folder_ / "tsuji.csv";
  ASSERT_EQ(
      run_cli("sweep --law tsuji-hertz --zeta-range 0.1:2.1:5 --end naive --out " + tsuji.string()).status,
      0);
  const auto t = read_csv(tsuji);
  ASSERT_EQ(t.at("zeta").size(), 5U);
  for (std::size_t i = 0; i < 5; ++i) {
    expect_eps(t.at("naive_eps")[i], tsuji_naive_eps(t.at("zeta")[i]), "sweep tsuji");
  }
  const fs::path dashpot = folder_ / "dashpot.csv";
  ASSERT_EQ(run_cli("sweep --law linear-dashpot --zeta-range 0.2:1.8:4 --out " + dashpot.string()).status, 0);
  const auto d = read_csv(dashpot);
  ASSERT_EQ(d.at("zeta").size(), 4U);
  for (std::size_t i = 0; i < 4; ++i) {
    const double r = 0.5 * d.at("zeta")[i];
    expect_eps(d.at("naive_eps")[i], dashpot_naive_eps(r), "sweep dash-pot naive");
    expect_eps(d.at("delayed_recovery_eps")[i], dashpot_eps(r, dashpot_delayed_duration(r)),
               "sweep dash-pot delayed");
  }
}

TEST_F(LawEverywhere, SweepRefusesANaiveEndBeyondTheCriticalZeta) {
  const auto r =
      run_cli("sweep --law linear-dashpot --zeta-range 1:3:3 --out " + (folder_ / "x.csv").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("naive end does not exist"), std::string::npos) << r.err;
}

// Physical units: ζ and the SI scales by hand, F = k ξ^a + γ ξ^b ξ' on m: T = (v^{1-a} m/k)^{1/(1+a)},
// ζ = (γ/m) v^b T^{b+1}, L = v T.
TEST_F(LawEverywhere, PhysicalSweepsMatchContactLawPhysicalByHand) {
  const double k = 2.0e5;
  const double gamma = 3.0;
  const double m = 0.02;
  for (const char* law : {"tsuji-hertz", "linear-dashpot", "hertz-constant-damping", "viscoelastic-hertz"}) {
    const fs::path out = folder_ / (std::string(law) + ".csv");
    const auto r = run_cli(
        std::string("sweep --law ") + law + " --velocity-range 0.5:2:3 --end delayed-recovery --stiffness " +
        std::to_string(k) + " --damping-coefficient 3 --effective-mass 0.02 --out " + out.string());
    ASSERT_EQ(r.status, 0) << law << ": " << r.err;
    const auto c = read_csv(out);
    const auto [a, b] = law_exponents(law_from_name(law));
    ASSERT_EQ(c.at("velocity_m_s").size(), 3U) << law;
    for (std::size_t i = 0; i < 3; ++i) {
      const double v = c.at("velocity_m_s")[i];
      const double time_s = std::pow(std::pow(v, 1.0 - a) * m / k, 1.0 / (1.0 + a));
      const double zeta = gamma / m * std::pow(v, b) * std::pow(time_s, b + 1.0);
      EXPECT_NEAR(c.at("zeta")[i], zeta, 1e-14 * zeta) << law << " v=" << v;
      EXPECT_EQ(c.at("zeta")[i], ContactLaw::physical(law_from_name(law), k, gamma, m, v).zeta()) << law;
      const double tau = c.at("delayed_recovery_tau")[i];
      EXPECT_NEAR(c.at("delayed_recovery_duration_s")[i], tau * time_s, 1e-14 * tau * time_s) << law;
      const double x = c.at("max_compression_x")[i];
      EXPECT_NEAR(c.at("max_compression_m")[i], x * v * time_s, 1e-14 * x * v * time_s) << law;
    }
    if (speed_independent(law_from_name(law))) {
      // ζ is the same at every speed up to the rounding of the powers (and ε with it).
      EXPECT_NEAR(c.at("zeta").front(), c.at("zeta").back(), 1e-14 * c.at("zeta").back()) << law;
      EXPECT_NEAR(c.at("delayed_recovery_eps").front(), c.at("delayed_recovery_eps").back(), 1e-10) << law;
    }
  }
}

TEST_F(LawEverywhere, SweepRefusesBetaForAnotherLaw) {
  const auto r = run_cli(
      "sweep --law tsuji-hertz --velocity-range 1:2:2 --beta 0.1 "
      "--out " +
      (folder_ / "x.csv").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--stiffness"), std::string::npos) << r.err;
}

TEST_F(LawEverywhere, CalibrateInvertsTheClosedForms) {
  const json t =
      json::parse(run_cli("calibrate --law tsuji-hertz --eps 0.3 --velocity 1 --end naive --json").out);
  EXPECT_EQ(t["law"], "tsuji-hertz");
  EXPECT_NEAR(t["zeta"].get<double>(), tsuji_zeta_of(0.3), 1e-8 * tsuji_zeta_of(0.3));
  EXPECT_FALSE(t.contains("beta"));
  // Near the critical ζ the bracket stays below √5 (ε -> 0 there).
  const json t2 =
      json::parse(run_cli("calibrate --law tsuji-hertz --eps 1e-3 --velocity 1 --end naive --json").out);
  EXPECT_NEAR(t2["zeta"].get<double>(), tsuji_zeta_of(1e-3), 1e-8 * tsuji_zeta_of(1e-3));
  const json d =
      json::parse(run_cli("calibrate --law linear-dashpot --eps 0.05 --velocity 2 --end naive --json").out);
  EXPECT_NEAR(d["damping_ratio"].get<double>(), dashpot_ratio_of(0.05), 1e-8 * dashpot_ratio_of(0.05));
  EXPECT_EQ(d["zeta"].get<double>(), 2.0 * d["damping_ratio"].get<double>());
  EXPECT_EQ(run_cli("calibrate --law tsuji-hertz --eps 0.3 --velocity 1 --method fast").status, 2);
  EXPECT_EQ(run_cli("calibrate --law tsuji-hertz --eps 0.3 --velocity 1 --young-modulus 1e9 "
                    "--poisson-ratio 0.3 --radius 0.01 --density 1000")
                .status,
            2);
}

TEST_F(LawEverywhere, LibraryCalibrationAndSweepTakeTheLaw) {
  CollisionSolver solver;
  CalibrationRequest request;
  request.law = LawKind::linear_dashpot;
  request.eps = 0.2;
  request.velocity_m_s = 1.0;
  request.end = CollisionEnd::naive;
  const Calibration c = calibrate(request, solver);
  EXPECT_EQ(c.law, LawKind::linear_dashpot);
  EXPECT_NEAR(c.parameter, dashpot_ratio_of(0.2), 1e-8);
  EXPECT_EQ(c.beta, 0.0);
  EXPECT_FALSE(c.dissipative_constant_s.has_value());

  SolveOptions options;
  options.ends = EndSet{CollisionEnd::naive};
  std::vector<double> eps(3);
  SweepControl control;
  control.threads = 1;
  control.point_finished = [&eps](const SweepPoint& p) {
    eps[p.index] = end_of(*p.result, CollisionEnd::naive).eps;
  };
  run_sweep({0.5, 1.0, 2.0}, options, control, LawKind::tsuji_hertz);
  for (std::size_t i = 0; i < 3; ++i)
    expect_eps(eps[i], tsuji_naive_eps(std::vector{0.5, 1.0, 2.0}[i]), "lib");
}

TEST_F(LawEverywhere, SceneComputesTsujiAndDashpot) {
  const fs::path scene = folder_ / "laws.toml";
  std::ofstream(scene) << R"(output = "unused"
[[sweep]]
name = "tsuji"
law = "tsuji-hertz"
ends = "naive"
zeta = [0.5, 1.0, 2.0]

[[sweep]]
name = "dashpot"
law = "linear-dashpot"
zeta = [0.4, 1.2]

[[trajectory]]
name = "dashpot_trajectory"
law = "linear-dashpot"
zeta = 0.6

[[calibration]]
name = "tsuji_calibration"
law = "tsuji-hertz"
eps = 0.3
velocity = 1.0
end = "naive"
)";
  const auto r = run_cli("run " + scene.string() + " --out " + folder_.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto t = read_csv(folder_ / "tsuji.csv");
  ASSERT_EQ(t.at("zeta").size(), 3U);
  for (std::size_t i = 0; i < 3; ++i)
    expect_eps(t.at("naive_eps")[i], tsuji_naive_eps(t.at("zeta")[i]), "scene");
  const auto d = read_csv(folder_ / "dashpot.csv");
  for (std::size_t i = 0; i < 2; ++i) {
    expect_eps(d.at("naive_eps")[i], dashpot_naive_eps(0.5 * d.at("zeta")[i]), "scene dash-pot");
  }
  EXPECT_TRUE(fs::exists(folder_ / "dashpot_trajectory.csv"));
  const json summary = json::parse(slurp((folder_ / "summary.json").string()));
  const json& c = summary["calibrations"][0];
  EXPECT_EQ(c["law"], "tsuji-hertz");
  EXPECT_NEAR(c["zeta"].get<double>(), tsuji_zeta_of(0.3), 1e-8);
}

TEST_F(LawEverywhere, SceneRefusesHertzOnlyKeysAndAMissingNaiveEnd) {
  const fs::path scene = folder_ / "bad.toml";
  std::ofstream(scene) << "output = \"x\"\n[[sweep]]\nlaw = \"tsuji-hertz\"\nzeta = [1.0]\ncompare_series = "
                          "true\n";
  auto r = run_cli("run " + scene.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("compare_series"), std::string::npos) << r.err;
  std::ofstream(scene) << "output = \"x\"\n[[sweep]]\nlaw = \"tsuji-hertz\"\nzeta = [3.0]\n";
  r = run_cli("run " + scene.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("zeta"), std::string::npos) << r.err;
  std::ofstream(scene) << "output = \"x\"\n[[sweep]]\nlaw = \"hooke\"\nzeta = [1.0]\n";
  r = run_cli("run " + scene.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("law"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace restitution
