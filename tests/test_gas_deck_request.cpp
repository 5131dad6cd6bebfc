// SPDX-License-Identifier: BSD-3-Clause
// The gas deck's request from the theory's gas (gas_deck/gas_deck_request.hpp) and the comparison of a deck's
// logs with the theory (gas_deck/compared_logs.hpp): the deck's T0, duration and bath are the theory's, a
// Haff log made at 0.9 of Enskog's rate gives back 0.9, and a log's notes reach the caller before a later
// log's error.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "gas_deck/compared_logs.hpp"
#include "gas_deck/gas_deck_request.hpp"
#include "gas_deck/gas_log_setup.hpp"
#include "restitution/errors.hpp"

namespace {

namespace gd = restitution::gas_deck;
namespace gas = restitution::gas;
using restitution::InvalidInput;

gas::GasInputs issue_gas_inputs() {
  gas::GasInputs in;
  in.radius_m = 0.005;
  in.density_kg_m3 = 920.0;
  in.young_modulus_pa = 1e8;
  in.poisson_ratio = 0.4;
  in.eps = 0.8;
  in.velocity_m_s = 2.0;
  in.packing_fraction = 0.1;
  in.rms_speed_m_s = 1.0;
  in.haff_times = 30.0;
  return in;
}

restitution::Material issue_material() {
  restitution::Material m;
  m.young_modulus_pa = 1e8;
  m.poisson_ratio = 0.4;
  m.density_kg_m3 = 920.0;
  m.radius1_m = m.radius2_m = 0.005;
  return m;
}

gd::GasDeckRequest issue_request(const std::optional<gas::Thermostat>& bath = std::nullopt) {
  const gas::GasInputs in = issue_gas_inputs();
  return gd::gas_deck_request(in, gas::cooling_request(in, gas::ArgumentStyle::option), issue_material(),
                              bath, {restitution::dem::kDefaultCode, 20, 7, 1e-3});
}

TEST(GasDeckRequest, TakesTheTheorysGas) {
  const gas::GasInputs in = issue_gas_inputs();
  const gas::CoolingRequest theory = gas::cooling_request(in, gas::ArgumentStyle::option);
  const gd::GasDeckRequest r = issue_request();
  // T0 = m rms^2 per direction: the deck's rms speed is the one asked for.
  EXPECT_NEAR(r.rms_speed_m_s, 1.0, 1e-14);
  EXPECT_DOUBLE_EQ(r.duration_s, 30.0 * gas::haff_reference(theory).tau0_s);
  EXPECT_EQ(r.packing_fraction, 0.1);
  EXPECT_EQ(r.particles, 20U);
  EXPECT_EQ(r.seed, 7U);
  EXPECT_EQ(r.damping.eps, 0.8);
  EXPECT_FALSE(r.bath.has_value());
}

TEST(GasDeckRequest, ABathRelaxesAsTheTheorysSteadyState) {
  const gas::GasInputs in = issue_gas_inputs();
  const gas::CoolingRequest theory = gas::cooling_request(in, gas::ArgumentStyle::option);
  gas::Thermostat bath;
  bath.bath_temperature_j = 1e-3;
  bath.bath_time_s = 0.5;
  const gd::GasDeckRequest r = issue_request(bath);
  ASSERT_TRUE(r.bath.has_value());
  EXPECT_EQ(r.bath->relaxation_time_s, gas::steady_state({theory, bath}).relaxation_time_s);
  EXPECT_GT(r.bath->relaxation_time_s, 0.0);
  EXPECT_EQ(r.bath->temperature_j, 1e-3);
  EXPECT_EQ(r.bath->seed, 7U);
  bath.kind = gas::ThermostatKind::white_noise;
  bath.power_w = 1e-3;
  EXPECT_THROW(issue_request(bath), InvalidInput);
}

TEST(GasDeckRequest, OnlyViscoelasticHertz) {
  EXPECT_NO_THROW(gd::require_deck_law("viscoelastic-hertz"));
  EXPECT_THROW(gd::require_deck_law("tsuji-hertz"), InvalidInput);
}

class ComparedLogs : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ =
        std::filesystem::temp_directory_path() /
        ("restitution-compared-logs-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
         "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(folder_);
  }
  void TearDown() override { std::filesystem::remove_all(folder_); }

  // A constant-eps run of `setup`'s gas cooling by Haff's law at `factor` of Enskog's rate, its last line
  // cut.
  std::string haff_log(const std::string& name, gd::GasLogSetup line, double factor) const {
    const gd::GasSetup setup = gd::gas_setup(issue_request());
    gas::CoolingRequest haff;
    haff.particles = setup.particles;
    haff.law = gas::constant_eps_law(setup.constant_eps);
    haff.initial_temperature_j = setup.log.initial_temperature_j;
    const double tau0 = gas::haff_reference(haff).tau0_s, t0 = haff.initial_temperature_j;
    line.law = "constant-eps";
    const std::filesystem::path path = folder_ / name;
    std::ofstream log(path);
    log.precision(17);
    log << "LAMMPS (29 Sep 2021)\n" << gd::gas_log_setup_line(line) << "\n";
    for (int i = 0; i <= 30; ++i) {
      const double t = i == 0 ? 0.0 : 0.1 * tau0 * std::pow(10.0, (i - 1) / 10.0);
      log << gd::kGasTag << " law=constant-eps time_s=" << t
          << " temperature_j=" << t0 / std::pow(1.0 + factor * t / tau0, 2) << " timestep_s=5e-06 step=" << i
          << "\n";
    }
    log << gd::kGasTag << " law=constant-eps time_s=";  // cut by the end of the run
    return path.string();
  }

  std::filesystem::path folder_;
};

TEST_F(ComparedLogs, RecoverTheCollisionRateFactor) {
  const gd::GasSetup setup = gd::gas_setup(issue_request());
  std::vector<std::string> notes;
  const gd::GasComparison c = gd::compare_logs({haff_log("haff.log", setup.log, 0.9)}, setup,
                                               [&](const std::string& n) { notes.push_back(n); });
  EXPECT_TRUE(c.collision_rate_factor_measured);
  EXPECT_NEAR(c.collision_rate_factor, 0.9, 1e-6);
  ASSERT_EQ(c.runs.size(), 1U);
  EXPECT_LT(c.runs[0].max_relative_deviation, 1e-6);
  EXPECT_EQ(notes.size(), 1U);  // the cut line
}

TEST_F(ComparedLogs, NotesComeBeforeALaterLogsError) {
  const gd::GasSetup setup = gd::gas_setup(issue_request());
  gd::GasLogSetup other = setup.log;
  other.packing_fraction = 0.2;
  const std::vector<std::string> logs{haff_log("a.log", setup.log, 0.9), haff_log("b.log", other, 0.9)};
  std::vector<std::string> notes;
  EXPECT_THROW(gd::compare_logs(logs, setup, [&](const std::string& n) { notes.push_back(n); }),
               InvalidInput);
  EXPECT_EQ(notes.size(), 2U);  // a.log's, then b.log's before its setup is checked
}

TEST_F(ComparedLogs, ALogWithoutTheDecksLinesIsRefused) {
  const gd::GasSetup setup = gd::gas_setup(issue_request());
  const std::filesystem::path empty = folder_ / "empty.log";
  std::ofstream(empty) << "LAMMPS (29 Sep 2021)\n";
  try {
    gd::compare_logs({empty.string()}, setup, [](const std::string&) {});
    FAIL() << "no lines, no comparison";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("no restitution-gas lines"), std::string::npos) << e.what();
  }
  EXPECT_THROW(gd::compare_logs({(folder_ / "missing.log").string()}, setup, [](const std::string&) {}),
               InvalidInput);
}

}  // namespace
