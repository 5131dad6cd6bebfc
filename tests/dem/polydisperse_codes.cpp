// SPDX-License-Identifier: BSD-3-Clause
// A polydisperse set through LAMMPS and LIGGGHTS: three sizes spanning a factor 4 and two materials (steel
// types 1 and 2, glass type 3), fed exactly the lines `restitution dem --radius R1,R2,R3 ... --json` prints.
// One deck per code (the check deck's pass, dem/check_deck_codes.hpp) holds every type pair (6) at three
// speeds, each collision a head-on pair of touching spheres; it runs at dt = T_min/2000 and T_min/20000 and ε
// is Richardson-extrapolated as in dem_integration.cpp. Every pair must reproduce restitution's ε within 1e-6
// min(ε, 1 - ε). The MPI case runs the same LAMMPS deck under `mpirun -np 2` with `processors 2 1 1`: the
// first sphere of every collision is owned by rank 0 (x < 0), the second by rank 1 (x > 0), so every contact
// straddles the ranks; its ε must equal the serial run's to 1e-12 relative.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "dem/check_deck.hpp"
#include "dem/code_runner.hpp"
#include "dem/process_output.hpp"

namespace {

using nlohmann::json;
namespace dem = restitution::dem;

const char* const kSet =
    "--radius 0.002,0.004,0.008 --density 7850,7850,2500 --young-modulus 2.1e11,2.1e11,6.3e10 "
    "--poisson-ratio 0.3,0.3,0.22 --eps 0.9 --velocity 1 --impact-velocity 0.25 1 4 --json";

json polydisperse_json(const std::string& code, double friction = 0.0) {
  const auto r = restitution::test_support::run_cli("dem --code " + code + " " + kSet + " --friction " +
                                                    std::to_string(friction));
  EXPECT_EQ(r.status, 0) << r.err;
  return json::parse(r.out);
}

// Every type pair at every speed of the JSON, with the ε restitution predicts for it: the rows of the check
// deck's pass (pair by pair, speed by speed).
struct Deck {
  dem::CheckDeckRequest request;
  std::vector<double> predicted;
  std::vector<std::string> labels;
};

Deck deck_of(const json& out, dem::Code code) {
  Deck d;
  d.request.code = code;
  d.request.lines = out.at("lines").get<std::vector<std::string>>();
  const json& types = out.at("types");
  d.request.type_count = static_cast<int>(types.size());
  for (const json& e : out.at("pairs").at(0).at("eps")) {
    d.request.speeds_m_s.push_back(e.at("velocity_m_s").get<double>());
  }
  for (const json& p : out.at("pairs")) {
    dem::CheckPair c;
    c.type1 = p.at("type1").get<int>();
    c.type2 = p.at("type2").get<int>();
    const json& a = types.at(c.type1 - 1);
    const json& b = types.at(c.type2 - 1);
    c.pair.radius1_m = a.at("radius_m").get<double>();
    c.pair.radius2_m = b.at("radius_m").get<double>();
    c.pair.mass1_kg = a.at("mass_kg").get<double>();
    c.pair.mass2_kg = b.at("mass_kg").get<double>();
    c.pair.effective_modulus_pa = p.at("effective_modulus_pa").get<double>();
    c.pair.effective_radius_m = p.at("effective_radius_m").get<double>();
    c.pair.effective_mass_kg = p.at("effective_mass_kg").get<double>();
    for (const json& e : p.at("eps")) {
      c.eps_restitution.push_back(e.at("eps").get<double>());
      d.predicted.push_back(e.at("eps").get<double>());
      d.labels.push_back("pair (" + std::to_string(c.type1) + "," + std::to_string(c.type2) +
                         ") v = " + std::to_string(e.at("velocity_m_s").get<double>()) + " m/s");
    }
    d.request.pairs.push_back(c);
  }
  return d;
}

// A code and the Coulomb mu of the tangential lines: with friction the codes must accept the per-pair
// tangential stiffness (LAMMPS' mindlin NULL from the pair's effective (Y, nu), LIGGGHTS' kt matrix) and a
// head-on collision must keep the frictionless ε.
struct Case {
  std::string code;
  double friction = 0.0;
};

// Names the case in test listings (instead of googletest's byte dump of the struct).
void PrintTo(const Case& c, std::ostream* os) {
  *os << c.code << " friction " << c.friction;
}

class Polydisperse : public testing::TestWithParam<Case> {};

TEST_P(Polydisperse, EveryTypePairReproducesRestitutionsEps) {
  const std::string name = GetParam().code;
  const dem::Code code = dem::code_from_name(name);
  const std::string program = dem::dem_program(code);
  ASSERT_FALSE(program.empty()) << name << " not found on PATH: scripts/setup installs it";
  const json out = polydisperse_json(name, GetParam().friction);
  ASSERT_EQ(out.at("types").size(), 3U);
  ASSERT_EQ(out.at("pairs").size(), 6U);
  Deck d = deck_of(out, code);
  ASSERT_EQ(d.predicted.size(), 18U);
  const dem::DemMeasurement m = dem::measure_type_pairs(program, d.request, {2000, "", "", {}});
  double worst = 0.0;
  for (std::size_t i = 0; i < d.predicted.size(); ++i) {
    ASSERT_TRUE(std::isfinite(m.coarse[i]) && std::isfinite(m.fine[i]))
        << program << " printed no eps for " << d.labels[i] << ":\n"
        << m.output;
    EXPECT_GT(m.gap_m[i], 0.0) << d.labels[i] << ": the spheres still touch at the end";
    const double predicted = d.predicted[i];
    const double scale = std::min(predicted, 1.0 - predicted);
    EXPECT_NEAR(m.extrapolated[i], predicted, 1e-6 * scale)
        << name << " " << d.labels[i] << ": coarse " << m.coarse[i] << ", fine " << m.fine[i];
    worst = std::max(worst, std::fabs(m.extrapolated[i] - predicted) / scale);
  }
  std::ostringstream text;
  text << std::scientific << std::setprecision(2) << worst;
  std::cout << name << " friction " << GetParam().friction
            << ": worst |eps_code - eps| / min(eps, 1 - eps) over 6 pairs x 3 speeds = " << text.str()
            << " (bound 1e-6)\n";
  RecordProperty("worst_relative_error", text.str());
}

INSTANTIATE_TEST_SUITE_P(Codes, Polydisperse,
                         testing::Values(Case{"lammps"}, Case{"liggghts"}, Case{"lammps", 0.5},
                                         Case{"liggghts", 0.5}),
                         [](const testing::TestParamInfo<Case>& info) {
                           return info.param.code + (info.param.friction > 0.0 ? "_friction" : "");
                         });

// The ranks that own atoms, from a `write_dump ... custom FILE id proc` file.
std::set<int> owner_ranks(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::set<int> ranks;
  std::string line;
  bool atoms = false;
  while (std::getline(in, line)) {
    if (line.rfind("ITEM: ATOMS", 0) == 0) {
      atoms = true;
      continue;
    }
    if (!atoms) continue;
    std::istringstream fields(line);
    int id = 0;
    int rank = -1;
    if (fields >> id >> rank) ranks.insert(rank);
  }
  return ranks;
}

// Open MPI as root (CI runs as root; --allow-run-as-root says the same), one machine: the self and
// shared-memory transports only, so no network interface is probed, and no cross-memory attach, which
// containers often forbid (docs/dem.md, "MPI").
void set_open_mpi_environment() {
  setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  setenv("OMPI_MCA_btl", "self,vader", 1);
  setenv("OMPI_MCA_btl_vader_single_copy_mechanism", "none", 1);
}

TEST(PolydisperseMpi, TwoRanksGiveTheSerialEps) {
  const std::string lmp = dem::dem_program(dem::Code::lammps);
  ASSERT_FALSE(lmp.empty()) << "lmp not found on PATH";
  set_open_mpi_environment();
  Deck d = deck_of(polydisperse_json("lammps"), dem::Code::lammps);
  const auto folder =
      std::filesystem::temp_directory_path() / ("restitution-mpi-" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  const auto owners = folder / "owners.txt";
  const dem::DemRun serial = dem::run_type_pairs(lmp, d.request, {2000, "", "", {}});
  // Split at x = 0: rank 0 owns every collision's first sphere, rank 1 its second.
  const dem::PassOptions two_ranks{2000,
                                   "2 1 1",
                                   "write_dump all custom " + owners.string() + " id proc\n",
                                   {"mpirun", "--allow-run-as-root", "--oversubscribe", "-np", "2"}};
  const dem::DemRun parallel = dem::run_type_pairs(lmp, d.request, two_ranks);
  EXPECT_EQ(owner_ranks(owners), (std::set<int>{0, 1})) << parallel.output;
  EXPECT_NE(parallel.output.find("2 by 1 by 1 MPI processor grid"), std::string::npos) << parallel.output;
  double worst = 0.0;
  for (std::size_t i = 0; i < d.predicted.size(); ++i) {
    ASSERT_TRUE(std::isfinite(serial.eps[i]) && std::isfinite(parallel.eps[i])) << d.labels[i] << ":\n"
                                                                                << parallel.output;
    const double relative = std::fabs(parallel.eps[i] - serial.eps[i]) / serial.eps[i];
    EXPECT_LE(relative, 1e-12) << d.labels[i] << ": serial " << serial.eps[i] << ", 2 ranks "
                               << parallel.eps[i];
    worst = std::max(worst, relative);
  }
  std::cout << "mpirun -np 2 vs serial: worst relative eps difference " << worst << " over "
            << d.predicted.size() << " collisions\n";
  RecordProperty("worst_relative_difference", std::to_string(worst));
  std::filesystem::remove_all(folder);
}

// The check deck `dem --deck FILE` writes for the set, run unchanged as a user would, under `mpirun -np 2`
// (LAMMPS picks the processor grid itself here): every check line agrees with restitution's ε.
TEST(PolydisperseMpi, CheckDeckOfTheSetRunsUnchangedOnTwoRanks) {
  const std::string lmp = dem::dem_program(dem::Code::lammps);
  ASSERT_FALSE(lmp.empty()) << "lmp not found on PATH";
  set_open_mpi_environment();
  const auto deck = std::filesystem::temp_directory_path() /
                    ("restitution-poly-deck-" + std::to_string(::getpid()) + ".in");
  const auto r = restitution::test_support::run_cli("dem --code lammps " + std::string(kSet) + " --deck " +
                                                    deck.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string output = dem::output_of("mpirun --allow-run-as-root --oversubscribe -np 2 " + lmp +
                                            " -in " + deck.string() + " -log none -echo none 2>&1");
  std::filesystem::remove(deck);
  const std::vector<dem::CheckLine> lines = dem::read_check_lines(output);
  ASSERT_EQ(lines.size(), 18U) << output;
  EXPECT_NE(output.find("MPI processor grid"), std::string::npos) << output;
  for (const dem::CheckLine& l : lines) {
    const double eps = l.eps_restitution;
    EXPECT_NEAR(l.eps_code, eps, 1e-6 * std::min(eps, 1.0 - eps))
        << "types " << l.type1 << "," << l.type2 << " v = " << l.speed_m_s;
    EXPECT_GT(l.gap_m, 0.0);
  }
}

}  // namespace
