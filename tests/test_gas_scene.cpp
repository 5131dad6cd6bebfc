// SPDX-License-Identifier: BSD-3-Clause
// The [[gas]] scene section (docs/scenes.md): its keys are read and checked (a misspelled one is refused by
// name), and scenes/gas.toml writes both curves, their plots and the summary the command would compute.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.hpp"
#include "restitution/errors.hpp"
#include "scene/scene.hpp"
#include "scene/scene_gas.hpp"
#include "scene/scene_sections.hpp"
#include "scene_errors.hpp"

namespace restitution::scene {
namespace {

const std::string kHead = R"(output = "out/gas"
[materials.pe]
young_modulus = 1e8
poisson_ratio = 0.4
density = 920.0
radius = 0.005
dissipative_constant = 1e-5
)";

const std::string kGas = R"([[gas]]
name = "g"
material = "pe"
packing_fraction = 0.1
rms_speed = 1.0
haff_times = 100.0
)";

std::string error_of(const std::string& text) {
  return scene_errors::scene_error(text, "gas.toml");
}

TEST(GasScene, ReadsTheSection) {
  const Scene s =
      parse_scene(kHead + kGas + "eps = 0.8\nvelocity = 2.0\nlaw = \"tsuji-hertz\"\n", "gas.toml");
  ASSERT_EQ(tasks_of<GasTask>(s, "gas").size(), 1U);
  EXPECT_EQ(tasks_of<GasTask>(s, "gas")[0]->material, "pe");
  const gas::GasInputs& g = tasks_of<GasTask>(s, "gas")[0]->inputs;
  EXPECT_EQ(g.law, "tsuji-hertz");
  EXPECT_EQ(*g.eps, 0.8);
  EXPECT_EQ(*g.velocity_m_s, 2.0);
  EXPECT_EQ(*g.packing_fraction, 0.1);
  EXPECT_EQ(*g.rms_speed_m_s, 1.0);
  EXPECT_EQ(*g.haff_times, 100.0);
  EXPECT_FALSE(g.duration_s);
  EXPECT_FALSE(g.radius_m);                                     // the material's, when the section runs
  EXPECT_FALSE(tasks_of<GasTask>(s, "gas")[0]->own_tolerance);  // the scene's, as run
}

TEST(GasScene, RefusesBadKeysByName) {
  EXPECT_NE(error_of(kHead + kGas + "packing_fracton = 0.1\n").find("packing_fracton"), std::string::npos);
  EXPECT_NE(error_of(kHead + kGas + "eps = 0.8\n").find("velocity"), std::string::npos);
  EXPECT_NE(error_of(kHead + kGas + "duration = 1.0\n").find("duration"), std::string::npos);
  EXPECT_NE(error_of(kHead + kGas + "temperature = 1e-3\n").find("rms_speed"), std::string::npos);
  std::string far = kGas;
  far.replace(far.find("0.1"), 3, "0.5");
  EXPECT_NE(error_of(kHead + far).find("packing_fraction"), std::string::npos);
  std::string unknown = kGas;
  unknown.replace(unknown.find("\"pe\""), 4, "\"ice\"");
  EXPECT_NE(error_of(kHead + unknown).find("material"), std::string::npos);
}

TEST(GasScene, ReadsTheSonineCoefficientInTheCommandsWords) {
  const auto inputs = [](const std::string& key) {
    const Scene s = parse_scene(kHead + kGas + key, "gas.toml");
    return tasks_of<GasTask>(s, "gas")[0]->inputs;
  };
  EXPECT_FALSE(inputs("").a2);
  EXPECT_FALSE(inputs("").a2_of_haff_eps || inputs("").a2_evolving);
  EXPECT_EQ(inputs("a2 = -0.0125\n").a2, -0.0125);
  EXPECT_TRUE(inputs("a2 = \"haff\"\n").a2_of_haff_eps);
  EXPECT_TRUE(inputs("a2 = \"evolving\"\n").a2_evolving);
  for (const char* bad : {"a2 = \"evolve\"\n", "a2 = true\n"}) {
    const std::string error = error_of(kHead + kGas + bad);
    EXPECT_NE(error.find("gas.toml:"), std::string::npos) << error;
    EXPECT_NE(error.find("a2"), std::string::npos) << error;
    EXPECT_NE(error.find("evolving"), std::string::npos) << error;
  }
}

TEST(GasScene, EvolvingSonineCoefficientIsAColumnOfTheSectionsTable) {
  const test_support::TempFolder folder;
  const std::filesystem::path scene = folder.path / "gas.toml";
  std::ofstream(scene) << kHead + kGas + "a2 = \"evolving\"\n";
  const auto outcome =
      test_support::run_cli("run " + scene.string() + " --out " + (folder.path / "out").string());
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  const std::string table = test_support::slurp((folder.path / "out" / "g.csv").string());
  const std::string header = table.substr(0, table.find('\n'));
  EXPECT_NE(header.find(",a2"), std::string::npos) << header;
}

// The driven gas (issue 49): the section's thermostat keys give the command's steady state in summary.json.
TEST(GasScene, ThermostatKeysDriveTheGasToItsSteadyState) {
  const std::string driven = kHead + kGas + "eps = 0.8\nvelocity = 2.0\nthermostat = \"langevin\"\n";
  const Scene s = parse_scene(driven + "bath_temperature = 1e-3\nbath_time = 0.5\n", "gas.toml");
  EXPECT_EQ(tasks_of<GasTask>(s, "gas")[0]->inputs.thermostat, "langevin");
  EXPECT_EQ(*tasks_of<GasTask>(s, "gas")[0]->inputs.bath_temperature_j, 1e-3);
  EXPECT_EQ(*tasks_of<GasTask>(s, "gas")[0]->inputs.bath_time_s, 0.5);
  EXPECT_NE(error_of(kHead + kGas + "thermostat = \"shaker\"\n").find("thermostat"), std::string::npos);
  EXPECT_NE(error_of(driven + "bath_time = -1\n").find("bath_time"), std::string::npos);
  const test_support::TempFolder folder;
  const std::filesystem::path scene = folder.path / "gas.toml";
  std::ofstream(scene) << driven + "bath_temperature = 1e-3\nbath_time = 0.5\n";
  const auto outcome =
      test_support::run_cli("run " + scene.string() + " --out " + (folder.path / "out").string());
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  const auto summary =
      nlohmann::json::parse(test_support::slurp((folder.path / "out" / "summary.json").string()));
  const auto command = nlohmann::json::parse(
      test_support::run_cli("gas --radius 0.005 --density 920 --eps 0.8 --velocity 2 --packing-fraction 0.1 "
                            "--rms-speed 1 --haff-times 100 --thermostat langevin --bath-temperature 1e-3 "
                            "--bath-time 0.5 --json")
          .out);
  EXPECT_EQ(summary.at("gas_g").at("steady_temperature_j"), command.at("steady_temperature_j"));
  EXPECT_EQ(summary.at("gas_g").at("steady_a2"), command.at("steady_a2"));
  // A bath without the thermostat's kind is refused by name.
  std::ofstream(scene) << kHead + kGas + "eps = 0.8\nvelocity = 2.0\npower = 1.0\n";
  const auto refused =
      test_support::run_cli("run " + scene.string() + " --out " + (folder.path / "o2").string());
  EXPECT_NE(refused.status, 0);
  EXPECT_NE(refused.err.find("thermostat"), std::string::npos) << refused.err;
}

TEST(GasScene, SceneWritesBothCurves) {
  const test_support::TempFolder folder;
  const auto outcome = test_support::run_cli(std::string("run ") + RESTITUTION_SOURCE_DIR +
                                             "/scenes/gas.toml --out " + folder.path.string());
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  for (const char* file : {"viscoelastic_gas.csv", "constant_eps_gas.csv", "report.md", "summary.json"}) {
    EXPECT_TRUE(std::filesystem::exists(folder.path / file)) << file;
  }
  const auto summary = nlohmann::json::parse(test_support::slurp((folder.path / "summary.json").string()));
  // 1000 τ₀: the viscoelastic gas near −5/3 (−1.69), the constant ε at Haff's −2 t/(τ₀ + t).
  const double viscoelastic = summary.at("gas_viscoelastic_gas").at("final_local_exponent").get<double>();
  const double constant = summary.at("gas_constant_eps_gas").at("final_local_exponent").get<double>();
  EXPECT_GT(viscoelastic, -1.75);
  EXPECT_LT(viscoelastic, -5.0 / 3.0);
  EXPECT_NEAR(constant, -2.0 * 1000.0 / 1001.0, 1e-10);
}

}  // namespace
}  // namespace restitution::scene
