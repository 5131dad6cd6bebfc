// SPDX-License-Identifier: BSD-3-Clause
// `restitution gas` at the edges of its domain (issue 44 items 3, 4, 6, 7, 10 and 14, issue 45 item 10), run
// through the program: the collisions per sphere to rounding from 1e-20 s to 1e4 τ₀ against closed forms
// written here, a dilute gas (φ = 1e-300) computed right and one beyond the doubles refused with the range
// that works, --tolerance, --seed and --particles refused with their ranges, the deck's size said and its
// clustering warning only where the box exceeds the clustering length, and a scene of [[gas]] alone reporting
// its work truly.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "cli_runner.hpp"

namespace {

using nlohmann::json;
using restitution::test_support::run_cli;
using restitution::test_support::slurp;
using restitution::test_support::TempFolder;

// The issue's spheres: R = 5 mm, ρ = 920 kg/m³, rms speed 1 m/s per direction.
constexpr double kRadius = 0.005, kDensity = 920.0, kRmsSpeed = 1.0;
const std::string kSpheres = "gas --radius 0.005 --density 920 --rms-speed 1 ";
const std::string kGas = kSpheres + "--packing-fraction 0.1 ";
const std::string kDeckGas = kGas + "--young-modulus 1e8 --poisson-ratio 0.4 --eps 0.8 --velocity 2 ";
const std::string kDeck = kDeckGas + "--haff-times 30 ";

// Enskog's collision frequency of one sphere at T0 [1/s], written out from docs/gas.md:
// ω = 4√π n g₂ σ² √(T/m), n = 6φ/(πσ³), g₂ = (1 − φ/2)/(1 − φ)³, T0 = m v_rms².
double collision_frequency_at_t0(double phi) {
  const double sigma = 2.0 * kRadius;
  const double n = 6.0 * phi / (std::numbers::pi * sigma * sigma * sigma);
  const double g2 = (1.0 - phi / 2.0) / std::pow(1.0 - phi, 3);
  return 4.0 * std::sqrt(std::numbers::pi) * n * g2 * sigma * sigma * kRmsSpeed;  // √(T0/m) = v_rms
}

json gas_json(const std::string& arguments) {
  const auto outcome = run_cli(arguments + " --json");
  EXPECT_EQ(outcome.status, 0) << arguments << "\n" << outcome.err;
  return outcome.status == 0 ? json::parse(outcome.out) : json::object();
}

// A speed-independent ε (the linear dash-pot): Haff's gas, ω = ω0/(1 + t/τ0) with τ0 = 6/((1 − ε²) ω0), so
// N(t) = ω0 τ0 ln(1 + t/τ0), evaluated with log1p to full relative accuracy at every t.
TEST(GasEdges, CollisionsPerSphereOfHaffsGasToRoundingFrom1e20SecondsTo1e4Tau0) {
  const json j = gas_json(kGas +
                          "--law linear-dashpot --eps 0.8 --velocity 2 --haff-times 1e4 --first-time 1e-20 "
                          "--points-per-decade 2");
  ASSERT_FALSE(j.empty());
  const double eps = j.at("haff_eps").get<double>();
  const double omega0 = collision_frequency_at_t0(0.1);
  const double tau0 = 6.0 / ((1.0 - eps * eps) * omega0);
  const auto& times = j.at("time_s");
  ASSERT_GE(times.size(), 46U);  // 23.4 decades
  for (std::size_t i = 0; i < times.size(); ++i) {
    const double t = times[i].get<double>();
    const double expected = omega0 * tau0 * std::log1p(t / tau0);
    EXPECT_NEAR(j.at("collisions_per_particle")[i].get<double>() / expected, 1.0, 1e-12) << "t = " << t;
  }
}

// Viscoelastic Hertz: ω ∝ √T and dT/dt = −(2/τ0) T at t = 0, so N(t) = ω0 t (1 − t/(2τ0) + O(t²/τ0²)): to
// 1e-13 relative below 1e-7 τ0.
TEST(GasEdges, CollisionsPerSphereOfTheViscoelasticGasAtTheFirstInstants) {
  const json j =
      gas_json(kGas + "--eps 0.8 --velocity 2 --haff-times 1 --first-time 1e-20 --points-per-decade 1");
  ASSERT_FALSE(j.empty());
  const double tau0 = j.at("tau0_s").get<double>();
  const double omega0 = collision_frequency_at_t0(0.1);
  std::size_t checked = 0;
  for (std::size_t i = 0; i < j.at("time_s").size(); ++i) {
    const double t = j.at("time_s")[i].get<double>();
    if (t > 1e-7 * tau0) break;
    const double expected = omega0 * t * (1.0 - t / (2.0 * tau0));
    EXPECT_NEAR(j.at("collisions_per_particle")[i].get<double>() / expected, 1.0, 1e-13) << "t = " << t;
    ++checked;
  }
  EXPECT_GE(checked, 12U);
}

// φ = 1e-300 (τ0 ≈ 1e298 s) is the same gas in units of τ0 as any dilute one: at 10 τ0 its T/T0 and local
// exponent are those of φ = 1e-12 (g₂ = 1 + 2.5φ: 1 to 3e-12 for both).
TEST(GasEdges, ExtremelyDiluteGasCoolsLikeAnyDiluteOne) {
  const std::string law = "--eps 0.8 --velocity 2 --haff-times 10 --points-per-decade 2 ";
  const json dilute = gas_json(kSpheres + law + "--packing-fraction 1e-12");
  const json extreme = gas_json(kSpheres + law + "--packing-fraction 1e-300");
  ASSERT_FALSE(dilute.empty());
  ASSERT_FALSE(extreme.empty());
  EXPECT_NEAR(extreme.at("tau0_s").get<double>() / dilute.at("tau0_s").get<double>(), 1e288, 1e288 * 1e-11);
  const auto& a = dilute.at("temperature_j");
  const auto& b = extreme.at("temperature_j");
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_NEAR(b[i].get<double>() / a[i].get<double>(), 1.0, 1e-12) << i;
    EXPECT_NEAR(extreme.at("local_exponent")[i].get<double>(), dilute.at("local_exponent")[i].get<double>(),
                1e-12)
        << i;
    EXPECT_NEAR(extreme.at("collisions_per_particle")[i].get<double>() /
                    dilute.at("collisions_per_particle")[i].get<double>(),
                1.0, 1e-12)
        << i;
  }
  const double end = b.back().get<double>() / extreme.at("initial_temperature_j").get<double>();
  EXPECT_NEAR(end, 0.012565, 1e-6);  // main gave 0.6065 (the end of the first panel) and -15
  EXPECT_NEAR(extreme.at("local_exponent").back().get<double>(), -1.5856, 1e-4);
}

void expect_refused(const std::string& arguments, const std::vector<std::string>& words) {
  const auto outcome = run_cli(arguments);
  EXPECT_EQ(outcome.status, 2) << arguments << "\n" << outcome.err;
  EXPECT_TRUE(outcome.out.empty()) << arguments;
  for (const std::string& w : words)
    EXPECT_NE(outcome.err.find(w), std::string::npos) << arguments << "\n" << outcome.err;
}

// A Haff time beyond 1e300 s is refused naming the packing fraction and the range that works here.
TEST(GasEdges, GasWhoseHaffTimeLeavesTheDoublesIsRefusedWithTheRange) {
  expect_refused(
      kSpheres + "--eps 0.8 --velocity 2 --haff-times 100 --packing-fraction 1e-305",
      {"--packing-fraction", "tau0 = 1e303 s", "--packing-fraction must be in [1.19e-302, 0.5) here"});
}

// The scene's [[gas]] takes the command's path to the request: the same refusal, exit 2.
TEST(GasEdges, SceneRefusesTheSameGas) {
  TempFolder folder;
  std::ofstream(folder.path / "dilute.toml") << R"(output = "out"
[materials.pe]
young_modulus = 1e8
poisson_ratio = 0.4
density = 920.0
radius = 0.005
[[gas]]
name = "g"
material = "pe"
eps = 0.8
velocity = 2.0
packing_fraction = 1e-305
rms_speed = 1.0
haff_times = 100.0
)";
  const auto outcome =
      run_cli("run " + (folder.path / "dilute.toml").string() + " --out " + (folder.path / "out").string());
  EXPECT_EQ(outcome.status, 2) << outcome.err;
  EXPECT_NE(outcome.err.find("gas \"g\""), std::string::npos) << outcome.err;
  EXPECT_NE(outcome.err.find("tau0 = 1e303 s"), std::string::npos) << outcome.err;
  EXPECT_NE(outcome.err.find("must be in [1.19e-302, 0.5) here"), std::string::npos) << outcome.err;
}

TEST(GasEdges, ToleranceIsCheckedForEveryLaw) {
  for (const std::string law : {"", "--law tsuji-hertz ", "--law linear-dashpot "}) {
    for (const std::string tolerance : {"-1", "nan", "1e-20", "0.5"}) {
      expect_refused(kGas + law + "--eps 0.8 --velocity 2 --duration 1 --tolerance " + tolerance,
                     {"--tolerance must be in [1e-11, 0.01]"});
    }
  }
}

TEST(GasEdges, SeedAndParticlesAreRefusedOutsideTheirRanges) {
  TempFolder folder;
  const std::string deck = kDeck + "--deck " + (folder.path / "d.in").string() + " ";
  expect_refused(deck + "--seed -1", {"--seed", "[0, 9223372036854775807]", "'-1'"});
  expect_refused(deck + "--particles -5", {"--particles", "[2, 10000000]", "'-5'"});
  expect_refused(deck + "--particles 100000000", {"--particles", "[2, 10000000]"});
  EXPECT_TRUE(std::filesystem::is_empty(folder.path));
}

// A deck no code could finish is refused before a file is written: φ = 1e-300 asks for a box of 2e98 m and
// about 1e100 steps (it used to be written).
TEST(GasEdges, DeckOfARunTooLongForAnyCodeIsRefused) {
  TempFolder folder;
  expect_refused(kSpheres +
                     "--packing-fraction 1e-300 --young-modulus 1e8 --poisson-ratio 0.4 --eps 0.8 "
                     "--velocity 2 --haff-times 30 --deck " +
                     (folder.path / "d.in").string(),
                 {"time steps", "at most 1e+10", "--packing-fraction", "--duration"});
  EXPECT_TRUE(std::filesystem::is_empty(folder.path));
}

// The deck says how big its data file is, and the figure docs/gas.md gives per sphere is the one measured.
TEST(GasEdges, DeckSaysHowBigItsDataFileIs) {
  TempFolder folder;
  const auto outcome = run_cli(kDeck + "--particles 2000 --json --deck " + (folder.path / "d.in").string());
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  const json j = json::parse(outcome.out);
  const auto bytes = std::filesystem::file_size(folder.path / "d.data");
  EXPECT_EQ(j.at("deck").at("data_bytes").get<std::uintmax_t>(), bytes);
  EXPECT_NEAR(static_cast<double>(bytes) / 2000.0, 160.0, 8.0);
  const auto text = run_cli(kDeck + "--particles 2000 --deck " + (folder.path / "e.in").string());
  EXPECT_NE(text.out.find(std::to_string(std::filesystem::file_size(folder.path / "e.data")) + " bytes"),
            std::string::npos)
      << text.out;
}

// A box below the clustering length L_c holds no growing shear mode: N = 100 (8.06 diameters, L_c = 20.7) is
// not warned, and its text says the modes decay; N = 4000 (27.6 diameters) over 100 τ0 is.
TEST(GasEdges, ClusteringWarningOnlyWhereTheBoxExceedsTheClusteringLength) {
  TempFolder folder;
  const auto small = run_cli(kDeck + "--particles 100 --deck " + (folder.path / "s.in").string());
  ASSERT_EQ(small.status, 0) << small.err;
  EXPECT_EQ(small.out.find("warning"), std::string::npos) << small.out;
  EXPECT_NE(small.out.find("above the box: every shear mode decays"), std::string::npos) << small.out;
  EXPECT_EQ(slurp((folder.path / "s_constant_eps.in").string()).find("cluster"), std::string::npos);
  const auto large =
      run_cli(kDeckGas + "--haff-times 100 --particles 4000 --deck " + (folder.path / "l.in").string());
  ASSERT_EQ(large.status, 0) << large.err;
  EXPECT_NE(large.out.find("# warning: the constant-eps gas will cluster"), std::string::npos) << large.out;
}

// A scene of [[gas]] sections alone integrates no collision of the shared plan, and its report says so.
TEST(GasEdges, SceneOfGasAloneReportsItsWorkTruly) {
  TempFolder folder;
  std::ofstream(folder.path / "gas.toml") << R"(output = "out"
[materials.pe]
young_modulus = 1e8
poisson_ratio = 0.4
density = 920.0
radius = 0.005
[[gas]]
name = "g"
material = "pe"
eps = 0.8
velocity = 2.0
packing_fraction = 0.1
rms_speed = 1.0
haff_times = 10.0
points_per_decade = 2
)";
  const auto outcome =
      run_cli("run " + (folder.path / "gas.toml").string() + " --out " + (folder.path / "out").string());
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  const std::string report = slurp((folder.path / "out" / "report.md").string());
  EXPECT_EQ(report.find("0 distinct collisions"), std::string::npos) << report;
  EXPECT_NE(report.find("no collision of the shared plan integrated (not counted here: the [[gas]] sections "
                        "take eps(v) from the fast table or from their own solves)"),
            std::string::npos)
      << report;
}

}  // namespace
