// SPDX-License-Identifier: BSD-3-Clause
// The oblique outputs of `restitution dem --code liggghts --friction 0.3` (src/dem/oblique_lines.cpp, worded
// by src/cli/dem/dem_oblique.cpp) are what Debian's LIGGGHTS (3.8.0+repack1) gives with the printed lines
// pasted unchanged: two 1 mm steel spheres under hertz/stiffness with `tangential history`, at the six
// default angles and 20°, with the lines as printed and with the kt line --target-et prints in place of the
// printed one (e_t = 0.25 at 20°). At the printed timestep (the steps per contact for e_t within 1e-4)
// LIGGGHTS's e_t is within 1e-4 of the printed one; at a tenth of it, Richardson-extrapolated, within 1e-5,
// and so are the rebound angle (degrees, relative 1e-4) and both spins. The check deck `--deck FILE` writes,
// run unchanged by `liggghts -in`, prints one restitution-oblique-check line per angle with |diff| <= 1e-5
// (measured 1.8e-6).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "dem/code_runner.hpp"
#include "dem/oblique_runs.hpp"

namespace {

using restitution::test_support::run_cli;
using restitution::test_support::TempFolder;

constexpr double kRadius = restitution::test_support::kObliqueRunRadius;
const std::string kSteel =
    "dem --code liggghts --young-modulus 2e11 --poisson-ratio 0.3 --radius 1e-3 --density 7800 --eps 0.9 "
    "--velocity 1 --friction 0.3 --json";

std::vector<double> angles_of(const nlohmann::json& impacts) {
  std::vector<double> angles;
  for (const auto& i : impacts) angles.push_back(i["angle_deg"].get<double>());
  return angles;
}

void expect_liggghts_agrees(const nlohmann::json& out, const std::vector<std::string>& lines,
                            const nlohmann::json& impacts, const std::string& label) {
  const std::string program = restitution::dem::dem_program(restitution::dem::Code::liggghts);
  ASSERT_FALSE(program.empty()) << "liggghts not found on PATH: scripts/setup installs Debian's liggghts";
  ASSERT_EQ(out["oblique"]["speed_m_s"].get<double>(), 1.0);  // the speed the runs collide at
  const double dt = out["oblique"]["liggghts_steps"]["timestep_s"].get<double>();
  const double accuracy = out["oblique"]["liggghts_steps"]["et_accuracy"].get<double>();
  double longest = 0.0;
  for (const auto& i : impacts) longest = std::max(longest, i["contact_time_s"].get<double>());
  const std::vector<double> angles = angles_of(impacts);
  ASSERT_GE(angles.size(), 4U);
  const auto run = restitution::test_support::run_liggghts_oblique;
  const auto coarse = run(program, lines, false, 0.0, dt, 1.1 * longest, angles);
  const auto fine = run(program, lines, false, 0.0, dt / 10.0, 1.1 * longest, angles);
  const auto extrapolate = restitution::test_support::extrapolate_first_order;
  double largest = 0.0;
  for (std::size_t i = 0; i < impacts.size(); ++i) {
    const auto& p = impacts[i];
    ASSERT_EQ(p["conditioning"].get<std::string>(), "well-conditioned") << label;
    const double et = p["tangential_restitution"].get<double>();
    const std::string where = label + " at " + std::to_string(angles[i]) + " deg";
    // The printed steps per contact keep LIGGGHTS's own e_t within the accuracy they are printed for.
    EXPECT_NEAR(coarse[i].et, et, accuracy) << where << ", at the printed timestep";
    const double et_liggghts = extrapolate(coarse[i].et, fine[i].et);
    EXPECT_NEAR(et_liggghts, et, 1e-5) << where;
    largest = std::max(largest, std::abs(et_liggghts - et));
    const double rebound = p["rebound_angle_deg"].get<double>();
    EXPECT_NEAR(extrapolate(coarse[i].rebound_deg, fine[i].rebound_deg), rebound,
                1e-4 * std::abs(rebound) + 1e-5)
        << where;
    for (const auto& [key, code_spin, code_spin_fine] :
         {std::tuple{"spin_rad_s", coarse[i].spin, fine[i].spin},
          std::tuple{"spin2_rad_s", coarse[i].spin2, fine[i].spin2}}) {
      const double spin = p[key].get<double>();
      EXPECT_NEAR(extrapolate(code_spin, code_spin_fine), spin, 1e-4 * std::abs(spin) + 1e-5 / kRadius)
          << where << ", " << key;
    }
  }
  restitution::test_support::record_largest_et_difference(largest);
}

TEST(ObliqueDemLinesLiggghts, LiggghtsGivesThePrintedObliqueOutputs) {
  // The default angles and the inverse's reference angle.
  const auto r = run_cli(kSteel + " --angle 5,15,20,30,45,60,80 --target-et 0.25 --reference-angle 20");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto out = nlohmann::json::parse(r.out);
  const auto lines = out["lines"].get<std::vector<std::string>>();
  expect_liggghts_agrees(out, lines, out["oblique"]["impacts"], "the printed lines");
  // The kt line --target-et found, in place of the printed one.
  std::vector<std::string> changed = lines;
  const auto inverse_line = out["oblique"]["inverse"]["lines"][0].get<std::string>();
  const auto kt = std::find_if(changed.begin(), changed.end(),
                               [](const std::string& l) { return l.rfind("fix dem_kt ", 0) == 0; });
  ASSERT_NE(kt, changed.end());
  ASSERT_EQ(inverse_line.rfind("fix dem_kt all property/global kt peratomtypepair 1 ", 0), 0U)
      << inverse_line;
  *kt = inverse_line;
  const auto& inverse_impacts = out["oblique"]["inverse"]["impacts"];
  ASSERT_EQ(inverse_impacts[2]["angle_deg"].get<double>(), 20.0);
  EXPECT_NEAR(inverse_impacts[2]["tangential_restitution"].get<double>(), 0.25, 1e-9);
  expect_liggghts_agrees(out, changed, inverse_impacts, "the inverse's line");
}

// `--deck FILE` with friction: after the head-on collisions the deck collides the pair at each listed angle
// (dt = t_c/10000 and t_c/100000) and prints a restitution-oblique-check line per angle, LIGGGHTS's
// extrapolated e_t against the printed one: |diff| <= 1e-5 (measured 1.8e-6 at 15 deg).
TEST(ObliqueDemLinesLiggghts, CheckDeckCoversTheObliqueImpacts) {
  TempFolder folder;
  const auto deck = folder.path / "check.liggghts";
  const auto r = run_cli(kSteel + " --deck " + deck.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto impacts = nlohmann::json::parse(r.out)["oblique"]["impacts"];
  ASSERT_EQ(impacts.size(), 6U);  // 5, 15, 30, 45, 60, 80 degrees
  const auto run = restitution::test_support::run_oblique_check_deck(restitution::dem::Code::liggghts, deck,
                                                                     impacts, 1e-5);
  EXPECT_EQ(run.head_on, 3U);  // v/10, v, 10 v
  EXPECT_EQ(run.oblique, impacts.size());
  restitution::test_support::record_largest_et_difference(run.largest_diff);
}

}  // namespace
