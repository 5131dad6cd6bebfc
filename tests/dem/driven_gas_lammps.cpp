// SPDX-License-Identifier: BSD-3-Clause
// Issue 49's must-show for the driven deck (docs/gas.md, "The driven deck"), as a user runs it: `gas --deck`
// with a Langevin bath, the two inputs run unchanged by Debian's LAMMPS side by side (N = 2000, phi = 0.1,
// issue 35's material, T_b = 0.07 J, tau_b = 2 s: the cheapest of the docs' three drivings, 1e5 steps), and
// `gas --compare`: the viscoelastic steady temperature within 3 % of the theory at the collision-rate factor
// of the companion, the factor within 10 % of 1, and the relaxation within 10 % of the theory's T(t) (single
// samples of T fluctuate by about sqrt(2/(3N)) = 1.8 %).
#include <gtest/gtest.h>

#include <future>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.hpp"
#include "dem/code_runner.hpp"
#include "dem/gas_deck_runs.hpp"

namespace {

const std::string kGas =
    "gas --radius 0.005 --density 920 --young-modulus 1e8 --poisson-ratio 0.4 --eps 0.8 --velocity 2 "
    "--packing-fraction 0.1 --rms-speed 1 --duration 0.435 --thermostat langevin --bath-temperature 7e-2 "
    "--bath-time 2";

using restitution::test_support::timed_run;
using restitution::test_support::TimedRun;

TEST(DrivenGasLammps, SteadyTemperatureAsTheTheorySays) {
  ASSERT_FALSE(restitution::dem::dem_program(restitution::dem::Code::lammps).empty())
      << "lmp not found on PATH: scripts/setup installs Debian's lammps";
  const restitution::test_support::TempFolder folder;
  const std::string deck = (folder.path / "driven.in").string();
  const auto written = restitution::test_support::run_cli(kGas + " --deck " + deck);
  ASSERT_EQ(written.status, 0) << written.err;
  const std::string in = "cd " + folder.path.string() + " && ";
  auto law = std::async(std::launch::async,
                        [&] { return timed_run(in + "lmp -in driven.in -log driven.log -screen none"); });
  auto companion = std::async(std::launch::async, [&] {
    return timed_run(in + "lmp -in driven_constant_eps.in -log driven_constant_eps.log -screen none");
  });
  const TimedRun serial = law.get();
  const TimedRun constant = companion.get();
  const auto compared =
      restitution::test_support::run_cli(kGas + " --json --compare " + (folder.path / "driven.log").string() +
                                         " " + (folder.path / "driven_constant_eps.log").string());
  ASSERT_EQ(compared.status, 0) << compared.err;
  const auto c = nlohmann::json::parse(compared.out).at("driven_comparison");
  const double factor = c.at("collision_rate_factor").get<double>();
  std::cout << "collision-rate factor " << factor << "; wall " << serial.wall_s << " s and "
            << constant.wall_s << " s side by side\n";
  for (const auto& run : c.at("runs")) {
    const double measured = run.at("steady_temperature_j").get<double>();
    const double theory = run.at("theory_steady_temperature_j").get<double>();
    std::cout << run.at("law").get<std::string>() << ": T_s " << measured << " +- "
              << run.at("steady_temperature_error_j").get<double>() << " J (theory " << theory << "), a2 "
              << run.at("steady_a2").get<double>() << " +- " << run.at("steady_a2_error").get<double>()
              << " (theory " << run.at("theory_steady_a2").get<double>() << "), relaxation max deviation "
              << run.at("relaxation_max_deviation").get<double>() << "\n";
    EXPECT_NEAR(measured / theory, 1.0, 0.03) << run.at("law");
    EXPECT_LT(run.at("relaxation_max_deviation").get<double>(), 0.1) << run.at("law");
  }
  EXPECT_NEAR(factor, 1.0, 0.1);
}

}  // namespace
