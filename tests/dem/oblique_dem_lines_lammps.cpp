// SPDX-License-Identifier: BSD-3-Clause
// The oblique outputs of `restitution dem --code lammps --friction 0.3` (src/dem/oblique_lines.cpp, worded by
// src/cli/dem/dem_oblique.cpp) are what Debian's LAMMPS gives with the printed lines pasted unchanged: two 1
// mm steel spheres under `pair granular` and a sphere on `fix wall/gran granular`, at the six listed angles,
// with the lines as printed (mindlin NULL) and with the line --target-et prints (a numeric k_t). At the
// printed timestep (the steps per contact for e_t within 1e-4) LAMMPS's e_t is within 1e-4 of the printed
// one; at a tenth of it, Richardson-extrapolated, within 1e-5, and so are the rebound angle (degrees,
// relative 1e-4) and the spin. The same for the line `--tangential linear_history` prints and its --target-et
// line.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "dem/code_runner.hpp"
#include "dem/oblique_runs.hpp"

namespace {

using restitution::test_support::run_cli;
using restitution::test_support::slurp;
using restitution::test_support::TempFolder;

constexpr double kRadius = 1e-3;
const std::string kSteel =
    "dem --code lammps --young-modulus 2e11 --poisson-ratio 0.3 --radius 1e-3 --density 7800 --eps 0.9 "
    "--velocity 1 --friction 0.3 --json";

using Outcome = restitution::test_support::ObliqueOutcome;  // spin2 unused

// One collision per angle, 10 mm apart: a pair (atom 2k+2 onto 2k+1 at rest) or a sphere onto the wall at
// z = 0. Our spin is -omega_y (LAMMPS's slip is vx - R omega_y per sphere, n = +z towards the mover).
std::vector<Outcome> run_lammps(const nlohmann::json& out, bool wall, const std::vector<std::string>& lines,
                                double dt, double run_time) {
  const auto& impacts = out["oblique"]["impacts"];
  const double speed = out["oblique"]["speed_m_s"].get<double>();
  const std::size_t n = impacts.size();
  const std::size_t per_angle = wall ? 1 : 2;
  TempFolder folder;
  std::ostringstream deck;
  deck.precision(17);
  for (const auto& p : out["prerequisites"]) deck << p.get<std::string>() << "\n";
  deck << "atom_modify map array\nboundary f f f\nregion box block -0.05 0.05 -0.01 0.01 -0.01 0.01\n"
       << "create_box 1 box\n";
  for (std::size_t i = 0; i < n; ++i) {
    const double x = -0.04 + 0.01 * static_cast<double>(i);
    if (!wall) deck << "create_atoms 1 single " << x << " 0 0\n";
    deck << "create_atoms 1 single " << x << " 0 " << (wall ? kRadius : 2.0 * kRadius) << "\n";
  }
  deck << "set type 1 diameter " << 2.0 * kRadius << " density 7800\n";
  for (std::size_t i = 0; i < n; ++i) {
    const double a = impacts[i]["angle_deg"].get<double>() * std::numbers::pi / 180.0;
    deck << "set atom " << per_angle * (i + 1) << " vx " << speed * std::sin(a) << " vy 0 vz "
         << -speed * std::cos(a) << "\n";
  }
  for (const auto& line : lines) deck << line << "\n";
  if (!wall) deck << "neighbor " << 0.1 * kRadius << " bin\nneigh_modify every 1 delay 0 check no\n";
  const auto steps = static_cast<long>(std::ceil(run_time / dt));
  deck << "fix 1 all nve/sphere\ntimestep " << dt << "\nthermo " << steps << "\n"
       << "dump d all custom " << steps << " " << (folder.path / "out.dump").string() << " id vx vz omegay\n"
       << "dump_modify d sort id format float %.17g\nrun " << steps << "\n";
  std::ofstream(folder.path / "in.lmp") << deck.str();
  const std::string program = restitution::dem::dem_program(restitution::dem::Code::lammps);
  const std::string command = program + " -log none -in " + (folder.path / "in.lmp").string() + " > " +
                              (folder.path / "out.txt").string() + " 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << command << "\n" << slurp((folder.path / "out.txt").string());
  std::istringstream dump(slurp((folder.path / "out.dump").string()));
  std::vector<std::string> rows;
  for (std::string row; std::getline(dump, row);) rows.push_back(row);
  const std::size_t atoms = per_angle * n;
  std::vector<std::array<double, 3>> v(atoms);  // vx, vz, omega_y by id - 1
  for (std::size_t k = rows.size() - atoms; k < rows.size(); ++k) {
    std::istringstream row(rows.at(k));
    long id = 0;
    std::array<double, 3> values{};
    row >> id >> values[0] >> values[1] >> values[2];
    v.at(static_cast<std::size_t>(id - 1)) = values;
  }
  std::vector<Outcome> result(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = impacts[i]["angle_deg"].get<double>() * std::numbers::pi / 180.0;
    const auto& moving = v[per_angle * (i + 1) - 1];
    const std::array<double, 3> rest = wall ? std::array<double, 3>{} : v[per_angle * i];
    const double dvx = moving[0] - rest[0];
    const double dvz = moving[1] - rest[1];
    result[i] = {-(dvx - kRadius * moving[2] - kRadius * rest[2]) / (speed * std::sin(a)),
                 std::atan2(dvx, dvz) * 180.0 / std::numbers::pi, -moving[2]};
  }
  return result;
}

void expect_lammps_agrees(const nlohmann::json& out, bool wall, const std::vector<std::string>& lines,
                          const nlohmann::json& impacts, const std::string& label) {
  ASSERT_FALSE(restitution::dem::dem_program(restitution::dem::Code::lammps).empty())
      << "lmp not found on PATH: scripts/setup installs Debian's lammps";
  const double dt = out["oblique"]["lammps_steps"]["timestep_s"].get<double>();
  const double accuracy = out["oblique"]["lammps_steps"]["et_accuracy"].get<double>();
  double longest = 0.0;
  for (const auto& i : impacts) longest = std::max(longest, i["contact_time_s"].get<double>());
  const auto coarse = run_lammps(out, wall, lines, dt, 1.1 * longest);
  const auto fine = run_lammps(out, wall, lines, dt / 10.0, 1.1 * longest);
  const auto extrapolate = restitution::test_support::extrapolate_first_order;
  for (std::size_t i = 0; i < impacts.size(); ++i) {
    const auto& p = impacts[i];
    const double et = p["tangential_restitution"].get<double>();
    const std::string where = label + " at " + std::to_string(p["angle_deg"].get<double>()) + " deg";
    // The printed steps per contact keep LAMMPS's own e_t within the accuracy they are printed for.
    EXPECT_NEAR(coarse[i].et, et, accuracy) << where << ", at the printed timestep";
    EXPECT_NEAR(extrapolate(coarse[i].et, fine[i].et), et, 1e-5) << where;
    const double rebound = p["rebound_angle_deg"].get<double>();
    EXPECT_NEAR(extrapolate(coarse[i].rebound_deg, fine[i].rebound_deg), rebound,
                1e-4 * std::abs(rebound) + 1e-5)
        << where;
    const double spin = p["spin_rad_s"].get<double>();
    EXPECT_NEAR(extrapolate(coarse[i].spin, fine[i].spin), spin, 1e-4 * std::abs(spin) + 1e-5 / kRadius)
        << where;
  }
}

std::vector<std::string> strings_of(const nlohmann::json& array) {
  std::vector<std::string> out;
  for (const auto& s : array) out.push_back(s.get<std::string>());
  return out;
}

class ObliqueDemLines : public ::testing::TestWithParam<bool> {};

TEST_P(ObliqueDemLines, LammpsGivesThePrintedObliqueOutputs) {
  const bool wall = GetParam();
  const auto r = run_cli(kSteel + (wall ? " --wall" : "") + " --target-et 0.25 --reference-angle 20");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto out = nlohmann::json::parse(r.out);
  expect_lammps_agrees(out, wall, strings_of(out["lines"]), out["oblique"]["impacts"],
                       std::string(wall ? "wall" : "pair") + ", the printed lines");
  // The line with the k_t --target-et found, in place of the printed one.
  std::vector<std::string> lines = strings_of(out["lines"]);
  lines.back() = out["oblique"]["inverse"]["lines"][0].get<std::string>();
  expect_lammps_agrees(out, wall, lines, out["oblique"]["inverse"]["impacts"],
                       std::string(wall ? "wall" : "pair") + ", the inverse's line");
}

// `--tangential linear_history --tangential-stiffness 4e6` (about mindlin's k_t a at half the peak overlap
// here): the printed line carries that model, and LAMMPS run on it gives the printed oblique outputs, and so
// does the line --target-et prints for it (linear_history's own k_t).
TEST_P(ObliqueDemLines, LinearHistoryLineGivesItsPrintedObliqueOutputs) {
  const bool wall = GetParam();
  const auto r = run_cli(kSteel + (wall ? " --wall" : "") +
                         " --tangential linear_history --tangential-stiffness 4e6 --target-et 0.25 "
                         "--reference-angle 20");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto out = nlohmann::json::parse(r.out);
  std::vector<std::string> lines = strings_of(out["lines"]);
  ASSERT_NE(lines.back().find(" tangential linear_history 4000000 1 0.3 "), std::string::npos)
      << lines.back();
  expect_lammps_agrees(out, wall, lines, out["oblique"]["impacts"],
                       std::string(wall ? "wall" : "pair") + ", linear_history as printed");
  lines.back() = out["oblique"]["inverse"]["lines"][0].get<std::string>();
  expect_lammps_agrees(out, wall, lines, out["oblique"]["inverse"]["impacts"],
                       std::string(wall ? "wall" : "pair") + ", linear_history, the inverse's line");
}

// `--deck FILE` with friction: after the head-on collisions the deck collides the pair (or the sphere and
// the wall) at each listed angle and prints a restitution-oblique-check line per angle, LAMMPS's extrapolated
// e_t against the printed one (measured: |diff| <= 2e-7).
TEST_P(ObliqueDemLines, CheckDeckCoversTheObliqueImpacts) {
  const bool wall = GetParam();
  ASSERT_FALSE(restitution::dem::dem_program(restitution::dem::Code::lammps).empty())
      << "lmp not found on PATH: scripts/setup installs Debian's lammps";
  TempFolder folder;
  const auto deck = folder.path / "check.lmp";
  const auto r = run_cli(kSteel + (wall ? " --wall" : "") + " --deck " + deck.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto out = nlohmann::json::parse(r.out);
  const auto& impacts = out["oblique"]["impacts"];
  const auto run = restitution::test_support::run_oblique_check_deck(restitution::dem::Code::lammps, deck,
                                                                     out["oblique"]["impacts"], 1e-6);
  EXPECT_EQ(run.head_on, 3U);  // v/10, v, 10 v
  EXPECT_EQ(run.oblique, out["oblique"]["impacts"].size());
  restitution::test_support::record_largest_et_difference(run.largest_diff);
}

INSTANTIATE_TEST_SUITE_P(PairAndWall, ObliqueDemLines, ::testing::Values(false, true));

}  // namespace
