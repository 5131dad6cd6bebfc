// SPDX-License-Identifier: BSD-3-Clause
// Issue 46 item 4: the head-on collision's parameters that `eps` and `sweep` share are declared once
// (restitution/head_on_parameters.hpp), and the rows other tables repeat word for word (the material's
// fields, the law) are made once (restitution/parameter_rows.hpp). Every row is complete and named once; both
// commands have each row's option with the row's help and read it into the row's member; a scene's [[sweep]]
// reads its `law` key with the row's check and refuses the rows it takes otherwise as unknown keys.
#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <set>
#include <string>
#include <vector>

#include "cli/common/commands.hpp"
#include "cli/common/material_options.hpp"
#include "cli/common/parameter_options.hpp"
#include "dem/dem_parameters.hpp"
#include "parameter_table_checks.hpp"
#include "restitution/errors.hpp"
#include "restitution/head_on_parameters.hpp"
#include "restitution/parameter_rows.hpp"
#include "restitution_gas/gas_parameters.hpp"
#include "scene/scene.hpp"
#include "scene/scene_sections.hpp"
#include "scene_errors.hpp"

namespace restitution {
namespace {

using table_checks::expected;
using table_checks::read_back;
using table_checks::valid_value;

TEST(HeadOnParameters, EveryRowIsCompleteAndNamedOnce) {
  std::set<std::string> options;
  for (const HeadOnField& f : head_on_fields()) {
    table_checks::expect_complete(f);
    EXPECT_EQ(&head_on_field(f.name), &f);
    EXPECT_TRUE(options.insert(option_name(f.name)).second) << f.name;
  }
  EXPECT_THROW((void)head_on_field("zeta"), std::out_of_range);  // each command's own
}

// The command as the program makes it: each row's option is there with the row's help.
void expect_command_has_rows(void (*add_command)(CLI::App&, cli::Action&), const char* command) {
  CLI::App app;
  cli::Action chosen;
  add_command(app, chosen);
  const CLI::App* cmd = app.get_subcommand(command);
  for (const HeadOnField& f : head_on_fields()) {
    SCOPED_TRACE(std::string(command) + " " + f.name);
    const CLI::Option* option = cmd->get_option_no_throw(option_name(f.name));
    ASSERT_NE(option, nullptr);
    EXPECT_EQ(option->get_description(), f.help);
  }
}

TEST(HeadOnParameters, EpsAndSweepHaveEveryRowsOption) {
  expect_command_has_rows(cli::add_eps_command, "eps");
  expect_command_has_rows(cli::add_sweep_command, "sweep");
}

TEST(HeadOnParameters, TheCommandLineReadsEveryOptionIntoItsMember) {
  for (const HeadOnField& f : head_on_fields()) {
    SCOPED_TRACE(f.name);
    CLI::App app;
    HeadOnInputs in;
    cli::add_parameter_options(app, head_on_fields(), in, [](const HeadOnField&, CLI::Option*) {});
    table_checks::parse_option(app, f);
    EXPECT_EQ(read_back(f, in), expected(f));
  }
}

// The defaults are the solver's: inputs given nothing solve as SolveOptions{} does.
TEST(HeadOnParameters, TheDefaultsAreTheSolversOwn) {
  const SolveOptions given = solve_options_of(HeadOnInputs{});
  const SolveOptions own;
  EXPECT_EQ(given.tolerance, own.tolerance);
  EXPECT_EQ(given.method, own.method);
  EXPECT_TRUE(given.ends == EndSet::both());
  HeadOnInputs unknown;
  unknown.method = "euler";
  EXPECT_THROW((void)solve_options_of(unknown), InvalidInput);
}

// The material rows are one declaration: the gas table's, the head-on table's and the options of the
// commands that take a material (calibrate) say the same.
TEST(HeadOnParameters, TheSharedRowsSayTheSameEverywhere) {
  CLI::App calibrate;
  cli::Action chosen;
  cli::add_calibrate_command(calibrate, chosen);
  const CLI::App* cmd = calibrate.get_subcommand("calibrate");
  int compared = 0;
  for (const MaterialRowWords& w : material_row_words()) {
    SCOPED_TRACE(w.name);
    EXPECT_EQ(head_on_field(w.name).help, w.help);
    EXPECT_TRUE(head_on_field(w.name).from_material);
    EXPECT_EQ(cmd->get_option(option_name(w.name))->get_description(), w.help);
    for (const gas::GasField& g : gas::gas_fields()) {
      if (std::string(g.name) != w.name) continue;
      EXPECT_EQ(g.help, w.help);
      EXPECT_STREQ(g.unit, w.unit);
      ++compared;
    }
  }
  EXPECT_EQ(compared, 5);  // the gas takes one radius and one mass
  EXPECT_EQ(gas::gas_field("law").help, head_on_field("law").help);
  EXPECT_EQ(cmd->get_option("--law")->get_description(), head_on_field("law").help);
  // The one-end rows (not eps and sweep's, which take "both" too) are one maker's as well.
  EXPECT_EQ(gas::gas_field("end").help, dem::dem_field("end").help);
  EXPECT_EQ(gas::gas_field("end").words, end_names());
  for (const std::string& law : law_names())
    EXPECT_NE(head_on_field("law").help.find(law), std::string::npos) << law;
}

using scene_errors::scene_error;

const std::string kSweep = "output = \"out/s\"\n[[sweep]]\nname = \"s\"\nzeta = [0.1]\n";

TEST(HeadOnParameters, ASceneSweepReadsItsLawWithTheRowsCheck) {
  const HeadOnField& law = head_on_field("law");
  ASSERT_TRUE(law.is_key());
  for (const std::string& name : law.words) {
    const scene::Scene s = scene::parse_scene(kSweep + "law = \"" + name + "\"\n", "s.toml");
    EXPECT_EQ(law_name(scene::tasks_of<scene::Sweep>(s, "sweep").at(0)->law), name);
  }
  try {
    law.check_word("no-such-law");
    ADD_FAILURE() << "no-such-law passes the check";
  } catch (const InvalidInput& e) {
    EXPECT_NE(scene_error(kSweep + "law = \"no-such-law\"\n").find(std::string("law: ") + e.what()),
              std::string::npos);
  }
}

TEST(HeadOnParameters, ASceneSweepRefusesTheRowsItTakesOtherwise) {
  for (const HeadOnField& f : head_on_fields()) {
    if (f.is_key()) continue;
    SCOPED_TRACE(f.name);
    // The scene's own tolerance is a top-level key, not the section's.
    EXPECT_NE(scene_error(kSweep + f.name + " = 0.25\n").find(std::string(f.name) + ": unknown key"),
              std::string::npos);
  }
}

}  // namespace
}  // namespace restitution
