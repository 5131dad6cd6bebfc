// SPDX-License-Identifier: BSD-3-Clause
// A scene's [[oblique]] section computed in the library (scene/scene_oblique_run.hpp): Maw's χ of a sphere on
// a rigid wall is 7(1 − ν)/(2(2 − ν)), the counts and ranges the report quotes are those of the impacts, a
// head-on impact has no e_t, and without a plot no sticking limit is computed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "scene/scene.hpp"
#include "scene/scene_oblique_run.hpp"
#include "scene/scene_sections.hpp"

namespace {

using namespace restitution;

std::string scene_text(const std::string& extra) {
  return R"(output = "out/oblique_test"

[materials.steel]
young_modulus = 2e11
poisson_ratio = 0.3
density = 7800.0
radius = 1e-3
dissipative_constant = 1e-9

[[oblique]]
name = "wall"
material = "steel"
wall = true
model = ["mindlin", "linear_history"]
tangential_stiffness = 2.2e6
friction = 0.3
impact_velocity = 1.0
angles = [0.0, 5.0, 30.0, 60.0, 85.0]
)" + extra;
}

TEST(SceneObliqueRun, CountsAndRangesAreThoseOfTheImpacts) {
  const scene::Scene s = scene::parse_scene(scene_text(""), "oblique_test.toml");
  const scene::ObliqueOutcome o =
      scene::run_oblique_section(s, *scene::tasks_of<scene::ObliqueTask>(s, "oblique").at(0));
  ASSERT_EQ(o.runs.size(), 2U);
  EXPECT_TRUE(o.plotted);
  EXPECT_NEAR(o.maw_chi, 7.0 * (1.0 - 0.3) / (2.0 * (2.0 - 0.3)), 1e-14);
  for (const scene::ObliqueModelRun& run : o.runs) {
    ASSERT_EQ(run.impacts.size(), 5U);
    EXPECT_EQ(run.failed, 0U);
    EXPECT_TRUE(std::isnan(run.impacts[0].result.tangential_restitution));  // head-on: no slip to restitute
    std::size_t sliding = 0;
    double lowest = HUGE_VAL;
    for (const auto& i : run.impacts) {
      if (i.result.slip_time_s >= 0.99 * i.result.contact_time_s) ++sliding;
      if (std::isfinite(i.result.tangential_restitution))
        lowest = std::min(lowest, i.result.tangential_restitution);
    }
    EXPECT_EQ(run.sliding, sliding);
    EXPECT_EQ(run.lowest_et, lowest);
    EXPECT_LE(run.lowest_et, run.highest_et);
    EXPECT_TRUE(run.sticking.failure.empty());
    EXPECT_TRUE(std::isfinite(run.sticking.tangential_restitution));
  }
  // ε depends on v cos θ only, and rises as the normal speed falls: the head-on impact gives the lowest.
  EXPECT_EQ(o.eps_low, o.runs[0].impacts[0].result.normal_restitution);
  EXPECT_EQ(o.first_eps, o.eps_low);
  EXPECT_EQ(o.eps_high, o.runs[0].impacts[4].result.normal_restitution);
}

TEST(SceneObliqueRun, NoPlotNoStickingLimit) {
  const scene::Scene s = scene::parse_scene(scene_text("plot = false\n"), "oblique_test.toml");
  const scene::ObliqueOutcome o =
      scene::run_oblique_section(s, *scene::tasks_of<scene::ObliqueTask>(s, "oblique").at(0));
  EXPECT_FALSE(o.plotted);
  for (const scene::ObliqueModelRun& run : o.runs)
    EXPECT_TRUE(std::isnan(run.sticking.tangential_restitution));
}

}  // namespace
