// SPDX-License-Identifier: BSD-3-Clause
// The table of scene sections (scene/scene_sections.hpp) and the CLI's table of their writers
// (cli/scene/scene_section_writers.hpp) list the same kinds, each row complete, so that a section the parser
// reads always has a writer; a section of the table is parsed into Scene::sections in its place, thinned by
// `run --quick` through its row and run into an outcome per section.
#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <string>

#include "cli/scene/scene_section_writers.hpp"
#include "cli/scene/scene_text.hpp"
#include "scene/scene.hpp"
#include "scene/scene_adhesion.hpp"
#include "scene/scene_adhesion_run.hpp"
#include "scene/scene_damping_check.hpp"
#include "scene/scene_dem.hpp"
#include "scene/scene_fit.hpp"
#include "scene/scene_plan.hpp"
#include "scene/scene_run.hpp"
#include "scene/scene_sections.hpp"
#include "scene/scene_studies.hpp"

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
    // One way of writing each: in the file's order, or together with the rows sharing the function.
    EXPECT_NE(writer->write == nullptr, writer->write_together == nullptr) << kind.name;
  }
  EXPECT_FALSE(kinds.empty());
  for (const cli::SectionWriter& writer : cli::section_writers()) {
    EXPECT_TRUE(kinds.contains(writer.name)) << "a writer for [[" << writer.name << "]], which no row parses";
  }
  // The planner's rows add their collisions to the shared plan; the others solve their own or none.
  for (const char* planned : {"sweep", "trajectory", "dashpot"}) {
    ASSERT_NE(find_section_kind(planned), nullptr) << planned;
    EXPECT_NE(find_section_kind(planned)->plan, nullptr) << planned;
  }
  for (const char* own : {"calibration", "dem", "gas", "oblique", "fit"})
    EXPECT_EQ(find_section_kind(own)->plan, nullptr);
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
  ASSERT_EQ(s.sections.size(), 3U);
  EXPECT_EQ(s.sections[1].kind, "adhesion");
  EXPECT_EQ(s.sections[1].name, "first");
  EXPECT_EQ(s.sections[1].line, 10);
  EXPECT_EQ(s.sections[2].name, "second");
  EXPECT_EQ(s.sections.size(), 3U);
  EXPECT_EQ(s.sections[0].kind, "dashpot");  // the planner's rows come first in the table
  make_quick(s, 3);
  EXPECT_EQ(tasks_of<AdhesionTask>(s, "adhesion")[0]->speeds_m_s, (std::vector<double>{0.5, 2.5, 5.0}));
  const SceneResults results = run_scene(s, plan_scene(s));
  ASSERT_EQ(results.sections.size(), 3U);
  const auto& second = std::any_cast<const AdhesionOutcome&>(results.sections[2]);
  ASSERT_EQ(second.collisions.size(), 1U);
  EXPECT_EQ(second.contact.model, AdhesiveModel::jkr_lammps);
  EXPECT_EQ(second.collisions[0].outcome, AdhesiveOutcome::bounced);  // 2 m/s > v_s = 0.78 m/s
}

constexpr const char* kSteelScene = R"(output = "out/s"
tolerance = 1e-8
[materials.steel]
young_modulus = 2.1e11
poisson_ratio = 0.3
density = 7850.0
radius = 0.005
dissipative_constant = 5.8e-7
)";

// Every kind that used to be a member of Scene is a row now: read in the table's order (unnamed sections are
// numbered in it, whatever the file's order), thinned and run through its row into its own outcome type.
TEST(SceneSections, TheFormerMembersAreRowsRunIntoTheirOutcomes) {
  Scene s = parse_scene(std::string(kSteelScene) + R"([[stability]]
zeta = [0.1, 0.5, 1.0]
[[fit]]
v = [0.1, 0.3, 1.0, 3.0]
eps = [0.95, 0.93, 0.9, 0.87]
[[damping_check]]
recipes = ["pade-1-4"]
eps = [0.3, 0.5, 0.9]
speeds = [0.1, 1.0]
[[dem]]
code = "lammps"
material = "steel"
speeds = [0.3, 1.0, 3.0]
run = false
)",
                        "s.toml");
  std::vector<std::string> order;
  for (const SectionTask& section : s.sections) order.push_back(section.kind + ":" + section.name);
  // The table's order, numbered in it: dem, damping_check, ..., fit, work_precision, stability.
  EXPECT_EQ(order, (std::vector<std::string>{"dem:dem1", "damping_check:damping_check2", "fit:fit3",
                                             "stability:stability4"}));
  EXPECT_EQ(s.sections[0].line, 18);  // of [[dem]]
  make_quick(s, 2);
  EXPECT_EQ(tasks_of<DemTask>(s, "dem")[0]->inputs.speeds_m_s, (std::vector<double>{0.3, 3.0}));
  EXPECT_EQ(tasks_of<DampingCheckTask>(s, "damping_check")[0]->eps, (std::vector<double>{0.3, 0.9}));
  EXPECT_EQ(tasks_of<ExternalStudy>(s, "stability")[0]->zeta, (std::vector<double>{0.1, 1.0}));
  EXPECT_EQ(tasks_of<FitTask>(s, "fit")[0]->data.velocity_m_s.size(), 4U);  // measured data are kept whole
  const SceneResults results = run_scene(s, plan_scene(s));
  ASSERT_EQ(results.sections.size(), 4U);
  const auto& dem = std::any_cast<const DemOutcome&>(results.sections[0]);
  EXPECT_EQ(dem.comparison.predicted_eps.size(), 2U);
  EXPECT_FALSE(dem.comparison.measured.has_value());  // run = false
  const auto& grid = std::any_cast<const damping_check::GridResult&>(results.sections[1]);
  EXPECT_FALSE(grid.recipes.empty());
  const auto& fit = std::any_cast<const FitOutcome&>(results.sections[2]);
  EXPECT_EQ(fit.options.tolerance, s.tolerance);  // the scene's
  EXPECT_FALSE(fit.result.fits.empty());
  const auto& study = std::any_cast<const StudyOutcome&>(results.sections[3]);
  ASSERT_TRUE(study.stability.has_value());
  EXPECT_EQ(study.stability->tolerance, s.tolerance);
}

// Rows with the same words for the report's account of the work are named once: [[dem]] and
// [[damping_check]] share theirs.
TEST(SceneSections, SharedFooterWordsAreNamedOnce) {
  const Scene s = parse_scene(std::string(kSteelScene) + R"([[damping_check]]
recipes = ["pade-1-4"]
[[dem]]
code = "lammps"
material = "steel"
speeds = [1.0]
)",
                              "s.toml");
  EXPECT_TRUE(has_sections(s, "dem"));
  EXPECT_FALSE(has_sections(s, "gas"));
  EXPECT_EQ(cli::own_collisions_text(s),
            "not counted here: the [[dem]] and [[damping_check]] sections solve their own collisions");
}

// The planner's rows share one plan of distinct collisions across sections and kinds: a collision two
// sections ask for is one job (solved with the union of their ends and the trajectory one of them keeps),
// each section's points name it, and the sections of other rows add nothing to the plan.
TEST(SceneSections, ThePlannersRowsShareOneJobPerDistinctCollision) {
  const Scene s = parse_scene(std::string(kSteelScene) + R"([[dashpot]]
damping_ratio = [0.5, 2.0]
ends = "naive"
[[sweep]]
name = "a"
zeta = [0.5, 1.0]
ends = "naive"
[[fit]]
v = [0.1, 0.3, 1.0, 3.0]
eps = [0.95, 0.93, 0.9, 0.87]
[[trajectory]]
zeta = 1.0
ends = "delayed-recovery"
[[sweep]]
name = "b"
zeta = [1.0, 2.0]
ends = "delayed-recovery"
[[calibration]]
eps = 0.8
velocity = 1.0
)",
                              "s.toml");
  const Plan plan = plan_scene(s);
  ASSERT_EQ(plan.points.size(), s.sections.size());
  // ζ = 0.5, 1, 2 of viscoelastic Hertz and r = 0.5 of the dash-pot (r = 2 has no naive end): four jobs for
  // the seven points asked.
  EXPECT_EQ(plan.jobs.size(), 4U);
  const auto points_of = [&](std::string_view name) -> const std::vector<PlannedPoint>& {
    for (std::size_t i = 0; i < s.sections.size(); ++i) {
      if (s.sections[i].name == name) return plan.points[i];
    }
    throw std::logic_error("no section " + std::string(name));
  };
  const std::size_t one = points_of("a")[1].job;
  EXPECT_EQ(points_of("b")[0].job, one);
  EXPECT_EQ(points_of("trajectory3")[0].job,
            one);  // every section counts in the numbering, in the table's order
  EXPECT_EQ(plan.jobs[one].ends, EndSet::both());  // naive for "a", delayed recovery for the others
  EXPECT_TRUE(plan.jobs[one].keep_trajectory);
  EXPECT_FALSE(plan.jobs[points_of("a")[0].job].keep_trajectory);
  EXPECT_EQ(points_of("dashpot5")[1].job, kNoJob);
  EXPECT_TRUE(points_of("fit6").empty());
  EXPECT_TRUE(points_of("calibration4").empty());
  // The solved plan reaches each section's outcome: the trajectory and sweep "b" read the same collision.
  const SceneResults results = run_scene(s, plan);
  const auto trajectory = outcomes_of<TrajectoryOutcome>(s, results, "trajectory");
  const auto sweeps = outcomes_of<SweepOutcome>(s, results, "sweep");
  ASSERT_EQ(trajectory.size(), 1U);
  ASSERT_EQ(sweeps.size(), 2U);
  EXPECT_EQ(trajectory[0]->result[CollisionEnd::delayed_recovery]->eps,
            sweeps[1]->results[0][CollisionEnd::delayed_recovery]->eps);
  EXPECT_FALSE(trajectory[0]->result.trajectory.empty());
  // The calibration's root finding counts with the plan's collisions, the [[fit]]'s solves do not.
  const auto calibration = outcomes_of<CalibrationOutcome>(s, results, "calibration");
  EXPECT_EQ(results.collisions,
            plan.jobs.size() + static_cast<std::size_t>(calibration[0]->calibration.solves));
}

// The sections' order in the file changes neither the plan's distinct collisions nor which point names which.
TEST(SceneSections, ThePlanDoesNotDependOnTheFilesOrder) {
  const std::string sweep = "[[sweep]]\nname = \"s\"\nzeta = [0.5, 1.0]\n";
  const std::string trajectory = "[[trajectory]]\nname = \"t\"\nzeta = 0.5\n";
  const std::string dashpot = "[[dashpot]]\nname = \"d\"\ndamping_ratio = [0.5]\n";
  const Scene a = parse_scene("output = \"o\"\n" + sweep + trajectory + dashpot, "a.toml");
  const Scene b = parse_scene("output = \"o\"\n" + dashpot + trajectory + sweep, "b.toml");
  const Plan pa = plan_scene(a);
  const Plan pb = plan_scene(b);
  ASSERT_EQ(pa.jobs.size(), 3U);
  EXPECT_EQ(pb.jobs.size(), pa.jobs.size());
  for (std::size_t i = 0; i < a.sections.size(); ++i) {
    EXPECT_EQ(a.sections[i].name, b.sections[i].name);  // read in the table's order, not the file's
    ASSERT_EQ(pa.points[i].size(), pb.points[i].size());
    for (std::size_t k = 0; k < pa.points[i].size(); ++k) EXPECT_EQ(pa.points[i][k].job, pb.points[i][k].job);
  }
}

}  // namespace
}  // namespace restitution::scene
