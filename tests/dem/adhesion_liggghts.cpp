// SPDX-License-Identifier: BSD-3-Clause
// `restitution dem --code liggghts --adhesion sjkr` against Debian's LIGGGHTS 3.8.0 run as a user runs it:
// the printed lines, two spheres per listed speed (0.97 ... 100 v_s). ε within 1e-5 of what `dem` printed
// at its time step, the outcome (stuck or bounced) right at 0.97 and 1.03 v_s (docs/adhesion.md §10).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "cli_runner.hpp"
#include "dem/adhesive_pair_deck.hpp"
#include "dem/steel_beads.hpp"

namespace {

using nlohmann::json;
using restitution::test_support::run_json;

struct Case {
  const char* name;
  double young, poisson, radius, density, cohesion_energy_density, dissipative_constant;
};

std::string command_of(const Case& c) {
  char b[512];
  std::snprintf(b, sizeof b,
                "dem --code liggghts --adhesion sjkr --cohesion-energy-density %.17g --young-modulus %.17g "
                "--poisson-ratio %.17g --radius %.17g --density %.17g --dissipative-constant %.17g --json",
                c.cohesion_energy_density, c.young, c.poisson, c.radius, c.density, c.dissipative_constant);
  return b;
}

class AdhesionLiggghts : public testing::TestWithParam<Case> {};

TEST_P(AdhesionLiggghts, PrintedLinesGiveThePrintedEps) {
  ASSERT_FALSE(restitution::dem::dem_program(restitution::dem::Code::liggghts).empty())
      << "liggghts not found on PATH: scripts/setup installs Debian's liggghts";
  const Case& c = GetParam();
  const json dem = run_json(command_of(c));
  const auto& speeds = dem.at("speeds");
  const auto measured = adhesive_pair_test::run_code(
      restitution::dem::Code::liggghts,
      adhesive_pair_test::deck_of(dem, c.radius, c.density, dem.at("timestep_s").get<double>()),
      speeds.size());
  ASSERT_EQ(speeds.at(0).at("outcome"), "stuck");    // 0.97 v_s
  ASSERT_EQ(speeds.at(1).at("outcome"), "bounced");  // 1.03 v_s
  double worst = 0.0;
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    const double v = speeds[i].at("velocity_m_per_s").get<double>();
    const bool stuck = speeds[i].at("outcome") == "stuck";
    // Stuck: the spheres still overlap at the end; bounced: apart and receding.
    EXPECT_EQ(measured.gap_m[i] <= 0.0, stuck) << c.name << " v " << v;
    if (stuck) continue;
    EXPECT_NEAR(measured.eps[i], speeds[i].at("eps").get<double>(), 1e-5) << c.name << " v " << v;
    worst = std::max(worst, std::abs(measured.eps[i] - speeds[i].at("eps").get<double>()));
  }
  char worst_text[32];
  std::snprintf(worst_text, sizeof worst_text, "%.3e", worst);
  RecordProperty("worst_eps_error", worst_text);
}

TEST_P(AdhesionLiggghts, WrittenCheckDeckAgrees) {
  adhesive_pair_test::expect_written_deck_agrees(restitution::dem::Code::liggghts, command_of(GetParam()),
                                                 GetParam().name, run_json);
}

// mm spheres soft enough for the cohesion to matter (Y = 5 MPa, as in LIGGGHTS's own examples; the overlap
// reaches a few % of R, where the exact intersection area differs from 2πRδ), and two damping levels.
INSTANTIATE_TEST_SUITE_P(Pairs, AdhesionLiggghts,
                         testing::Values(Case{"soft_mm_light_damping", 5e6, 0.45, 1e-3, 2500.0, 1e5, 1e-6},
                                         Case{"soft_mm_strong_damping", 5e6, 0.45, 1e-3, 2500.0, 1e5, 1e-5}),
                         [](const testing::TestParamInfo<Case>& info) {
                           return std::string(info.param.name);
                         });

}  // namespace
