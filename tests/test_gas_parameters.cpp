// SPDX-License-Identifier: BSD-3-Clause
// Issue 46 item 4: the gas study's parameters are declared once (restitution_gas/gas_parameters.hpp). Every
// row is complete, and both the command line and a scene's [[gas]] section read each row into its member of
// GasInputs by the row's name, with the row's range (Python's keywords: python/tests/test_gas_parameters.py).
#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "cli/gas/gas_options.hpp"
#include "restitution/errors.hpp"
#include "restitution_gas/gas_parameters.hpp"
#include "scene/scene.hpp"
#include "scene/scene_gas.hpp"
#include "scene/scene_sections.hpp"

namespace restitution::gas {
namespace {

int members_set(const GasField& f) {
  return int{f.optional_number != nullptr} + int{f.number != nullptr} + int{f.whole_number != nullptr} +
         int{f.word != nullptr};
}

TEST(GasParameters, EveryRowIsComplete) {
  for (const GasField& f : gas_fields()) {
    SCOPED_TRACE(f.name);
    EXPECT_FALSE(std::string(f.name).empty());
    EXPECT_EQ(std::string(f.name).find_first_not_of("abcdefghijklmnopqrstuvwxyz_0123456789"),
              std::string::npos);
    EXPECT_FALSE(f.help.empty());
    EXPECT_NE(f.unit, nullptr);
    switch (f.kind) {
      case FieldKind::optional_number:
        EXPECT_TRUE(f.optional_number != nullptr && members_set(f) == 1);
        break;
      case FieldKind::number:
        EXPECT_TRUE(f.number != nullptr && members_set(f) == 1);
        break;
      case FieldKind::whole_number:
        EXPECT_TRUE(f.whole_number != nullptr && members_set(f) == 1);
        EXPECT_TRUE(f.range.has_value());
        break;
      case FieldKind::word:
      case FieldKind::optional_word:
        EXPECT_TRUE(f.word != nullptr && members_set(f) == 1);
        EXPECT_FALSE(f.words.empty());
        EXPECT_NE(f.check_word, nullptr);
        for (const std::string& w : f.words) EXPECT_NO_THROW(f.check_word(w)) << w;
        EXPECT_THROW(f.check_word("no such word"), InvalidInput);
        break;
      case FieldKind::number_or_word:
        EXPECT_EQ(members_set(f), 0);  // a2, a2_of_haff_eps, a2_evolving
        EXPECT_FALSE(f.words.empty());
        break;
    }
    if (f.range) EXPECT_NE(f.range->text, nullptr);
    EXPECT_EQ(&gas_field(f.name), &f);
  }
  EXPECT_THROW((void)gas_field("no_such_parameter"), std::out_of_range);
  for (const FieldGroup& g : gas_field_groups()) {
    EXPECT_NE(gas_field(g.first).optional_number, nullptr) << g.first;
    EXPECT_NE(gas_field(g.second).optional_number, nullptr) << g.second;
  }
}

// A value inside the row's range (or one of its words), written as TOML and as an option's argument.
std::string valid_value(const GasField& f) {
  if (!f.words.empty()) return f.words.back();
  if (f.kind == FieldKind::whole_number) return "7";
  return f.range && f.range->high ? "0.25" : "3.5";
}

// What the value became in the inputs, as text.
std::string read_back(const GasField& f, const GasInputs& in) {
  if (f.optional_number) return in.*f.optional_number ? std::to_string(*(in.*f.optional_number)) : "none";
  if (f.number) return std::to_string(in.*f.number);
  if (f.whole_number) return std::to_string(in.*f.whole_number);
  if (f.word) return in.*f.word;
  return in.a2_evolving ? "evolving" : in.a2_of_haff_eps ? "haff" : "number";
}

std::string expected(const GasField& f) {
  const std::string v = valid_value(f);
  if (f.kind == FieldKind::whole_number || !f.words.empty()) return v;
  return std::to_string(std::stod(v));
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
  const bool word = !f.words.empty() && value == f.words.back();
  return text + f.name + " = " + (word ? "\"" + value + "\"" : value) + "\n";
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
    app.parse(
        std::vector<std::string>{valid_value(f), option_name(f.name)});  // reversed: CLI11 pops the back
    if (f.kind == FieldKind::number_or_word) {
      EXPECT_EQ(o.a2, valid_value(f));
    } else {
      EXPECT_EQ(read_back(f, o.inputs), expected(f));
    }
  }
}

}  // namespace
}  // namespace restitution::gas
