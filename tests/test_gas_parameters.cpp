// SPDX-License-Identifier: BSD-3-Clause
// Issue 46 item 4: the gas study's parameters are declared once (restitution_gas/gas_parameters.hpp). Every
// row is complete, and both the command line and a scene's [[gas]] section read each row into its member of
// GasInputs by the row's name, with the row's range (Python's keywords: python/tests/test_gas_parameters.py).
#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "cli/gas/gas_options.hpp"
#include "parameter_table_checks.hpp"
#include "restitution/errors.hpp"
#include "restitution_gas/gas_parameters.hpp"
#include "scene/scene.hpp"
#include "scene/scene_gas.hpp"
#include "scene/scene_sections.hpp"

namespace restitution::gas {
namespace {

using table_checks::expected;
using table_checks::valid_value;

// a2's member: its word, or "number".
std::string sonine_words(const GasInputs& in) {
  return in.a2_evolving ? "evolving" : in.a2_of_haff_eps ? "haff" : "number";
}
std::string read_back(const GasField& f, const GasInputs& in) {
  return table_checks::read_back(f, in, sonine_words);
}

TEST(GasParameters, EveryRowIsComplete) {
  for (const GasField& f : gas_fields()) {
    table_checks::expect_complete(f);
    EXPECT_EQ(&gas_field(f.name), &f);
  }
  EXPECT_THROW((void)gas_field("no_such_parameter"), std::out_of_range);
  for (const FieldGroup& g : gas_field_groups()) {
    EXPECT_NE(gas_field(g.first).optional_number, nullptr) << g.first;
    EXPECT_NE(gas_field(g.second).optional_number, nullptr) << g.second;
  }
}

const std::string kScene = R"(output = "out/gas"
[materials.pe]
young_modulus = 1e8
poisson_ratio = 0.4
density = 920.0
radius = 0.005
dissipative_constant = 1e-5
[[gas]]
name = "g"
material = "pe"
)";
// The keys every section needs (eps with velocity: any law, A or not), unless the row under test is one of
// them or the other of its pair.
const std::vector<std::pair<std::string, std::string>> kNeeded{{"eps", "0.8"},
                                                               {"velocity", "2.0"},
                                                               {"packing_fraction", "0.1"},
                                                               {"rms_speed", "1.0"},
                                                               {"haff_times", "10.0"}};

std::string scene_with(const GasField& f, const std::string& value) {
  std::string text = kScene;
  for (const auto& [key, v] : kNeeded) {
    const bool pair_of_row = (f.name == std::string("temperature") && key == "rms_speed") ||
                             (f.name == std::string("duration") && key == "haff_times");
    if (key != f.name && !pair_of_row) text += key + " = " + v + "\n";
  }
  return text + f.name + " = " + table_checks::toml_value(f, value) + "\n";
}

TEST(GasParameters, ASceneReadsEveryKeyIntoItsMemberWithItsRange) {
  for (const GasField& f : gas_fields()) {
    if (f.from_material) continue;
    SCOPED_TRACE(f.name);
    const scene::Scene s = scene::parse_scene(scene_with(f, valid_value(f)), "gas.toml");
    EXPECT_EQ(read_back(f, scene::tasks_of<scene::GasTask>(s, "gas").at(0)->inputs), expected(f));
    if (!f.range) continue;
    try {
      (void)scene::parse_scene(scene_with(f, "-1.0"), "gas.toml");
      ADD_FAILURE() << "-1 taken";
    } catch (const InvalidInput& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find(std::string("gas[0].") + f.name + ": expected " + f.range->text),
                std::string::npos)
          << message;
    }
  }
}

TEST(GasParameters, ASceneTakesNoKeyOfTheMaterial) {
  for (const GasField& f : gas_fields()) {
    if (!f.from_material) continue;
    try {
      (void)scene::parse_scene(scene_with(f, "0.25"), "gas.toml");
      ADD_FAILURE() << f.name << " taken";
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find(std::string(f.name) + ": unknown key"), std::string::npos)
          << e.what();
    }
  }
}

TEST(GasParameters, TheCommandLineReadsEveryOptionIntoItsMember) {
  for (const GasField& f : gas_fields()) {
    SCOPED_TRACE(f.name);
    CLI::App app;
    cli::GasOptions o;
    cli::add_gas_options(app, o);
    table_checks::parse_option(app, f);
    if (f.kind == FieldKind::number_or_word) {
      EXPECT_EQ(o.a2, valid_value(f));
    } else {
      EXPECT_EQ(read_back(f, o.inputs), expected(f));
    }
  }
}

}  // namespace
}  // namespace restitution::gas
