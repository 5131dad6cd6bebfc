// SPDX-License-Identifier: BSD-3-Clause
// End-to-end: `restitution eps --adhesion` (JSON members equal to the library's doubles, stuck below v_s,
// named refusals).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "restitution/adhesion.hpp"
#include "restitution/adhesive_calibration.hpp"

namespace restitution {
namespace {

using nlohmann::json;
using test_support::run_cli;

const char* const kIce = " --young-modulus 7e9 --poisson-ratio 0.25 --radius 1.5e-6 --density 920 ";

TEST(CliEpsAdhesion, JsonIsTheLibrarysResult) {
  for (const char* model : {"jkr", "jkr-lammps", "dmt"}) {
    const auto outcome = run_cli(std::string("eps --adhesion ") + model + " --surface-energy 0.19" + kIce +
                                 "--dissipative-constant 2e-9 --velocity 3 --json");
    ASSERT_EQ(outcome.status, 0) << outcome.err;
    const json j = json::parse(outcome.out);
    EXPECT_EQ(j["adhesion"], model);
    AdhesiveContact c{
        adhesive_model_from_name(model),
        j["effective_modulus_pa"].get<double>(),
        j["effective_radius_m"].get<double>(),
        j["effective_mass_kg"].get<double>(),
        0.19,
        j[std::string(model) == "jkr" ? "dissipative_constant_s" : "lammps_damping_per_m_s"].get<double>()};
    const auto r = solve_adhesive(c, 3.0);
    EXPECT_EQ(j["outcome"], adhesive_outcome_name(r.outcome));
    EXPECT_EQ(j["eps"].get<double>(), r.eps);
    EXPECT_EQ(j["one_minus_eps"].get<double>(), r.one_minus_eps);
    EXPECT_EQ(j["sticking_speed_m_per_s"].get<double>(), sticking_speed(c).speed_m_per_s);
    for (const char* member :
         {"contact_time_s", "max_compression_m", "hysteresis_work_j", "viscous_work_j",
          "kinetic_to_adhesion_energy", "break_overlap_m", "elastic_hysteresis_work_j"}) {
      EXPECT_TRUE(j[member].is_number()) << member;
    }
  }
}

TEST(CliEpsAdhesion, StuckBelowTheStickingSpeedIsAResult) {
  const auto outcome =
      run_cli(std::string("eps --adhesion jkr --surface-energy 0.19") + kIce + "--velocity 1 --json");
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  const json j = json::parse(outcome.out);
  EXPECT_EQ(j["outcome"], "stuck");
  EXPECT_EQ(j["eps"].get<double>(), 0.0);
  EXPECT_GT(j["sticking_speed_m_per_s"].get<double>(), 1.0);
}

TEST(CliEpsAdhesion, CalibrateFromTheStickingSpeedIsTheLibrarys) {
  const auto outcome = run_cli(std::string("calibrate --adhesion jkr-lammps --eps 0.5 --velocity 3 ") +
                               "--sticking-speed 1.5 --json" + kIce);
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  const json j = json::parse(outcome.out);
  Material ice;
  ice.young_modulus_pa = 7e9;
  ice.poisson_ratio = 0.25;
  ice.radius1_m = ice.radius2_m = 1.5e-6;
  ice.density_kg_m3 = 920.0;
  const auto c = calibrate_adhesive_sticking(AdhesiveModel::jkr_lammps, ice, 0.5, 3.0, 1.5);
  EXPECT_EQ(j["surface_energy_j_per_m2"].get<double>(), c.surface_energy_j_per_m2);
  EXPECT_EQ(j["dissipative_constant_s"].get<double>(), c.dissipative_constant_s);
  EXPECT_EQ(j["lammps_damping_per_m_s"].get<double>(), c.contact.damping);
  EXPECT_EQ(j["eps_at_velocity"].get<double>(), c.eps_at_velocity);
  EXPECT_EQ(j["sticking_speed_resolved_m_per_s"].get<double>(), c.sticking_speed_m_per_s);
  EXPECT_EQ(j["undamped_eps"].get<double>(), c.undamped_eps);
  EXPECT_EQ(j["solves"].get<int>(), c.solves);
  EXPECT_NEAR(c.eps_at_velocity, 0.5, 1e-9);
  EXPECT_NEAR(c.sticking_speed_m_per_s, 1.5, 1.5e-9);
}

TEST(CliEpsAdhesion, RefusalsNameTheProblem) {
  const std::pair<std::string, std::string> cases[] = {
      {std::string("eps --adhesion jkr") + kIce, "--surface-energy"},
      {std::string("eps --adhesion jkr --surface-energy -0.1") + kIce, "surface energy"},
      {std::string("eps --adhesion jkr --surface-energy 0") + kIce, "non-adhesive"},
      {std::string("eps --adhesion jkr --surface-energy 0.19 --zeta 1") + kIce, "--zeta"},
      {std::string("eps --adhesion jkr --surface-energy 0.19 --young-modulus 7e9"), "--poisson-ratio"},
      {std::string("eps --surface-energy 0.19 --zeta 1"), "--adhesion"},
      {std::string("eps --adhesion jkr --surface-energy 0.19 --dissipative-constant -1") + kIce,
       "--dissipative-constant"},
      {std::string("calibrate --adhesion sjkr --cohesion-energy-density 1e5 --eps 0.6 --velocity 0.1") + kIce,
       "sjkr (--cohesion-energy-density) is not calibrated yet"},
      {std::string("calibrate --adhesion jkr --eps 0.5 --velocity 2 --sticking-speed 2") + kIce,
       "not below the impact speed"},
      {std::string("calibrate --adhesion jkr --eps 0.9 --velocity 2 --sticking-speed 1") + kIce,
       "damping only lowers eps"},
      {std::string(
           "calibrate --adhesion jkr --eps 0.5 --velocity 2 --sticking-speed 1 --surface-energy 0.1") +
           kIce,
       "exclude each other"},
      {std::string("calibrate --eps 0.5 --velocity 2 --sticking-speed 1") + kIce, "--adhesion MODEL"},
  };
  for (const auto& [command, word] : cases) {
    const auto outcome = run_cli(command);
    EXPECT_EQ(outcome.status, 2) << command << "\n" << outcome.err;
    EXPECT_NE(outcome.err.find(word), std::string::npos) << command << "\n" << outcome.err;
  }
}

}  // namespace
}  // namespace restitution
