// SPDX-License-Identifier: BSD-3-Clause
// The table of scene sections (scene/scene_sections.hpp) and the CLI's table of their writers
// (cli/scene/scene_section_writers.hpp) list the same kinds, each row complete, so that a section the parser
// reads always has a writer; a section of the table is parsed into Scene::sections in its place, thinned by
// `run --quick` through its row and run into an outcome per section.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "cli/scene/scene_section_writers.hpp"
#include "scene/scene.hpp"
#include "scene/scene_adhesion.hpp"
#include "scene/scene_adhesion_run.hpp"
#include "scene/scene_plan.hpp"
#include "scene/scene_run.hpp"
#include "scene/scene_sections.hpp"

namespace restitution::scene {
namespace {

TEST(SceneSections, EveryKindHasAWriterAndEveryWriterAKind) {
  std::set<std::string> kinds;
  for (const SectionKind& kind : section_kinds()) {
    EXPECT_TRUE(kinds.insert(kind.name).second) << kind.name << " twice";
    EXPECT_NE(kind.parse, nullptr) << kind.name;
    EXPECT_NE(kind.run, nullptr) << kind.name;
    EXPECT_NE(kind.quick, nullptr) << kind.name;
    EXPECT_NE(kind.own_solves, nullptr) << kind.name;
    EXPECT_EQ(find_section_kind(kind.name), &kind);
    const cli::SectionWriter* writer = cli::find_section_writer(kind.name);
    ASSERT_NE(writer, nullptr) << "[[" << kind.name << "]] is parsed but has no writer";
    EXPECT_NE(writer->write, nullptr) << kind.name;
  }
  EXPECT_FALSE(kinds.empty());
  for (const cli::SectionWriter& writer : cli::section_writers()) {
    EXPECT_TRUE(kinds.contains(writer.name)) << "a writer for [[" << writer.name << "]], which no row parses";
  }
  EXPECT_EQ(find_section_kind("sweep"), nullptr);  // the planner's sections keep their own members
  EXPECT_EQ(cli::find_section_writer("no_such_section"), nullptr);
}

TEST(SceneSections, ParsedInPlaceThinnedAndRunThroughTheirRow) {
  Scene s = parse_scene(R"(output = "out/s"
[materials.ice]
young_modulus = 7e9
poisson_ratio = 0.25
density = 920.0
radius = 1.5e-6
dissipative_constant = 0.0
[[dashpot]]
damping_ratio = [0.5]
[[adhesion]]
name = "first"
material = "ice"
surface_energy = 0.19
speeds = { from = 0.5, to = 5.0, points = 10 }
[[adhesion]]
name = "second"
material = "ice"
model = "jkr-lammps"
surface_energy = 0.19
speeds = [2.0]
)",
                        "s.toml");
  ASSERT_EQ(s.sections.size(), 2U);
  EXPECT_EQ(s.sections[0].kind, "adhesion");
  EXPECT_EQ(s.sections[0].name, "first");
  EXPECT_EQ(s.sections[0].line, 10);
  EXPECT_EQ(s.sections[1].name, "second");
  EXPECT_EQ(s.dashpots.size(), 1U);
  make_quick(s, 3);
  EXPECT_EQ(tasks_of<AdhesionTask>(s, "adhesion")[0]->speeds_m_s, (std::vector<double>{0.5, 2.5, 5.0}));
  const SceneResults results = run_scene(s, plan_scene(s));
  ASSERT_EQ(results.sections.size(), 2U);
  const auto& second = std::any_cast<const AdhesionOutcome&>(results.sections[1]);
  ASSERT_EQ(second.collisions.size(), 1U);
  EXPECT_EQ(second.contact.model, AdhesiveModel::jkr_lammps);
  EXPECT_EQ(second.collisions[0].outcome, AdhesiveOutcome::bounced);  // 2 m/s > v_s = 0.78 m/s
}

}  // namespace
}  // namespace restitution::scene
