// SPDX-License-Identifier: BSD-3-Clause
// Issue 46 item 4: the oblique study's parameters are declared once
// (restitution_oblique/oblique_parameters.hpp). Every row is complete, and both the command line's options
// (made from the table as `restitution oblique` makes them) and a scene's [[oblique]] section read each row
// into its member of ObliqueInputs by the row's name (a scene: its key), with the row's range (Python's
// keywords: python/tests/test_oblique_parameters.py).
#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "cli/common/parameter_options.hpp"
#include "parameter_table_checks.hpp"
#include "restitution/errors.hpp"
#include "restitution_oblique/oblique_parameters.hpp"
#include "scene/scene.hpp"
#include "scene/scene_oblique.hpp"
#include "scene/scene_sections.hpp"

namespace restitution::oblique {
namespace {

using table_checks::expected;
using table_checks::read_back;
using table_checks::valid_value;

TEST(ObliqueParameters, EveryRowIsComplete) {
  for (const ObliqueField& f : oblique_fields()) {
    table_checks::expect_complete(f);
    EXPECT_EQ(&oblique_field(f.name), &f);
    EXPECT_NE(f.kind, FieldKind::number_or_word);  // every row has a member
  }
  EXPECT_THROW((void)oblique_field("no_such_parameter"), std::out_of_range);
  EXPECT_EQ(option_name("tangential_stiffness"), "--tangential-stiffness");
}

const std::string kScene = R"(output = "out/oblique"
[materials.steel]
young_modulus = 2e11
poisson_ratio = 0.3
density = 7800.0
radius = 1e-3
dissipative_constant = 1e-7
[[oblique]]
name = "o"
material = "steel"
)";
// The keys every section needs, unless the row under test is one of them.
const std::vector<std::pair<std::string, std::string>> kNeeded{{"friction", "0.3"}, {"angles", "[10.0]"}};

// The section with the keys it needs, less the row's.
std::string scene_without(const ObliqueField& f) {
  std::string text = kScene;
  for (const auto& [key, v] : kNeeded) {
    if (key != f.key()) text += key + " = " + v + "\n";
  }
  // A wall's material needs the wall.
  if (f.optional_number == &ObliqueInputs::wall_young_modulus_pa)
    text += "wall = true\nwall_poisson_ratio = 0.3\n";
  if (f.optional_number == &ObliqueInputs::wall_poisson_ratio)
    text += "wall = true\nwall_young_modulus = 1e9\n";
  return text;
}

std::string scene_with(const ObliqueField& f, const std::string& value) {
  return scene_without(f) + f.key() + " = " + table_checks::toml_value(f, value) + "\n";
}

const ObliqueInputs& inputs_of(const scene::Scene& s) {
  return scene::tasks_of<scene::ObliqueTask>(s, "oblique").at(0)->inputs;
}

TEST(ObliqueParameters, ASceneReadsEveryKeyIntoItsMemberWithItsRange) {
  for (const ObliqueField& f : oblique_fields()) {
    if (!f.is_key()) continue;
    SCOPED_TRACE(f.name);
    const scene::Scene s = scene::parse_scene(scene_with(f, valid_value(f)), "oblique.toml");
    EXPECT_EQ(read_back(f, inputs_of(s)), expected(f));
    if (!f.range) continue;
    try {
      (void)scene::parse_scene(scene_with(f, "-1.0"), "oblique.toml");
      ADD_FAILURE() << "a value out of range taken";
    } catch (const InvalidInput& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find(std::string(f.key()) + ": expected " + f.range->text), std::string::npos)
          << message;
    }
  }
}

TEST(ObliqueParameters, ASceneRefusesTheKeysItTakesOtherwise) {
  // The material gives A (and the spheres), the key `model` the tangential models; eps, velocity and law are
  // the command's and Python's.
  for (const ObliqueField& f : oblique_fields()) {
    if (f.is_key() || f.number == &ObliqueInputs::speed_m_s) continue;
    SCOPED_TRACE(f.name);
    try {
      (void)scene::parse_scene(scene_without(f) + f.name + " = 0.25\n", "oblique.toml");
      ADD_FAILURE() << f.name << " taken";
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find(std::string(f.name) + ": unknown key"), std::string::npos)
          << e.what();
    }
  }
}

TEST(ObliqueParameters, TheCommandLineReadsEveryOptionIntoItsMember) {
  for (const ObliqueField& f : oblique_fields()) {
    SCOPED_TRACE(f.name);
    CLI::App app;
    ObliqueInputs in;
    cli::add_parameter_options(app, oblique_fields(), in, [](const ObliqueField&, CLI::Option*) {});
    table_checks::parse_option(app, f);
    EXPECT_EQ(read_back(f, in), expected(f));
  }
}

}  // namespace
}  // namespace restitution::oblique
