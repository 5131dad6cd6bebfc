// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The deck the adhesive-pair tests run: the check deck of the printed lines of `dem --adhesion ... --json`,
// one pair per listed speed, run by the code as a user runs it (LAMMPS's lmp or LIGGGHTS's liggghts).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "dem/adhesive_check_deck.hpp"
#include "dem/code_runner.hpp"
#include "dem/process_output.hpp"

namespace adhesive_pair_test {

using nlohmann::json;

// The library's check deck (dem/adhesive_check_deck.hpp) of what `dem --adhesion ... --json` printed, at a
// chosen time step: one pair per speed, printing "PAIR i eps gap".
inline std::string deck_of(const json& dem, double radius, double density, double timestep_s) {
  restitution::dem::AdhesiveDeckRequest r;
  r.liggghts = dem.at("code") == "liggghts";
  for (const auto& line : dem.at("lines")) r.lines.push_back(line.get<std::string>());
  r.radius_m = radius;
  r.density_kg_per_m3 = density;
  r.timestep_s = timestep_s;
  for (const auto& s : dem.at("speeds")) {
    r.speeds_m_per_s.push_back(s.at("velocity_m_per_s").get<double>());
    restitution::AdhesiveCollision c;
    c.outcome = s.at("outcome") == "stuck" ? restitution::AdhesiveOutcome::stuck
                                           : restitution::AdhesiveOutcome::bounced;
    c.eps = s.at("eps").get<double>();
    c.contact_time_s = s.at("contact_time_s").get<double>();
    r.collisions.push_back(c);
  }
  return restitution::dem::adhesive_check_deck(r);
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

// Runs `restitution COMMAND --json --deck FILE`, then the code on FILE as written: the outcome at every speed
// and ε within 1e-5 at every bounce, against what the command printed.
template <typename RunJson>
void expect_written_deck_agrees(restitution::dem::Code code, const std::string& command,
                                const std::string& name, RunJson run_json) {
  const auto path = std::filesystem::temp_directory_path() / ("restitution_adhesive_deck_" + name + ".in");
  const json dem = run_json(command + " --deck " + path.string());
  std::ifstream in(path);
  ASSERT_TRUE(in) << "no deck at " << path;
  const std::string deck((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(deck.find("print \"EXPECT 0 "), std::string::npos);
  const auto& speeds = dem.at("speeds");
  const auto measured = run_code(code, deck, speeds.size());
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    const bool stuck = speeds[i].at("outcome") == "stuck";
    EXPECT_EQ(measured.gap_m[i] <= -dem.at("break_overlap_m").get<double>(), stuck) << name << " speed " << i;
    if (!stuck)
      EXPECT_NEAR(measured.eps[i], speeds[i].at("eps").get<double>(), 1e-5) << name << " speed " << i;
  }
  std::filesystem::remove(path);
}

}  // namespace adhesive_pair_test
