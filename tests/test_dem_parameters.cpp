// SPDX-License-Identifier: BSD-3-Clause
// Issue 46 item 4: the DEM-lines study's and the damping check's parameters are declared once
// (dem/dem_parameters.hpp, damping_check/damping_check_parameters.hpp). Every row is complete and named once;
// `restitution dem` and `restitution damping-check` have each row's option with the row's help, and read it
// into the row's member; a scene's [[dem]] and [[damping_check]] read each key row into its member with the
// row's check, and refuse the rows they take otherwise as unknown keys.
#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "cli/common/commands.hpp"
#include "cli/common/parameter_options.hpp"
#include "damping_check/damping_check_parameters.hpp"
#include "dem/dem_parameters.hpp"
#include "material_examples.hpp"
#include "parameter_table_checks.hpp"
#include "restitution/errors.hpp"
#include "scene/scene.hpp"
#include "scene/scene_damping_check.hpp"
#include "scene/scene_dem.hpp"
#include "scene/scene_sections.hpp"
#include "scene_errors.hpp"

namespace restitution {
namespace {

using damping_check::DampingCheckField;
using damping_check::DampingCheckInputs;
using dem::DemField;
using dem::DemInputs;
using table_checks::expected;
using table_checks::read_back;
using table_checks::valid_value;

// Each row complete, its name and option once in the table, found by its name.
template <class In, class Find>
void expect_table_complete(const std::vector<ParameterField<In>>& fields, Find find) {
  std::set<std::string> names, keys;
  for (const ParameterField<In>& f : fields) {
    table_checks::expect_complete(f);
    EXPECT_EQ(&find(f.name), &f);
    EXPECT_TRUE(names.insert(option_name(f.name)).second) << f.name;
    if (f.is_key()) EXPECT_TRUE(keys.insert(f.key()).second) << f.key();
  }
  EXPECT_THROW((void)find("no_such_parameter"), std::out_of_range);
}

TEST(DemParameters, EveryRowIsCompleteAndNamedOnce) {
  expect_table_complete(dem::dem_fields(), dem::dem_field);
  expect_table_complete(damping_check::damping_check_fields(), damping_check::damping_check_field);
}

// The command as the program makes it: each row's option is there with the row's help, and no other option
// of the command spells a key of the section (what both front ends take is a row).
template <class In>
void expect_command_has_rows(void (*add_command)(CLI::App&, cli::Action&), const char* command,
                             const std::vector<ParameterField<In>>& fields,
                             const std::set<std::string>& section_keys) {
  CLI::App app;
  cli::Action chosen;
  add_command(app, chosen);
  const CLI::App* cmd = app.get_subcommand(command);
  std::set<std::string> rows;
  for (const ParameterField<In>& f : fields) {
    SCOPED_TRACE(f.name);
    rows.insert(option_name(f.name));
    const CLI::Option* option = cmd->get_option_no_throw(option_name(f.name));
    ASSERT_NE(option, nullptr);
    EXPECT_EQ(option->get_description(), f.help);
  }
  for (const CLI::Option* option : cmd->get_options()) {
    if (option->get_group().empty()) continue;  // an old name, hidden (cli/common/deprecated_alias.hpp)
    for (std::string key : option->get_lnames()) {
      if (rows.count("--" + key) > 0) continue;
      std::replace(key.begin(), key.end(), '-', '_');
      EXPECT_EQ(section_keys.count(key), 0U) << key << " is an option and a key: make it a row";
    }
  }
}

// The keys of a section: its rows' and the section's own.
template <class In>
std::set<std::string> keys_of(const std::vector<ParameterField<In>>& fields, std::set<std::string> own) {
  for (const ParameterField<In>& f : fields) {
    if (f.is_key()) own.insert(f.key());
  }
  return own;
}

TEST(DemParameters, TheCommandsHaveEveryRowsOption) {
  expect_command_has_rows(cli::add_dem_command, "dem", dem::dem_fields(),
                          keys_of(dem::dem_fields(), {"name", "title", "material", "run"}));
  expect_command_has_rows(
      cli::add_damping_check_command, "damping-check", damping_check::damping_check_fields(),
      keys_of(damping_check::damping_check_fields(), {"name", "title", "recipes", "speeds"}));
}

// Each row's option given alone to a command made of the table is read into the row's member.
template <class In>
void expect_options_read(const std::vector<ParameterField<In>>& fields) {
  for (const ParameterField<In>& f : fields) {
    SCOPED_TRACE(f.name);
    CLI::App app;
    In in;
    cli::add_parameter_options(app, fields, in, [](const ParameterField<In>&, CLI::Option*) {});
    table_checks::parse_option(app, f);
    EXPECT_EQ(read_back(f, in), expected(f));
  }
}

TEST(DemParameters, TheCommandLineReadsEveryOptionIntoItsMember) {
  expect_options_read(dem::dem_fields());
  expect_options_read(damping_check::damping_check_fields());
}

const std::string kMaterial = std::string("output = \"out/dem\"\n") + test_support::kRubberLikeToml;

// A [[dem]] with the keys it needs (a code, the speeds), less the row's; eps needs its velocity.
std::string dem_without(const DemField& f) {
  std::string text = kMaterial + "[[dem]]\nname = \"d\"\nmaterial = \"rubber\"\n";
  if (std::string(f.key()) != "code") text += "code = \"lammps\"\n";
  if (std::string(f.key()) != "speeds") text += "speeds = [1.0]\n";
  if (f.optional_number == &DemInputs::eps) text += "velocity = 1.0\n";
  return text;
}

std::string damping_check_without(const DampingCheckField& /*f*/) {
  return kMaterial + "[[damping_check]]\nname = \"c\"\nrecipes = [\"lammps-tsuji\"]\n";
}

const DemInputs& inputs_of_dem(const scene::Scene& s) {
  return scene::tasks_of<scene::DemTask>(s, "dem").at(0)->inputs;
}
const DampingCheckInputs& inputs_of_check(const scene::Scene& s) {
  return scene::tasks_of<scene::DampingCheckTask>(s, "damping_check").at(0)->inputs;
}

using scene_errors::scene_error;

// Every key row is read into its member; a value out of the row's range is refused in the range's words, one
// the study's own check refuses in its words, a missing required key with what it is.
template <class In>
void expect_keys_read(const std::vector<ParameterField<In>>& fields,
                      std::string (*without)(const ParameterField<In>&),
                      const In& (*inputs_of)(const scene::Scene&)) {
  for (const ParameterField<In>& f : fields) {
    if (!f.is_key()) continue;
    SCOPED_TRACE(f.name);
    const auto with = [&](const std::string& value) {
      return without(f) + f.key() + " = " + table_checks::toml_value(f, value) + "\n";
    };
    EXPECT_EQ(read_back(f, inputs_of(scene::parse_scene(with(valid_value(f)), "s.toml"))), expected(f));
    const std::string at = std::string(f.key()) + ": ";
    if (f.range)
      EXPECT_NE(scene_error(with("-1.0")).find(at + "expected " + f.range->text), std::string::npos);
    if (f.check_number != nullptr) {
      try {
        f.check_number(-1.0);
        ADD_FAILURE() << "-1 passes the check";
      } catch (const InvalidInput& e) {
        EXPECT_NE(scene_error(with("-1.0")).find(at + e.what()), std::string::npos);
      }
    }
    if (f.check_word != nullptr) {
      try {
        f.check_word("no-such-word");
        ADD_FAILURE() << "no-such-word passes the check";
      } catch (const InvalidInput& e) {
        EXPECT_NE(scene_error(with("no-such-word")).find(at + e.what()), std::string::npos);
      }
    }
    if (f.required) EXPECT_NE(scene_error(without(f)).find(at + "missing: " + f.required), std::string::npos);
  }
}

TEST(DemParameters, ASceneReadsEveryKeyIntoItsMemberWithItsCheck) {
  expect_keys_read<DemInputs>(dem::dem_fields(), dem_without, inputs_of_dem);
  expect_keys_read<DampingCheckInputs>(damping_check::damping_check_fields(), damping_check_without,
                                       inputs_of_check);
  // The code's absence is said with the codes there are.
  const std::string no_code = scene_error(dem_without(dem::dem_field("code")));
  EXPECT_NE(no_code.find("code: missing (" + dem::code_list(" or ") + ")"), std::string::npos) << no_code;
  // The damping check's list of requested eps takes --eps's range.
  const FieldRange& eps = *damping_check::damping_check_field("eps").range;
  EXPECT_NE(
      scene_error(damping_check_without(damping_check::damping_check_field("eps")) + "eps = [0.5, 1.5]\n")
          .find("eps: expected " + eps.text),
      std::string::npos);
}

// A row that is no key of the section (the material's A, the scene's tolerance, the command's modes) is
// refused as an unknown key: `own` the section's own keys of the same name (the damping check's list eps).
template <class In>
void expect_non_keys_refused(const std::vector<ParameterField<In>>& fields,
                             std::string (*without)(const ParameterField<In>&),
                             const std::set<std::string>& own) {
  for (const ParameterField<In>& f : fields) {
    if (f.is_key() || own.count(f.name) > 0) continue;
    SCOPED_TRACE(f.name);
    EXPECT_NE(scene_error(without(f) + f.name + " = 0.25\n").find(std::string(f.name) + ": unknown key"),
              std::string::npos);
  }
}

TEST(DemParameters, ASceneRefusesTheRowsItTakesOtherwise) {
  expect_non_keys_refused<DemInputs>(dem::dem_fields(), dem_without, {});
  expect_non_keys_refused<DampingCheckInputs>(damping_check::damping_check_fields(), damping_check_without,
                                              {"eps"});
}

}  // namespace
}  // namespace restitution
