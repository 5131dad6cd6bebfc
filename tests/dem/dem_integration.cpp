// SPDX-License-Identifier: BSD-3-Clause
// Runs LAMMPS and LIGGGHTS themselves on head-on collisions of two equal spheres, fed exactly the lines
// `restitution dem --json` prints, and checks the ε they measure against restitution's: two materials, both
// ends, three impact speeds per calibration (the calibration speed, a quarter and four times it).
// Both codes integrate with velocity-Verlet, first order in the time step here (the damping force is taken
// at the half-step velocity), so dem/code_runner.hpp runs each deck at dt = T/2000 and T/20000, T the natural
// time of the fastest collision, and extrapolates: ε = (10 ε_fine - ε_coarse) / 9.
// Two more cases add Coulomb friction (--friction 0.5): the codes must accept the tangential lines, and a
// head-on collision must still end with the frictionless ε.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "dem/code_runner.hpp"
#include "dem/deck.hpp"
#include "restitution/material.hpp"

namespace {

using nlohmann::json;

struct Material {
  const char* name;
  double young_pa, poisson, radius_m, density_kg_m3, eps, velocity_m_s;
};

// Hard steel beads and soft rubber balls: β and the speeds differ by orders of magnitude.
constexpr std::array<Material, 2> kMaterials{{
    {"steel", 2.1e11, 0.3, 0.005, 7850.0, 0.9, 1.0},
    {"rubber", 1e7, 0.45, 0.01, 1100.0, 0.6, 2.0},
}};

struct Case {
  std::string code;
  Material material;
  std::string end;
  double friction = 0.0;  // --friction: the Coulomb mu of the tangential model
};

// Names the case in test listings (instead of googletest's byte dump of the struct).
void PrintTo(const Case& c, std::ostream* os) {
  *os << c.code << " " << c.material.name << " " << c.end << " friction " << c.friction;
}

std::string case_name(const testing::TestParamInfo<Case>& info) {
  std::string end = info.param.end == "naive" ? "naive" : "delayed";
  return info.param.code + "_" + info.param.material.name + "_" + end +
         (info.param.friction > 0.0 ? "_friction" : "");
}

restitution::dem::Pair pair_of(const Material& m) {
  restitution::Material material;
  material.young_modulus_pa = m.young_pa;
  material.poisson_ratio = m.poisson;
  material.radius1_m = material.radius2_m = m.radius_m;
  material.density_kg_m3 = m.density_kg_m3;
  return restitution::dem::pair_of(material);
}

class DemIntegration : public testing::TestWithParam<Case> {};

TEST_P(DemIntegration, CodeMeasuresTheEpsRestitutionPredicts) {
  const Case& c = GetParam();
  restitution::dem::Deck deck;
  deck.code = restitution::dem::code_from_name(c.code);
  const std::string program = restitution::dem::dem_program(deck.code);
  ASSERT_FALSE(program.empty()) << (c.code == "lammps" ? "lmp" : "liggghts")
                                << " not found on PATH: scripts/setup installs Debian's " << c.code;
  const Material& m = c.material;
  const double v = m.velocity_m_s;
  const std::vector<double> speeds{v / 4.0, v, 4.0 * v};
  std::ostringstream args;
  args.precision(17);
  args << "dem --code " << c.code << " --end " << c.end << " --eps " << m.eps << " --velocity " << v
       << " --young-modulus " << m.young_pa << " --poisson-ratio " << m.poisson << " --radius " << m.radius_m
       << " --density " << m.density_kg_m3 << " --impact-velocity " << speeds[0] << " " << speeds[1] << " "
       << speeds[2] << " --friction " << c.friction << " --json";
  const auto outcome = restitution::test_support::run_cli(args.str());
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  const json out = json::parse(outcome.out);
  deck.lines = out.at("lines").get<std::vector<std::string>>();
  ASSERT_EQ(out.at("eps").size(), speeds.size());

  const auto measured = restitution::dem::measure_dem_eps(program, deck, pair_of(m), speeds, 2000);
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    ASSERT_TRUE(std::isfinite(measured.coarse[i]) && std::isfinite(measured.fine[i]))
        << program << " printed no eps for v = " << speeds[i] << " m/s:\n"
        << measured.output;
    EXPECT_GT(measured.gap_m[i], 0.0) << "the spheres at v = " << speeds[i] << " m/s still touch at the end";
  }
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    const double predicted = out.at("eps")[i].at("eps").get<double>();
    const double extrapolated = measured.extrapolated[i];
    const double tolerance = 1e-6 * std::min(predicted, 1.0 - predicted);
    EXPECT_NEAR(extrapolated, predicted, tolerance)
        << c.code << " " << m.name << " " << c.end << " v = " << speeds[i] << " m/s: coarse "
        << measured.coarse[i] << ", fine " << measured.fine[i];
    // The extrapolation must be a correction, not the whole answer: the fine run alone is already close.
    EXPECT_NEAR(measured.fine[i], predicted, 100.0 * tolerance);
    std::ostringstream error;
    error << std::scientific << std::setprecision(2) << (extrapolated - predicted) / tolerance;
    RecordProperty("error_over_tolerance_" + std::to_string(i), error.str());
  }
}

std::vector<Case> cases() {
  std::vector<Case> all;
  for (const char* code : {"lammps", "liggghts"}) {
    for (const Material& m : kMaterials) {
      for (const char* end : {"delayed-recovery", "naive"}) all.push_back({code, m, end});
    }
  }
  all.push_back({"lammps", kMaterials[0], "delayed-recovery", 0.5});
  all.push_back({"liggghts", kMaterials[1], "delayed-recovery", 0.5});
  return all;
}

INSTANTIATE_TEST_SUITE_P(Codes, DemIntegration, testing::ValuesIn(cases()), case_name);

}  // namespace

namespace {

// Reads one column of a CSV file with a header line.
std::vector<double> csv_column(const std::filesystem::path& file, const std::string& column) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  std::stringstream names(line);
  for (std::string name; std::getline(names, name, ',');) header.push_back(name);
  const auto index =
      static_cast<std::size_t>(std::find(header.begin(), header.end(), column) - header.begin());
  std::vector<double> values;
  while (std::getline(in, line)) {
    std::stringstream cells(line);
    std::string cell;
    for (std::size_t i = 0; std::getline(cells, cell, ','); ++i) {
      if (i == index) values.push_back(std::stod(cell));
    }
  }
  return values;
}

TEST(DemScene, ShippedSceneRunsBothCodesAndAgreesWithRestitution) {
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("restitution-dem-scene-" + std::to_string(::getpid()));
  std::filesystem::remove_all(folder);
  setenv("RESTITUTION_PYTHON", "/nonexistent/python3", 1);  // the plots are not what is tested here
  const auto r = restitution::test_support::run_cli(
      "run " RESTITUTION_SOURCE_DIR "/scenes/dem.toml --quick --out " + folder.string());
  ASSERT_EQ(r.status, 0) << r.err;
  for (const auto& [name, code] :
       {std::pair{"steel_lammps", "lammps"}, std::pair{"rubber_liggghts", "liggghts"}}) {
    const auto csv = folder / (std::string(name) + ".csv");
    const auto predicted = csv_column(csv, "eps_restitution");
    const auto measured = csv_column(csv, std::string("eps_") + code);
    ASSERT_EQ(measured.size(), predicted.size()) << name;
    ASSERT_GE(predicted.size(), 3U) << name;
    for (std::size_t i = 0; i < predicted.size(); ++i) {
      EXPECT_NEAR(measured[i], predicted[i], 1e-6 * std::min(predicted[i], 1.0 - predicted[i]))
          << name << " " << i;
    }
  }
  const std::string report = restitution::test_support::slurp((folder / "report.md").string());
  EXPECT_NE(report.find("pair_coeff * * hertz/material"), std::string::npos);
  EXPECT_NE(report.find("limitForce off"), std::string::npos);
  std::filesystem::remove_all(folder);
}

}  // namespace
