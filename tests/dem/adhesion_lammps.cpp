// SPDX-License-Identifier: BSD-3-Clause
// `restitution dem --code lammps --adhesion jkr|dmt` against Debian's LAMMPS 20220106 run as a user runs it:
// the printed lines, two spheres per listed speed (0.97 ... 100 v_s), with and without damping, two
// materials. ε within 1e-5 of what `dem` printed at its time step, the outcome (stuck or bounced) right at
// 0.97 and 1.03 v_s, and the O(dt) convergence: the error at 4 dt is larger than at dt (docs/adhesion.md §9).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "cli_runner.hpp"
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

// One pair per speed, 20 radii apart in y; each starts a thousandth of a radius from touching and prints
// "PAIR i eps gap" (gap: centre distance − 2R, negative while in contact).
std::string deck_of(const json& dem, const Case& c, double timestep_s) {
  std::string d = "atom_modify map array sort 0 0.0\nboundary f f f\n";
  const auto& speeds = dem.at("speeds");
  const std::size_t n = speeds.size();
  const double spacing = 20.0 * c.radius, gap = 1e-3 * c.radius;
  char b[512];
  for (std::size_t i = 0; i < 3; ++i)
    d += dem.at("lines").at(i).get<std::string>() + "\n";  // units, atom_style, comm_modify
  std::snprintf(b, sizeof b,
                "region box block %.17g %.17g %.17g %.17g %.17g %.17g units box\ncreate_box 1 box\n",
                -spacing, spacing, -spacing, spacing * static_cast<double>(n), -spacing, spacing);
  d += b;
  double longest = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double v = speeds[i].at("velocity_m_per_s").get<double>();
    const double y = spacing * static_cast<double>(i);
    std::snprintf(
        b, sizeof b,
        "create_atoms 1 single %.17g %.17g 0 units box\ncreate_atoms 1 single %.17g %.17g 0 units box\n",
        -c.radius - gap / 2, y, c.radius + gap / 2, y);
    d += b;
    longest = std::max(longest, gap / v + 3.0 * speeds[i].at("contact_time_s").get<double>());
  }
  std::snprintf(b, sizeof b, "set group all diameter %.17g\nset group all density %.17g\n", 2 * c.radius,
                c.density);
  d += b;
  for (std::size_t i = 0; i < n; ++i) {
    const double v = speeds[i].at("velocity_m_per_s").get<double>();
    std::snprintf(b, sizeof b, "set atom %zu vx %.17g\nset atom %zu vx %.17g\n", 2 * i + 1, 0.5 * v,
                  2 * i + 2, -0.5 * v);
    d += b;
  }
  for (std::size_t i = 3; i < dem.at("lines").size(); ++i) {
    const std::string line = dem.at("lines").at(i).get<std::string>();
    if (line.rfind("timestep", 0) == 0) continue;
    d += line + "\n";
  }
  std::snprintf(b, sizeof b, "timestep %.17g\nthermo 0\nrun %ld\n", timestep_s,
                static_cast<long>(std::ceil(longest / timestep_s)));
  d += b;
  for (std::size_t i = 0; i < n; ++i) {
    const double v = speeds[i].at("velocity_m_per_s").get<double>();
    std::snprintf(b, sizeof b, "print \"PAIR %zu $((vx[%zu]-vx[%zu])/%.17g) $(x[%zu]-x[%zu]-%.17g)\"\n", i,
                  2 * i + 2, 2 * i + 1, v, 2 * i + 2, 2 * i + 1, 2 * c.radius);
    d += b;
  }
  return d;
}

restitution::dem::TaggedEps run_lammps(const std::string& deck, std::size_t n) {
  const std::string program = restitution::dem::dem_program(restitution::dem::Code::lammps);
  const auto run = restitution::dem::output_with_input_file(deck, ".in", [&](const std::string& path) {
    return std::vector<std::string>{program, "-log", "none", "-echo", "none", "-in", path};
  });
  const auto read = restitution::dem::tagged_eps(run.output, "PAIR", n);
  const std::string failure = restitution::dem::code_run_failure(run, program, read);
  EXPECT_TRUE(failure.empty()) << failure << "\n"
                               << run.output.substr(run.output.size() > 2000 ? run.output.size() - 2000 : 0);
  return read;
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

TEST_P(AdhesionLammps, PrintedLinesGiveThePrintedEps) {
  ASSERT_FALSE(restitution::dem::dem_program(restitution::dem::Code::lammps).empty())
      << "lmp not found on PATH: scripts/setup installs Debian's lammps";
  const Case& c = GetParam();
  const json dem = run_json(command_of(c));
  const double dt = dem.at("timestep_s").get<double>();
  const auto& speeds = dem.at("speeds");
  const auto measured = run_lammps(deck_of(dem, c, dt), speeds.size());
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    const double v = speeds[i].at("velocity_m_per_s").get<double>();
    const bool stuck = speeds[i].at("outcome") == "stuck";
    // Stuck: the spheres are still within the pull-off distance at the end; bounced: apart and receding.
    EXPECT_EQ(measured.gap_m[i] <= -dem.at("break_overlap_m").get<double>(), stuck) << "v " << v;
    if (stuck) continue;
    EXPECT_NEAR(measured.eps[i], speeds[i].at("eps").get<double>(), 1e-5) << c.name << " v " << v;
  }
}

TEST_P(AdhesionLammps, ErrorShrinksWithTheTimeStep) {
  const Case& c = GetParam();
  const json dem = run_json(command_of(c));
  const double dt = dem.at("timestep_s").get<double>();
  const auto& speeds = dem.at("speeds");
  double worst_fine = 0.0, worst_coarse = 0.0;
  const auto fine = run_lammps(deck_of(dem, c, dt), speeds.size());
  const auto coarse = run_lammps(deck_of(dem, c, 16.0 * dt), speeds.size());
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    if (speeds[i].at("outcome") == "stuck") continue;
    const double eps = speeds[i].at("eps").get<double>();
    worst_fine = std::max(worst_fine, std::abs(fine.eps[i] - eps));
    worst_coarse = std::max(worst_coarse, std::abs(coarse.eps[i] - eps));
  }
  RecordProperty("worst_eps_error_at_dt", std::to_string(worst_fine));
  RecordProperty("worst_eps_error_at_16dt", std::to_string(worst_coarse));
  EXPECT_GT(worst_coarse, worst_fine) << c.name;
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
