// SPDX-License-Identifier: BSD-3-Clause
// The scene parser alone: what it accepts, and that every rejection names the file, the line and the key.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>

#include "cli_runner.hpp"
#include "restitution/errors.hpp"
#include "restitution/material.hpp"
#include "scene/scene.hpp"
#include "scene/scene_plan.hpp"
#include "scene/scene_sections.hpp"
#include "scene/scene_studies.hpp"

namespace restitution::scene {
namespace {

std::string error_of(const std::string& text) {
  try {
    (void)parse_scene(text, "test.toml");
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "accepted";
}

TEST(SceneParser, ReadsEverySection) {
  const Scene s = parse_scene(R"(
title = "t"
output = "out/x"
tolerance = 1e-8
method = "bdf"
[materials.rubber]
young_modulus = 1e7
poisson_ratio = 0.45
density = 1100
radius = 0.01
dissipative_constant = 5.8e-5
[[sweep]]
name = "a"
zeta = { from = 0, to = 1, points = 5 }
ends = "delayed-recovery"
quantities = ["eps"]
[[sweep]]
name = "b"
material = "rubber"
velocity = { from = 0.1, to = 10, points = 3, spacing = "log" }
axes = "log-log"
[[trajectory]]
zeta = 2
[[calibration]]
eps = 0.8
velocity = 1
material = "rubber"
[[dashpot]]
damping_ratio = [0.5, 2]
[[stability]]
zeta = [1, 10]
)",
                              "test.toml");
  EXPECT_EQ(s.output, "out/x");
  EXPECT_EQ(s.tolerance, 1e-8);
  EXPECT_EQ(s.method, Method::bdf);
  const auto sweeps = tasks_of<Sweep>(s, "sweep");
  ASSERT_EQ(sweeps.size(), 2U);
  EXPECT_EQ(sweeps[0]->zeta, (std::vector<double>{0, 0.25, 0.5, 0.75, 1}));
  EXPECT_FALSE(sweeps[0]->ends.contains(CollisionEnd::naive));
  EXPECT_FALSE(sweeps[0]->quantities.duration);
  EXPECT_NEAR(sweeps[1]->velocity_m_s[1], 1.0, 1e-15);
  EXPECT_EQ(sweeps[1]->velocity_m_s[2], 10.0);
  EXPECT_EQ(sweeps[1]->axes, Axes::log_log);
  ASSERT_EQ(tasks_of<Trajectory>(s, "trajectory").size(), 1U);
  EXPECT_EQ(*tasks_of<Trajectory>(s, "trajectory")[0]->zeta, 2.0);
  EXPECT_EQ(tasks_of<CalibrationTask>(s, "calibration")[0]->end, CollisionEnd::delayed_recovery);
  EXPECT_EQ(tasks_of<DashpotCheck>(s, "dashpot")[0]->damping_ratio.size(), 2U);
  EXPECT_EQ(tasks_of<ExternalStudy>(s, "stability")[0]->kind, "stability");
}

TEST(SceneParser, UnknownKeysNameFileLineAndKey) {
  EXPECT_EQ(error_of("output = \"o\"\n\n[[sweep]]\nzeta = 1\nzetta = 2\n"),
            "test.toml:5: sweep[0].zetta: unknown key");
  EXPECT_EQ(error_of("output = \"o\"\ncolour = 1\n"), "test.toml:2: colour: unknown key");
  EXPECT_EQ(error_of("output = \"o\"\n[[sweep]]\nzeta = {from = 0, to = 1, points = 3, step = 1}\n"),
            "test.toml:3: sweep[0].zeta.step: unknown key");
}

TEST(SceneParser, WrongTypesAndRangesNameTheKey) {
  EXPECT_EQ(error_of("output = \"o\"\ntolerance = \"tight\"\n"), "test.toml:2: tolerance: expected a number");
  EXPECT_EQ(error_of("output = \"o\"\ntolerance = 1.0\n"),
            "test.toml:2: tolerance: expected a value in [1e-11, 0.01]");
  EXPECT_EQ(error_of("output = \"o\"\n[[sweep]]\nzeta = [0.1, -1]\n"),
            "test.toml:3: sweep[0].zeta: expected 0 <= zeta <= 1e+06 (the checked range), got -1");
  EXPECT_EQ(error_of("output = \"o\"\n[[sweep]]\nzeta = 1\nends = \"middle\"\n"),
            "test.toml:4: sweep[0].ends: end must be naive, delayed-recovery or both, got 'middle'");
  EXPECT_EQ(error_of("output = \"o\"\n[[sweep]]\nzeta = {from = 0, to = 1, points = 2.5}\n"),
            "test.toml:3: sweep[0].zeta.points: expected a whole number in [1, 1000000]");
  EXPECT_EQ(error_of("output = \"o\"\n[[sweep]]\nzeta = {from = 0, to = 1, points = 3, spacing = \"log\"}\n"),
            "test.toml:3: sweep[0].zeta.from: must be > 0 for spacing = \"log\"");
  EXPECT_EQ(error_of("output = \"o\"\n[[calibration]]\neps = 1.2\nvelocity = 1\n"),
            "test.toml:3: calibration[0].eps: expected a value in (0, 1), got 1.2");
  EXPECT_EQ(
      error_of("output = \"o\"\n[[dashpot]]\ndamping_ratio = true\n"),
      "test.toml:3: dashpot[0].damping_ratio: expected a number, a list of numbers or a range { from, to, "
      "points, spacing }");
}

TEST(SceneParser, MaterialErrorsNameTheMaterialAndTheKey) {
  const std::string e = error_of(
      "output = \"o\"\n[materials.glass]\nyoung_modulus = 6e10\npoisson_ratio = 0.7\ndensity = 2500\nradius "
      "= "
      "0.01\ndissipative_constant = 1e-9\n");
  EXPECT_NE(e.find("test.toml:2: materials.glass: "), std::string::npos) << e;
  EXPECT_NE(e.find("poisson_ratio must be in (-1, 0.5)"), std::string::npos) << e;
  EXPECT_NE(error_of("output = \"o\"\n[[sweep]]\nmaterial = \"steel\"\nvelocity = 1\n")
                .find("test.toml:3: sweep[0].material: no [materials.steel]"),
            std::string::npos);
}

// A material's optional fields are assembled by the library (material_from_fields), so a scene, Python and
// the command line follow one rule in the same words; the scene names the file, the line and the key.
TEST(SceneParser, MaterialFieldsFollowTheLibrarysRules) {
  const std::string head =
      "output = \"o\"\n[materials.glass]\nyoung_modulus = 6e10\npoisson_ratio = 0.2\ndensity = 2500\n";
  const std::string both_radii = error_of(head + "radius = 0.01\nradii = [0.01, 0.02]\n");
  EXPECT_NE(
      both_radii.find("test.toml:6: materials.glass.radius: give radius (both spheres) or radii = [R1, R2]"),
      std::string::npos)
      << both_radii;
  const std::string both_masses = error_of(head + "radius = 0.01\nmass = 1\nmasses = [1, 2]\n");
  EXPECT_NE(both_masses.find("test.toml:7: materials.glass.mass: give mass or masses, not both"),
            std::string::npos)
      << both_masses;
  MaterialFields fields;
  fields.young_modulus_pa = 6e10;
  fields.poisson_ratio = 0.2;
  fields.radius_m = 0.01;
  fields.masses_kg = std::array<double, 2>{1.0, 2.0};
  const Material m = material_from_fields(fields);
  EXPECT_EQ(m.radius2_m, 0.01);
  EXPECT_EQ(m.mass2_kg, 2.0);
  fields.mass_kg = 1.0;
  EXPECT_THROW((void)material_from_fields(fields), InvalidInput);
}

// Issue 12, item 18: a material only calibrated needs no damping (the calibration computes it); the tasks
// that compute with its damping say so at their own line.
TEST(SceneParser, DampingIsNeededOnlyWhereItIsUsed) {
  const std::string elastic =
      "output = \"o\"\n[materials.ice]\nyoung_modulus = 7e9\npoisson_ratio = 0.3\ndensity = 917\n"
      "radius = 0.01\n";
  const Scene s =
      parse_scene(elastic + "[[calibration]]\neps = 0.8\nvelocity = 1\nmaterial = \"ice\"\n", "t");
  EXPECT_FALSE(s.materials.at("ice").dissipative_constant_s.has_value());
  EXPECT_EQ(
      error_of(elastic + "[[sweep]]\nmaterial = \"ice\"\nvelocity = 1\n"),
      "test.toml:8: sweep[0].material: [materials.ice] has neither dissipative_constant nor viscosities, "
      "which a sweep needs (only a calibration can do without: it computes them)");
  EXPECT_NE(error_of(elastic + "[[trajectory]]\nmaterial = \"ice\"\nvelocity = 1\n")
                .find("test.toml:8: trajectory[0].material: [materials.ice] has neither"),
            std::string::npos);
  EXPECT_NE(error_of(elastic + "[[dem]]\ncode = \"lammps\"\nmaterial = \"ice\"\nspeeds = [1]\n")
                .find("which a dem task without eps needs"),
            std::string::npos);
  EXPECT_EQ(error_of(elastic + "[[dem]]\ncode = \"lammps\"\nmaterial = \"ice\"\neps = 0.8\nvelocity = 1\n"
                               "speeds = [1]\n"),
            "accepted");
  // Both kinds of damping at once is still an error, and it is found at the material.
  EXPECT_NE(error_of(elastic + "dissipative_constant = 1e-6\nviscosities = [1, 1]\n")
                .find("give exactly one of dissipative_constant and viscosities"),
            std::string::npos);
}

TEST(SceneParser, SubjectsMustBeUnambiguous) {
  EXPECT_NE(error_of("output = \"o\"\n[[sweep]]\nzeta = 1\nbeta = 0.2\n").find("give zeta alone"),
            std::string::npos);
  EXPECT_NE(error_of("output = \"o\"\n[[sweep]]\nvelocity = 1\n").find("needs exactly one of"),
            std::string::npos);
  EXPECT_NE(error_of("output = \"o\"\n[[sweep]]\n").find("test.toml:2: sweep[0]: give zeta"),
            std::string::npos);
  EXPECT_NE(
      error_of("output = \"o\"\n[[sweep]]\nname = \"a\"\nzeta = 1\n[[trajectory]]\nname = \"a\"\nzeta = 1\n")
          .find("test.toml:6: trajectory[0].name: \"a\" is used twice"),
      std::string::npos);
  EXPECT_NE(error_of("title = \"no output\"\n").find("output: missing"), std::string::npos);
}

TEST(SceneParser, SyntaxErrorsCarryTheLine) {
  const std::string e = error_of("output = \"o\"\n\n[[sweep]\n");
  EXPECT_EQ(e.rfind("test.toml:3: ", 0), 0U) << e;
}

// Issue 12, item 20: log-spaced ranges start and end at exactly the numbers written.
TEST(SceneParser, LogRangesEndAtTheNumbersGiven) {
  const Scene s = parse_scene(
      "output = \"o\"\n[[sweep]]\nbeta = 0.2\nvelocity = {from = 0.01, to = 1e300, points = 7, spacing = "
      "\"log\"}\n",
      "t.toml");
  EXPECT_EQ(tasks_of<Sweep>(s, "sweep")[0]->velocity_m_s.front(), 0.01);
  EXPECT_EQ(tasks_of<Sweep>(s, "sweep")[0]->velocity_m_s.back(), 1e300);
}

TEST(SceneParser, QuickSettingsKeepTheEndsOfEveryRange) {
  Scene s = parse_scene("output = \"o\"\n[[sweep]]\nzeta = {from = 0, to = 10, points = 101}\n", "t.toml");
  make_quick(s, 4);
  const std::vector<double>& zeta = tasks_of<Sweep>(s, "sweep")[0]->zeta;
  EXPECT_EQ(zeta, (std::vector<double>{0.0, zeta[1], zeta[2], 10.0}));
}

}  // namespace
}  // namespace restitution::scene

namespace restitution::scene {
namespace {

TEST(SceneParser, TheDocumentedExampleSceneIsValid) {
  const std::string doc = restitution::test_support::slurp(RESTITUTION_SOURCE_DIR "/docs/scenes.md");
  const std::size_t start = doc.find("```toml\n");
  ASSERT_NE(start, std::string::npos);
  const std::size_t end = doc.find("```", start + 8);
  const Scene s = parse_scene(doc.substr(start + 8, end - start - 8), "docs/scenes.md");
  for (const char* kind : {"sweep", "trajectory", "calibration", "dashpot"})
    EXPECT_EQ(std::count_if(s.sections.begin(), s.sections.end(),
                            [kind](const SectionTask& section) { return section.kind == kind; }),
              1)
        << kind;
  EXPECT_NO_THROW((void)plan_scene(s));
}

}  // namespace
}  // namespace restitution::scene

namespace restitution::scene {
namespace {

// One vocabulary: the scene takes every method the library names (taylor included) and refuses others in
// the library's words; the defaults are SolveOptions'.
TEST(SceneParser, MethodsAndDefaultsAreTheLibrarys) {
  for (const std::string& name : method_names()) {
    const Scene s = parse_scene("output = \"o\"\nmethod = \"" + name + "\"\n", "test.toml");
    EXPECT_EQ(method_name(s.method), name);
  }
  const Scene s = parse_scene("output = \"o\"\n", "test.toml");
  EXPECT_EQ(s.tolerance, SolveOptions{}.tolerance);
  EXPECT_EQ(s.method, SolveOptions{}.method);
  try {
    (void)parse_scene("output = \"o\"\nmethod = \"rk4\"\n", "test.toml");
    FAIL() << "method rk4 was accepted";
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), "test.toml:2: method: method must be bdf, adams, auto or taylor, got 'rk4'");
  }
}

}  // namespace
}  // namespace restitution::scene
