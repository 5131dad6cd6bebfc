// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The deck the adhesive-pair tests run: the printed lines of `dem --adhesion ... --json`, one pair per listed
// speed, run by the code as a user runs it (LAMMPS's lmp or LIGGGHTS's liggghts).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "dem/code_runner.hpp"
#include "dem/process_output.hpp"

namespace adhesive_pair_test {

using nlohmann::json;

// One pair per speed, 20 radii apart in y; each starts a thousandth of a radius from touching and prints
// "PAIR i eps gap" (gap: centre distance − 2R, negative while in contact).
inline std::string deck_of(const json& dem, double radius, double density, double timestep_s) {
  std::string d = "atom_modify map array sort 0 0.0\nboundary f f f\n";
  const auto& speeds = dem.at("speeds");
  const std::size_t n = speeds.size();
  const double spacing = 20.0 * radius, gap = 1e-3 * radius;
  char b[512];
  // The prerequisites (units, atom_style, comm_modify; LIGGGHTS: newton, communicate) come before the box.
  const std::size_t before_box = dem.at("code") == "liggghts" ? 4 : 3;
  for (std::size_t i = 0; i < before_box; ++i) d += dem.at("lines").at(i).get<std::string>() + "\n";
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
        -radius - gap / 2, y, radius + gap / 2, y);
    d += b;
    longest = std::max(longest, gap / v + 3.0 * speeds[i].at("contact_time_s").get<double>());
  }
  std::snprintf(b, sizeof b, "set group all diameter %.17g\nset group all density %.17g\n", 2 * radius,
                density);
  d += b;
  for (std::size_t i = 0; i < n; ++i) {
    const double v = speeds[i].at("velocity_m_per_s").get<double>();
    std::snprintf(b, sizeof b, "set atom %zu vx %.17g\nset atom %zu vx %.17g\n", 2 * i + 1, 0.5 * v,
                  2 * i + 2, -0.5 * v);
    d += b;
  }
  for (std::size_t i = before_box; i < dem.at("lines").size(); ++i) {
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
                  2 * i + 2, 2 * i + 1, v, 2 * i + 2, 2 * i + 1, 2 * radius);
    d += b;
  }
  return d;
}

inline restitution::dem::TaggedEps run_code(restitution::dem::Code code, const std::string& deck,
                                            std::size_t n) {
  const std::string program = restitution::dem::dem_program(code);
  const auto run = restitution::dem::output_with_input_file(deck, ".in", [&](const std::string& path) {
    return std::vector<std::string>{program, "-log", "none", "-echo", "none", "-in", path};
  });
  const auto read = restitution::dem::tagged_eps(run.output, "PAIR", n);
  const std::string failure = restitution::dem::code_run_failure(run, program, read);
  EXPECT_TRUE(failure.empty()) << failure << "\n"
                               << run.output.substr(run.output.size() > 2000 ? run.output.size() - 2000 : 0);
  return read;
}

}  // namespace adhesive_pair_test
