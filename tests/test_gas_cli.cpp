// SPDX-License-Identifier: BSD-3-Clause
// `restitution gas` (docs/cli.md): the JSON and CSV carry the library's curve bit for bit, the law options
// (--eps/--velocity, --dissipative-constant, --law) reach the theory, and bad input exits 2 naming the
// option.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.hpp"
#include "restitution/material.hpp"
#include "restitution_gas/cooling.hpp"

namespace restitution::gas {
namespace {

using nlohmann::json;
using test_support::lines_of;
using test_support::run_cli;
using test_support::slurp;
using test_support::TempFolder;

// The spheres: R = 5 mm, ρ = 920 kg/m³, φ = 0.1, rms speed 1 m/s per direction.
const std::string kGas = "gas --radius 0.005 --density 920 --packing-fraction 0.1 --rms-speed 1 ";

TEST(GasCli, JsonCarriesTheLibrarysCurve) {
  const auto outcome = run_cli(kGas + "--eps 0.8 --velocity 2 --haff-times 100 --points-per-decade 4 --json");
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  const json j = json::parse(outcome.out);
  CoolingRequest r;
  r.particles = {sphere_mass_kg(0.005, 920.0), 0.01, 0.1};
  r.initial_temperature_j = r.particles.mass_kg;
  r.law = impact_law_from_eps(LawKind::viscoelastic_hertz, 0.8, 2.0, CollisionEnd::delayed_recovery);
  r.duration = 100.0;
  r.duration_in_haff_times = true;
  r.points_per_decade = 4;
  const CoolingCurve c = cooling_curve(r);
  EXPECT_EQ(j.at("tau0_s").get<double>(), c.tau0_s);
  ASSERT_EQ(j.at("time_s").size(), c.time_s.size());
  EXPECT_EQ(c.time_s.size(), 25U);  // six decades at 4 per decade, both ends
  for (std::size_t i = 0; i < c.time_s.size(); ++i) {
    EXPECT_EQ(j.at("time_s")[i].get<double>(), c.time_s[i]);
    EXPECT_EQ(j.at("temperature_j")[i].get<double>(), c.temperature_j[i]);
    EXPECT_EQ(j.at("local_exponent")[i].get<double>(), c.local_exponent[i]);
  }
  EXPECT_DOUBLE_EQ(j.at("duration_s").get<double>(), 100.0 * c.tau0_s);
}

TEST(GasCli, DissipativeConstantGivesTheMaterialsBeta) {
  const auto outcome = run_cli(
      kGas + "--young-modulus 1e8 --poisson-ratio 0.4 --dissipative-constant 1e-5 --duration 1 --json");
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  Material m;
  m.young_modulus_pa = 1e8;
  m.poisson_ratio = 0.4;
  m.radius1_m = m.radius2_m = 0.005;
  m.density_kg_m3 = 920.0;
  m.dissipative_constant_s = 1e-5;
  const json j = json::parse(outcome.out);
  EXPECT_DOUBLE_EQ(j.at("law").at("zeta_at_reference").get<double>(), material_constants(m).hertz.beta);
  EXPECT_EQ(j.at("law").at("reference_speed_m_s").get<double>(), 1.0);
}

TEST(GasCli, SpeedIndependentLawFollowsHaff) {
  const auto outcome = run_cli(kGas + "--law tsuji-hertz --eps 0.7 --velocity 2 --haff-times 1e3 --json");
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  const json j = json::parse(outcome.out);
  EXPECT_NEAR(j.at("haff_eps").get<double>(), 0.7, 1e-9);
  const double tau0 = j.at("tau0_s").get<double>();
  const double t0 = j.at("initial_temperature_j").get<double>();
  for (std::size_t i = 0; i < j.at("time_s").size(); ++i) {
    const double t = j.at("time_s")[i].get<double>();
    EXPECT_NEAR(j.at("temperature_j")[i].get<double>() * (1 + t / tau0) * (1 + t / tau0) / t0, 1.0, 1e-10);
  }
}

TEST(GasCli, CsvHoldsTheSameRows) {
  const TempFolder folder;
  const std::string csv = (folder.path / "gas.csv").string();
  const auto outcome = run_cli(kGas + "--eps 0.8 --velocity 2 --duration 10 --out " + csv + " --json");
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  const std::vector<std::string> lines = lines_of(slurp(csv));
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines[0].rfind("time_s,temperature_j,haff_temperature_j,local_exponent,", 0), 0U) << lines[0];
  EXPECT_EQ(lines.size(), json::parse(outcome.out).at("time_s").size() + 1);
}

TEST(GasCli, BadInputExitsTwoNamingTheOption) {
  const std::string law = "--eps 0.8 --velocity 2 --duration 1 ";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {kGas + law + "--packing-fraction 0.5", "--packing-fraction"},
      {"gas --radius 0.005 --density 920 --packing-fraction 0 --rms-speed 1 " + law, "--packing-fraction"},
      {"gas --radius 0.005 --density 920 --packing-fraction 0.1 --temperature -1 " + law, "--temperature"},
      {"gas --radius 0.005 --density 920 --packing-fraction 0.1 --temperature nan " + law, "--temperature"},
      {kGas + law + "--temperature 1", "--rms-speed and --temperature"},
      {kGas + law + "--haff-times 3", "--duration and --haff-times"},
      {"gas --density 920 --packing-fraction 0.1 --rms-speed 1 " + law, "--radius"},
      {kGas + "--eps 0.8 --duration 1", "--velocity"},
      {kGas + law + "--a2 much", "--a2"},
      {kGas + "--law tsuji-hertz --dissipative-constant 1e-5 --duration 1", "--dissipative-constant"},
      {kGas + law + "--radius2 0.004", "monodisperse"},
      {kGas + law + "--points-per-decade 0", "--points-per-decade"},
      {kGas + law + "--first-time -1", "--first-time"},
      {kGas + law + "--collision-rate-factor 0", "--collision-rate-factor"},
  };
  for (const auto& [arguments, named] : cases) {
    const auto outcome = run_cli(arguments);
    EXPECT_EQ(outcome.status, 2) << arguments;
    EXPECT_NE(outcome.err.find(named), std::string::npos) << arguments << "\n" << outcome.err;
    EXPECT_TRUE(outcome.out.empty()) << arguments;
  }
}

}  // namespace
}  // namespace restitution::gas
