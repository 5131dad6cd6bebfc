// SPDX-License-Identifier: BSD-3-Clause
// The [[adhesion]] scene section (docs/scenes.md, docs/adhesion.md): its keys are read and checked (a
// misspelled, missing or negative one is refused by name), its rows are the numbers `restitution eps
// --adhesion
// --json` gives for the same inputs, its calibrated damping is `calibrate --adhesion`'s, and the shipped
// scenes/adhesion.toml runs with --quick, its elastic sticking speeds the closed form sqrt(2W/m_eff).
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "restitution/errors.hpp"
#include "scene/scene.hpp"
#include "scene/scene_adhesion.hpp"
#include "scene/scene_sections.hpp"
#include "scene_errors.hpp"

namespace restitution::scene {
namespace {

// µm ice of docs/adhesion.md §7, with a dissipative constant (and without one, `elastic_ice`).
const std::string kHead = R"(output = "out/adhesion"
tolerance = 1e-10
[materials.ice]
young_modulus = 7e9
poisson_ratio = 0.25
density = 920.0
radius = 1.5e-6
dissipative_constant = 1e-9
[materials.bare_ice]
young_modulus = 7e9
poisson_ratio = 0.25
density = 920.0
radius = 1.5e-6
)";
const std::string kMaterialArguments =
    " --young-modulus 7e9 --poisson-ratio 0.25 --density 920 --radius 1.5e-6";

const std::string kSection = R"([[adhesion]]
name = "a"
material = "ice"
surface_energy = 0.19
speeds = [0.5, 3.0]
)";

std::string error_of(const std::string& text) {
  return scene_errors::scene_error(text, "adhesion.toml");
}

TEST(AdhesionScene, ReadsTheSection) {
  const Scene s = parse_scene(kHead + kSection + "model = \"jkr-lammps\"\ntolerance = 1e-9\ntitle = \"T\"\n",
                              "adhesion.toml");
  const std::vector<const AdhesionTask*> tasks = tasks_of<AdhesionTask>(s, "adhesion");
  ASSERT_EQ(tasks.size(), 1U);
  const AdhesionTask& t = *tasks[0];
  EXPECT_EQ(t.material, "ice");
  EXPECT_EQ(t.model, AdhesiveModel::jkr_lammps);
  EXPECT_EQ(t.surface_energy_j_per_m2, 0.19);
  EXPECT_EQ(t.speeds_m_s, (std::vector<double>{0.5, 3.0}));
  EXPECT_EQ(t.tolerance, 1e-9);
  EXPECT_EQ(t.title, "T");
  EXPECT_FALSE(t.eps.has_value());
  const Scene ranged = parse_scene(
      kHead +
          "[[adhesion]]\nmaterial = \"bare_ice\"\nmodel = \"dmt\"\nsurface_energy = 0.19\n"
          "eps = 0.5\nvelocity = 2.0\nspeeds = { from = 1.0, to = 100.0, points = 3, spacing = \"log\" }\n",
      "adhesion.toml");
  EXPECT_EQ(tasks_of<AdhesionTask>(ranged, "adhesion")[0]->speeds_m_s.size(), 3U);
}

TEST(AdhesionScene, RefusesBadKeysByName) {
  const auto refused = [](const std::string& section, const std::string& key) {
    const std::string message = error_of(kHead + section);
    EXPECT_NE(message.find(key), std::string::npos) << section << ": " << message;
    EXPECT_NE(message.find("adhesion.toml:"), std::string::npos) << message;
  };
  refused(kSection + "tolerence = 1e-8\n", "adhesion[0].tolerence");  // misspelled: "unknown key", named
  refused(kSection + "modle = \"jkr\"\n", "modle");
  refused(kSection + "model = \"jkr-lamps\"\n", "model");
  std::string no_gamma = kSection;
  no_gamma.erase(no_gamma.find("surface_energy = 0.19\n"), 22);
  refused(no_gamma, "adhesion[0].surface_energy: missing");
  std::string negative = kSection;
  negative.replace(negative.find("0.19"), 4, "-0.19");
  refused(negative, "adhesion[0].surface_energy");
  refused("[[adhesion]]\nmaterial = \"ice\"\nsurface_energy = 0.19\nspeeds = [1.0, -2.0]\n", "speeds");
  refused("[[adhesion]]\nmaterial = \"ice\"\nsurface_energy = 0.19\n", "adhesion[0].speeds: missing");
  refused(kSection + "tolerance = 0.5\n", "adhesion[0].tolerance");
  refused(kSection + "eps = 0.5\n", "adhesion[0].eps");  // without velocity
  refused(kSection + "eps = 1.5\nvelocity = 1.0\n", "adhesion[0].eps");
  refused(kSection + "model = \"sjkr\"\n", "adhesion[0].surface_energy");  // sjkr takes k_c
  refused(kSection + "cohesion_energy_density = 1e5\n", "cohesion_energy_density");
  refused(
      "[[adhesion]]\nmaterial = \"ice\"\nmodel = \"sjkr\"\ncohesion_energy_density = 1e5\neps = 0.5\n"
      "velocity = 2.0\nspeeds = [1.0]\n",
      "adhesion[0].eps");  // sjkr's damping is not calibrated (as `calibrate --adhesion`)
  refused("[[adhesion]]\nmaterial = \"bare_ice\"\nsurface_energy = 0.19\nspeeds = [1.0]\n", "material");
  refused("[[adhesion]]\nmaterial = \"glass\"\nsurface_energy = 0.19\nspeeds = [1.0]\n", "[materials.glass]");
  refused(
      kSection + "[[adhesion]]\nname = \"a\"\nmaterial = \"ice\"\nsurface_energy = 0.19\nspeeds = [1.0]\n",
      "used twice");
}

std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  for (std::string f; std::getline(in, f, ',');) fields.push_back(f);
  return fields;
}

// Runs a scene of the given sections into a fresh folder; returns the folder's summary.json.
nlohmann::json run_scene_text(const test_support::TempFolder& folder, const std::string& sections) {
  const std::string scene = (folder.path / "s.toml").string();
  {
    std::ofstream out(scene);
    out << kHead << sections;
  }
  const auto outcome = test_support::run_cli("run " + scene + " --out " + (folder.path / "out").string());
  EXPECT_EQ(outcome.status, 0) << outcome.err;
  return nlohmann::json::parse(test_support::slurp((folder.path / "out" / "summary.json").string()));
}

// Every column of every row, and the sticking speed, equal what `eps --adhesion --json` prints for the same
// model, material, γ, A and tolerance: one computation behind both (stuck and bounced rows, three models).
TEST(AdhesionScene, RowsAreTheEpsCommandsNumbers) {
  const test_support::TempFolder folder;
  std::string sections;
  for (const char* model : {"jkr", "jkr-lammps", "dmt"}) {
    sections += fmt::format(
        "[[adhesion]]\nname = \"{}\"\nmaterial = \"ice\"\nmodel = \"{}\"\nsurface_energy = 0.19\n"
        "speeds = [0.5, 6.0]\n",
        std::string(model) == "jkr-lammps" ? "jkr_lammps" : model, model);
  }
  const nlohmann::json summary = run_scene_text(folder, sections);
  const char* columns[] = {"velocity_m_per_s",  "outcome",        "eps",
                           "one_minus_eps",     "contact_time_s", "max_compression_m",
                           "hysteresis_work_j", "viscous_work_j", "kinetic_to_adhesion_energy"};
  for (const std::string model : {"jkr", "jkr-lammps", "dmt"}) {
    const std::string name = model == "jkr-lammps" ? "jkr_lammps" : model;
    const auto lines =
        test_support::lines_of(test_support::slurp((folder.path / "out" / (name + ".csv")).string()));
    ASSERT_EQ(lines.size(), 3U) << model;
    EXPECT_EQ(fields_of(lines[0]).front(), columns[0]);
    for (std::size_t row = 1; row < lines.size(); ++row) {
      const std::vector<std::string> f = fields_of(lines[row]);
      ASSERT_EQ(f.size(), 10U);
      const auto one = test_support::run_cli(
          "eps --adhesion " + model + " --surface-energy 0.19" + kMaterialArguments +
          " --dissipative-constant 1e-9 --tolerance 1e-10" + " --velocity " + f[0] + " --json");
      ASSERT_EQ(one.status, 0) << one.err;
      const auto json = nlohmann::json::parse(one.out);
      EXPECT_EQ(f[1], json["outcome"].get<std::string>()) << model << " " << lines[row];
      for (std::size_t c = 2; c < 9; ++c)
        EXPECT_EQ(std::stod(f[c]), json[columns[c]].get<double>()) << model << " " << columns[c];
      EXPECT_EQ(std::stod(f[9]), json["sticking_speed_m_per_s"].get<double>()) << model;
      const auto& section = summary["adhesion_" + name];
      EXPECT_EQ(section["sticking_speed_m_per_s"].get<double>(),
                json["sticking_speed_m_per_s"].get<double>());
      EXPECT_EQ(section["break_overlap_m"].get<double>(), json["break_overlap_m"].get<double>());
      EXPECT_EQ(section["elastic_hysteresis_work_j"].get<double>(),
                json["elastic_hysteresis_work_j"].get<double>());
    }
    EXPECT_EQ(fields_of(lines[1])[1], "stuck") << model << ": 0.5 m/s is below its v_s";
    EXPECT_EQ(fields_of(lines[2])[1], "bounced") << model << ": 6 m/s is above its v_s";
  }
}

// eps at a velocity: the damping `calibrate --adhesion` finds, and ε re-solved there is the requested one.
TEST(AdhesionScene, EpsAtVelocityIsCalibrateAdhesionsDamping) {
  const test_support::TempFolder folder;
  const nlohmann::json summary =
      run_scene_text(folder,
                     "[[adhesion]]\nname = \"c\"\nmaterial = \"bare_ice\"\nsurface_energy = 0.19\neps = 0.5\n"
                     "velocity = 5.0\nspeeds = [5.0]\n");
  const auto one =
      test_support::run_cli("calibrate --adhesion jkr --surface-energy 0.19 --eps 0.5 --velocity 5" +
                            kMaterialArguments + " --tolerance 1e-10 --json");
  ASSERT_EQ(one.status, 0) << one.err;
  const auto json = nlohmann::json::parse(one.out);
  EXPECT_EQ(summary["adhesion_c"]["dissipative_constant_s"].get<double>(),
            json["dissipative_constant_s"].get<double>());
  const auto lines = test_support::lines_of(test_support::slurp((folder.path / "out" / "c.csv").string()));
  ASSERT_EQ(lines.size(), 2U);
  EXPECT_NEAR(std::stod(fields_of(lines[1])[2]), 0.5, 1e-8);
}

// The shipped scene with --quick: every section's files, and the elastic sticking speeds are the closed form
// v_s = sqrt(2W/m_eff) of the break rule's hysteresis work (docs/adhesion.md §3), their ratio 0.7027567572.
TEST(AdhesionScene, ShippedSceneRunsQuick) {
  const test_support::TempFolder folder;
  const auto outcome = test_support::run_cli(std::string("run ") + RESTITUTION_SOURCE_DIR +
                                             "/scenes/adhesion.toml --quick --out " + folder.path.string());
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  for (const char* file :
       {"ice_jkr.csv", "ice_jkr_lammps.csv", "ice_jkr_damped.csv", "report.md", "summary.json"})
    EXPECT_TRUE(std::filesystem::exists(folder.path / file)) << file;
  const auto summary = nlohmann::json::parse(test_support::slurp((folder.path / "summary.json").string()));
  const double m_eff = 0.5 * 920.0 * 4.0 / 3.0 * M_PI * std::pow(1.5e-6, 3);
  for (const char* name : {"adhesion_ice_jkr", "adhesion_ice_jkr_lammps"}) {
    const auto& s = summary[name];
    EXPECT_EQ(s["speeds"].get<int>(), 6);  // --quick: six points of the range
    const double closed = std::sqrt(2.0 * s["elastic_hysteresis_work_j"].get<double>() / m_eff);
    EXPECT_NEAR(s["sticking_speed_m_per_s"].get<double>() / closed, 1.0, 1e-12) << name;
  }
  EXPECT_NEAR(summary["adhesion_ice_jkr_lammps"]["sticking_speed_m_per_s"].get<double>() /
                  summary["adhesion_ice_jkr"]["sticking_speed_m_per_s"].get<double>(),
              0.7027567572, 1e-10);
  const double damped = summary["adhesion_ice_jkr_damped"]["sticking_speed_m_per_s"].get<double>();
  EXPECT_GT(damped,
            summary["adhesion_ice_jkr"]["sticking_speed_m_per_s"].get<double>());  // damping only adds
  const std::string report = test_support::slurp((folder.path / "report.md").string());
  EXPECT_NE(report.find("Sticking speed v_s = "), std::string::npos);
  EXPECT_NE(report.find("the [[adhesion]] sections integrate their own collisions"), std::string::npos);
}

}  // namespace
}  // namespace restitution::scene
