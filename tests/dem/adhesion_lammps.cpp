// SPDX-License-Identifier: BSD-3-Clause
// `restitution dem --code lammps --adhesion jkr|dmt` against Debian's LAMMPS 20220106 run as a user runs it:
// the printed lines, two spheres per listed speed (0.97 ... 100 v_s), with and without damping, two
// materials. ε within 1e-5 of what `dem` printed at its time step, the outcome (stuck or bounced) right at
// 0.97 and 1.03 v_s, and the O(dt) convergence: the error at 16 dt is larger than at dt (docs/adhesion.md
// §9).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "dem/adhesive_pair_deck.hpp"
#include "dem/code_runner.hpp"
#include "dem/process_output.hpp"
#include "dem/steel_beads.hpp"

namespace {

using nlohmann::json;
using restitution::test_support::run_json;

struct Case {
  const char* name;
  const char* model;
  double young, poisson, radius, density, gamma, dissipative_constant;
  std::string speeds;  // --impact-velocity, or "" for the default multiples of v_s
};

using adhesive_pair_test::deck_of;

restitution::dem::TaggedEps run_lammps(const std::string& deck, std::size_t n) {
  return adhesive_pair_test::run_code(restitution::dem::Code::lammps, deck, n);
}

std::string command_of(const Case& c) {
  char b[512];
  std::snprintf(
      b, sizeof b,
      "dem --code lammps --adhesion %s --surface-energy %.17g --young-modulus %.17g --poisson-ratio %.17g "
      "--radius %.17g --density %.17g --dissipative-constant %.17g --json",
      c.model, c.gamma, c.young, c.poisson, c.radius, c.density, c.dissipative_constant);
  return std::string(b) + (c.speeds.empty() ? "" : " --impact-velocity " + c.speeds);
}

class AdhesionLammps : public testing::TestWithParam<Case> {};

// One test per case: the printed deck's run is the expensive part, so the O(dt) check reuses it and adds
// only the coarse run (1/16 of the steps).
TEST_P(AdhesionLammps, PrintedLinesGiveThePrintedEpsAndTheErrorShrinksWithTheTimeStep) {
  ASSERT_FALSE(restitution::dem::dem_program(restitution::dem::Code::lammps).empty())
      << "lmp not found on PATH: scripts/setup installs Debian's lammps";
  const Case& c = GetParam();
  const json dem = run_json(command_of(c));
  const double dt = dem.at("timestep_s").get<double>();
  const auto& speeds = dem.at("speeds");
  const auto measured = run_lammps(deck_of(dem, c.radius, c.density, dt), speeds.size());
  const auto coarse = run_lammps(deck_of(dem, c.radius, c.density, 16.0 * dt), speeds.size());
  double worst_fine = 0.0, worst_coarse = 0.0;
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    const double v = speeds[i].at("velocity_m_per_s").get<double>();
    const bool stuck = speeds[i].at("outcome") == "stuck";
    // Stuck: the spheres are still within the pull-off distance at the end; bounced: apart and receding.
    EXPECT_EQ(measured.gap_m[i] <= -dem.at("break_overlap_m").get<double>(), stuck) << "v " << v;
    if (stuck) continue;
    const double eps = speeds[i].at("eps").get<double>();
    EXPECT_NEAR(measured.eps[i], eps, 1e-5) << c.name << " v " << v;
    worst_fine = std::max(worst_fine, std::abs(measured.eps[i] - eps));
    worst_coarse = std::max(worst_coarse, std::abs(coarse.eps[i] - eps));
  }
  RecordProperty("worst_eps_error_at_dt", std::to_string(worst_fine));
  RecordProperty("worst_eps_error_at_16dt", std::to_string(worst_coarse));
  EXPECT_GT(worst_coarse, worst_fine) << c.name;
}

TEST(AdhesionLammpsDeck, WrittenCheckDeckAgrees) {
  const Case c{"ice_dmt_damped_deck", "dmt", 7e9, 0.25, 1.5e-6, 920.0, 0.19, 1e-9, ""};
  adhesive_pair_test::expect_written_deck_agrees(restitution::dem::Code::lammps, command_of(c), c.name,
                                                 run_json);
}

// µm ice (docs/adhesion.md §7) and 10 µm silica-like spheres (Y = 70 GPa, ν = 0.17, ρ = 2600, γ = 0.025).
INSTANTIATE_TEST_SUITE_P(
    Pairs, AdhesionLammps,
    testing::Values(Case{"ice_jkr_elastic", "jkr", 7e9, 0.25, 1.5e-6, 920.0, 0.19, 0.0, ""},
                    Case{"ice_jkr_damped", "jkr", 7e9, 0.25, 1.5e-6, 920.0, 0.19, 1e-9, ""},
                    Case{"ice_dmt_damped", "dmt", 7e9, 0.25, 1.5e-6, 920.0, 0.19, 1e-9, ""},
                    Case{"silica_jkr_damped", "jkr", 7e10, 0.17, 1e-5, 2600.0, 0.025, 2e-10, ""}),
    [](const testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

}  // namespace
