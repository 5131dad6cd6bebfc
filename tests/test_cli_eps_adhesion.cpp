// SPDX-License-Identifier: BSD-3-Clause
// End-to-end: `restitution eps --adhesion` (JSON members equal to the library's doubles, stuck below v_s,
// named refusals).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "restitution/adhesion.hpp"

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
  };
  for (const auto& [command, word] : cases) {
    const auto outcome = run_cli(command);
    EXPECT_EQ(outcome.status, 2) << command << "\n" << outcome.err;
    EXPECT_NE(outcome.err.find(word), std::string::npos) << command << "\n" << outcome.err;
  }
}

}  // namespace
}  // namespace restitution
