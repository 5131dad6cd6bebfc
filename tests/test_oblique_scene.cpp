// SPDX-License-Identifier: BSD-3-Clause
// The [[oblique]] scene section (docs/scenes.md, docs/oblique.md): its keys are read and checked (a
// misspelled one is refused by name), and scenes/oblique.toml writes every model's sweep with the numbers
// `restitution oblique` gives for the same impact, Maw's diagram, a report line per model and the summary.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "restitution/errors.hpp"
#include "scene/scene.hpp"
#include "scene/scene_oblique.hpp"
#include "scene/scene_sections.hpp"
#include "scene_errors.hpp"

namespace restitution::scene {
namespace {

const std::string kHead = R"(output = "out/oblique"
[materials.steel]
young_modulus = 2e11
poisson_ratio = 0.3
density = 7800.0
radius = 1e-3
dissipative_constant = 1e-7
)";

const std::string kOblique = R"([[oblique]]
name = "o"
material = "steel"
friction = 0.3
angles = [10.0, 40.0]
)";

std::string error_of(const std::string& text) {
  return scene_errors::scene_error(text, "oblique.toml");
}

TEST(ObliqueScene, ReadsTheSection) {
  const Scene s = parse_scene(
      kHead + kOblique +
          "model = [\"mindlin\", \"linear_nohistory\"]\nspins = { from = -100.0, to = 100.0, "
          "points = 3 }\nwall = true\nimpact_velocity = 2.0\ntangential_damping = 0.5\nplot = false\n",
      "oblique.toml");
  ASSERT_EQ(tasks_of<ObliqueTask>(s, "oblique").size(), 1U);
  const ObliqueTask& t = *tasks_of<ObliqueTask>(s, "oblique")[0];
  EXPECT_EQ(t.material, "steel");
  EXPECT_EQ(t.models, (std::vector<std::string>{"mindlin", "linear_nohistory"}));
  EXPECT_EQ(t.inputs.friction, std::optional<double>(0.3));
  EXPECT_EQ(t.inputs.angles_deg, (std::vector<double>{10.0, 40.0}));
  EXPECT_EQ(t.inputs.spins_rad_s, (std::vector<double>{-100.0, 0.0, 100.0}));
  EXPECT_TRUE(t.inputs.wall);
  EXPECT_EQ(t.inputs.speed_m_s, 2.0);
  EXPECT_EQ(t.inputs.tangential_damping, 0.5);
  EXPECT_FALSE(t.plot);
  EXPECT_EQ(t.inputs.tolerance, 1e-10);
  const Scene defaults = parse_scene(kHead + kOblique, "oblique.toml");
  EXPECT_EQ(tasks_of<ObliqueTask>(defaults, "oblique")[0]->models,
            std::vector<std::string>{"mindlin"});  // as dem's
  EXPECT_EQ(tasks_of<ObliqueTask>(defaults, "oblique")[0]->inputs.spins_rad_s, std::vector<double>{0.0});
}

TEST(ObliqueScene, RefusesBadKeysByName) {
  const auto refused = [](const std::string& extra, const std::string& key) {
    const std::string message = error_of(kHead + kOblique + extra);
    EXPECT_NE(message.find(key), std::string::npos) << extra << ": " << message;
  };
  refused("frictoin = 0.3\n", "frictoin");  // misspelled: "unknown key", named
  refused("frictoin = 0.3\n", "unknown key");
  refused("model = \"mindlim\"\n", "mindlim");
  refused("spins = [1.0, nan]\n", "spins");
  refused("impact_velocity = 0.0\n", "impact_velocity");
  refused("tolerance = 1.0\n", "tolerance");
  refused("mindlin_stiffness = -1.0\n", "mindlin_stiffness");
  refused("model = \"yade_mindlin\"\n", "model");  // not run here: one list with the command
  refused("wall = true\nwall_young_modulus = 2e11\n", "wall_poisson_ratio");
  std::string steep = kOblique;
  steep.replace(steep.find("40.0"), 4, "90.0");
  EXPECT_NE(error_of(kHead + steep).find("angles"), std::string::npos);
  std::string no_friction = kOblique;
  no_friction.erase(no_friction.find("friction = 0.3\n"), 15);
  EXPECT_NE(error_of(kHead + no_friction).find("friction"), std::string::npos);
  EXPECT_NE(error_of(kHead + "[[obliqe]]\nmaterial = \"steel\"\n").find("obliqe"), std::string::npos);
}

// The fields of a CSV line.
std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  for (std::string f; std::getline(in, f, ',');) fields.push_back(f);
  return fields;
}

TEST(ObliqueScene, ShippedSceneWritesTheCommandsNumbers) {
  const test_support::TempFolder folder;
  const auto outcome = test_support::run_cli(std::string("run ") + RESTITUTION_SOURCE_DIR +
                                             "/scenes/oblique.toml --out " + folder.path.string());
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  for (const char* file : {"steel_on_wall.csv", "report.md", "summary.json"}) {
    EXPECT_TRUE(std::filesystem::exists(folder.path / file)) << file;
  }
  const auto lines =
      test_support::lines_of(test_support::slurp((folder.path / "steel_on_wall.csv").string()));
  ASSERT_EQ(lines.size(), 1U + 2U * 29U * 2U);  // two models, 29 angles, two spins
  EXPECT_EQ(lines[0].rfind("tangential_model,angle_deg,", 0), 0U);
  // A mindlin row and a linear_history row against the command with the scene's arguments.
  const std::string command =
      "oblique --young-modulus 2e11 --poisson-ratio 0.3 --radius 1e-3 --density 7800 --dissipative-constant "
      "1e-9 "
      "--wall --wall-young-modulus 2e11 --wall-poisson-ratio 0.3 --friction 0.3 --impact-velocity 1 --json";
  for (const std::size_t row : {std::size_t{12}, std::size_t{58 + 31}}) {
    const std::vector<std::string> f = fields_of(lines[row]);
    ASSERT_EQ(f.size(), 16U);
    EXPECT_EQ(f[15], "solved");
    const std::string model = f[0] == "mindlin" ? " --tangential mindlin"
                                                : " --tangential linear_history --tangential-stiffness 2.2e6";
    const auto one = test_support::run_cli(command + model + " --angle " + f[1] + " --spin " + f[11]);
    ASSERT_EQ(one.status, 0) << one.err;
    const auto impact = nlohmann::json::parse(one.out)["impacts"][0];
    EXPECT_EQ(std::stod(f[3]), impact["tangential_restitution"].get<double>()) << lines[row];
    EXPECT_EQ(std::stod(f[5]), impact["spin_rad_s"].get<double>()) << lines[row];
    EXPECT_EQ(std::stod(f[13]), impact["psi_out"].get<double>()) << lines[row];
  }
  const auto summary = nlohmann::json::parse(test_support::slurp((folder.path / "summary.json").string()));
  const auto& section = summary["oblique_steel_on_wall"];
  EXPECT_EQ(section["impacts"].get<int>(), 58);
  EXPECT_NEAR(section["maw_chi"].get<double>(), 3.5 * 0.7 / 1.7, 1e-15);
  EXPECT_TRUE(section["sticking_restitution"].contains("mindlin"));
  const std::string report = test_support::slurp((folder.path / "report.md").string());
  EXPECT_NE(report.find("* mindlin: e_t from"), std::string::npos);
  EXPECT_NE(report.find("* linear_history: e_t from"), std::string::npos);
  EXPECT_NE(report.find("a sphere on a wall of Y = 2e+11 Pa"), std::string::npos);
  EXPECT_NE(report.find("sticking limit e_t(μ → ∞) = "), std::string::npos);
}

// Issue 44 item 8: the README's steel (A = 1e-7 s) with a plot ran the sticking-limit solve at μ = 1e12,
// which failed and took the section with it; now the plot has its limit, and `plot = false` skips the
// limit's solve altogether (null in summary.json, none in the report). A material without dissipation is
// refused, naming it (no silent elastic default).
TEST(ObliqueScene, ReadmeSteelPlotsAndPlotFalseSkipsTheStickingLimit) {
  for (const bool plot : {true, false}) {
    const test_support::TempFolder folder;
    const std::string scene = (folder.path / "s.toml").string();
    {
      std::ofstream out(scene);
      out << kHead << kOblique
          << "wall = true\nmodel = [\"mindlin\", \"linear_nohistory\", \"mindlin/force\"]\n"
          << "tangential_damping = 0.5\nplot = " << (plot ? "true" : "false") << "\n";
    }
    const auto outcome = test_support::run_cli("run " + scene + " --out " + (folder.path / "out").string());
    ASSERT_EQ(outcome.status, 0) << outcome.err;
    const auto summary =
        nlohmann::json::parse(test_support::slurp((folder.path / "out" / "summary.json").string()));
    const auto& limits = summary["oblique_o"]["sticking_restitution"];
    const std::string report = test_support::slurp((folder.path / "out" / "report.md").string());
    for (const char* model : {"mindlin", "linear_nohistory", "mindlin/force"}) {
      EXPECT_EQ(limits[model].is_number(), plot) << model << ": " << limits.dump();
    }
    EXPECT_EQ(report.find("sticking limit") != std::string::npos, plot) << report;
    EXPECT_NE(report.find("a sphere on a rigid wall"), std::string::npos) << report;
    EXPECT_EQ(std::filesystem::exists(folder.path / "out" / "o.png"), plot);
  }
  std::string elastic = kHead;
  elastic.erase(elastic.find("dissipative_constant = 1e-7\n"));
  EXPECT_NE(error_of(elastic + kOblique).find("dissipation"), std::string::npos)
      << error_of(elastic + kOblique);
}

}  // namespace
}  // namespace restitution::scene
