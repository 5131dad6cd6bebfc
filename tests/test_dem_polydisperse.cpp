// SPDX-License-Identifier: BSD-3-Clause
// Polydisperse sets for LAMMPS and LIGGGHTS (docs/dem.md, "Polydisperse sets"): the effective (Y, nu) of a
// pair of two materials gives both E* and Mindlin's G*; every type pair's parameters, read back the way the
// code reads them, give the law for that pair; the LIGGGHTS matrices are symmetric; the binning error is
// positive and shrinks with more classes; refusals name the option or the code. LAMMPS and
// LIGGGHTS themselves run in tests/dem/polydisperse_codes.cpp.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "dem/particle_types.hpp"
#include "dem/polydisperse_lines.hpp"
#include "restitution/errors.hpp"
#include "restitution/units.hpp"

namespace restitution {
namespace {

using nlohmann::json;

const dem::ParticleType kSteel{0.002, 7850.0, 2.1e11, 0.3};
const dem::ParticleType kGlass{0.008, 2500.0, 6.3e10, 0.22};

// Mindlin's 1/G* = 2 (2 - nu_a)(1 + nu_a)/Y_a + 2 (2 - nu_b)(1 + nu_b)/Y_b, LAMMPS' mix_stiffnessG.
double mindlin_g(double y1, double nu1, double y2, double nu2) {
  return 1.0 / (2.0 * (2.0 - nu1) * (1.0 + nu1) / y1 + 2.0 * (2.0 - nu2) * (1.0 + nu2) / y2);
}

TEST(TypePair, EffectivePoissonRatioGivesBothModuliOfTwoMaterials) {
  const dem::Pair p = dem::type_pair(kSteel, kGlass);
  const double e_star = 1.0 / ((1.0 - 0.09) / 2.1e11 + (1.0 - 0.22 * 0.22) / 6.3e10);
  EXPECT_NEAR(p.effective_modulus_pa, e_star, 1e-14 * e_star);
  // What LAMMPS' hertz/material and mindlin NULL make of the one (E, nu) of `pair_coeff I J`.
  EXPECT_NEAR(effective_modulus_pa(p.young_modulus_pa, p.poisson_ratio), e_star, 1e-13 * e_star);
  const double g_star = mindlin_g(2.1e11, 0.3, 6.3e10, 0.22);
  EXPECT_NEAR(mindlin_g(p.young_modulus_pa, p.poisson_ratio, p.young_modulus_pa, p.poisson_ratio), g_star,
              1e-13 * g_star);
  EXPECT_GT(p.poisson_ratio, 0.22);
  EXPECT_LT(p.poisson_ratio, 0.3);
  EXPECT_DOUBLE_EQ(p.effective_radius_m, 0.002 * 0.008 / 0.010);
  const double m1 = sphere_mass_kg(0.002, 7850.0);
  const double m2 = sphere_mass_kg(0.008, 2500.0);
  EXPECT_DOUBLE_EQ(p.effective_mass_kg, m1 * m2 / (m1 + m2));
}

TEST(TypePair, OneMaterialKeepsItsOwnYoungModulusAndPoissonRatio) {
  dem::ParticleType big = kSteel;
  big.radius_m = 0.004;
  const dem::Pair p = dem::type_pair(kSteel, big);
  EXPECT_EQ(p.young_modulus_pa, 2.1e11);
  EXPECT_EQ(p.poisson_ratio, 0.3);
  EXPECT_EQ(p.effective_modulus_pa, effective_modulus_pa(2.1e11, 0.3));
}

TEST(ParticleTypes, ListsOfOneOrOnePerTypeAndMaterialNumbers) {
  const auto types =
      dem::particle_types({0.001, 0.002, 0.004}, {7850.0, 7850.0, 2500.0}, {2.1e11}, {0.3, 0.3, 0.22});
  ASSERT_EQ(types.size(), 3U);
  EXPECT_EQ(types[0].material, 1);
  EXPECT_EQ(types[1].material, 1);
  EXPECT_EQ(types[2].material, 2);
  EXPECT_EQ(types[2].young_modulus_pa, 2.1e11);
  try {
    (void)dem::particle_types({0.001, 0.002, 0.004}, {7850.0, 2500.0}, {2.1e11}, {0.3});
    FAIL() << "a density list of 2 for 3 radii was accepted";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("--density has 2 values for 3 radii"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW((void)dem::particle_types({0.001, -0.002}, {7850.0}, {2.1e11}, {0.3}), InvalidInput);
}

TEST(SizeClasses, LogSpacedEdgesAndLogMidpoints) {
  const dem::SizeClasses s = dem::log_size_classes(0.001, 0.008, 3);
  ASSERT_EQ(s.edges_m.size(), 4U);
  ASSERT_EQ(s.radii_m.size(), 3U);
  EXPECT_DOUBLE_EQ(s.edges_m[1], 0.002);
  EXPECT_DOUBLE_EQ(s.edges_m[2], 0.004);
  EXPECT_EQ(s.edges_m[3], 0.008);
  EXPECT_DOUBLE_EQ(s.radii_m[0], std::sqrt(0.001 * 0.002));
  EXPECT_THROW((void)dem::log_size_classes(0.002, 0.001, 3), InvalidInput);
  EXPECT_THROW((void)dem::log_size_classes(0.001, 0.002, 0), InvalidInput);
}

dem::PolydisperseRequest request(dem::Code code) {
  dem::PolydisperseRequest r;
  r.code = code;
  r.types = dem::particle_types({0.002, 0.004, 0.008}, {7850.0, 7850.0, 2500.0}, {2.1e11, 2.1e11, 6.3e10},
                                {0.3, 0.3, 0.22});
  r.damping.dissipative_constant_s = 2e-7;
  r.speeds_m_s = {0.25, 1.0, 4.0};
  return r;
}

TEST(PolydisperseLines, EveryPairGetsTheLawForItsOwnEffectiveConstants) {
  for (dem::Code code : {dem::Code::lammps, dem::Code::liggghts}) {
    const dem::PolydisperseResult r = dem::polydisperse_lines(request(code));
    ASSERT_EQ(r.pairs.size(), 6U);
    for (const auto& p : r.pairs) {
      const double k =
          hertz_stiffness(p.pair.effective_modulus_pa, p.pair.effective_radius_m) / p.pair.effective_mass_kg;
      const double beta = hertz_constants(k, 2e-7).beta;
      EXPECT_NEAR(p.beta, beta, 1e-12 * beta) << dem::code_name(code) << " " << p.type1 << p.type2;
    }
  }
}

TEST(PolydisperseLines, LammpsHasOnePairCoeffPerPairAndLiggghtsSymmetricMatrices) {
  const dem::PolydisperseResult lammps = dem::polydisperse_lines(request(dem::Code::lammps));
  ASSERT_EQ(lammps.lines.size(), 7U);
  EXPECT_EQ(lammps.lines[0], "pair_style granular");
  EXPECT_EQ(lammps.lines[2].rfind("pair_coeff 1 2 hertz/material ", 0), 0U) << lammps.lines[2];
  EXPECT_EQ(lammps.lines[6].rfind("pair_coeff 3 3 hertz/material ", 0), 0U) << lammps.lines[6];

  const dem::PolydisperseResult liggghts = dem::polydisperse_lines(request(dem::Code::liggghts));
  ASSERT_EQ(liggghts.lines.size(), 7U);
  std::istringstream words(liggghts.lines[2]);  // gamman
  std::vector<std::string> w{std::istream_iterator<std::string>(words), {}};
  ASSERT_EQ(w.size(), 7U + 9U) << liggghts.lines[2];
  EXPECT_EQ(w[4], "gamman");
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) EXPECT_EQ(w[7 + 3 * i + j], w[7 + 3 * j + i]);
  }
  // Entry (1,3) is the gamman of pair (1,3).
  EXPECT_EQ(std::stod(w[7 + 2]), liggghts.pairs[2].deck.parameter("gamman"));
}

TEST(PolydisperseLines, BinningErrorShrinksWithMoreClasses) {
  double previous = HUGE_VAL;
  for (int classes : {2, 4, 8}) {
    dem::PolydisperseRequest r = request(dem::Code::lammps);
    r.classes = dem::log_size_classes(0.001, 0.008, classes);
    r.types = dem::particle_types(r.classes->radii_m, {7850.0}, {2.1e11}, {0.3});
    r.speeds_m_s = {1.0};
    const dem::PolydisperseResult result = dem::polydisperse_lines(r);
    ASSERT_TRUE(result.binning.has_value());
    const double worst = result.binning->worst_relative_error;
    EXPECT_GT(worst, 0.0);
    EXPECT_LT(worst, previous) << classes << " classes";
    previous = worst;
  }
}

TEST(DemCommand, SeveralRadiiJsonCarriesTypesPairsAndLines) {
  const auto r = test_support::run_cli(
      "dem --code lammps --radius 0.002,0.004 --density 7850 --young-modulus 2.1e11 --poisson-ratio 0.3 "
      "--eps 0.9 --velocity 1 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const json out = json::parse(r.out);
  EXPECT_EQ(out.at("types").size(), 2U);
  EXPECT_EQ(out.at("pairs").size(), 3U);
  EXPECT_EQ(out.at("lines").size(), 4U);
  EXPECT_EQ(out.at("dissipative_constant_source"), "calibrated for type pair (1,1)");
  // A is calibrated for pair (1,1): its eps at the calibration speed is the measured one.
  EXPECT_NEAR(out.at("pairs")[0].at("eps")[1].at("eps").get<double>(), 0.9, 1e-9);
}

TEST(DemCommand, DeckOfSeveralTypesCollidesEveryTypePair) {
  test_support::TempFolder folder;
  const std::string deck = (folder.path / "poly.in").string();
  const auto r = test_support::run_cli(
      "dem --code lammps --radius 0.002,0.004,0.008 --density 7850,7850,2500 --young-modulus "
      "2.1e11,2.1e11,6.3e10 "
      "--poisson-ratio 0.3,0.3,0.22 --dissipative-constant 2e-7 --impact-velocity 1 --json --deck " +
      deck);
  ASSERT_EQ(r.status, 0) << r.err;
  const json out = json::parse(r.out);
  EXPECT_EQ(out.at("deck").at("file"), deck);
  EXPECT_EQ(out.at("deck").at("run"), "lmp -in " + deck);
  const std::string text = test_support::slurp(deck);
  EXPECT_NE(text.find("create_box 3 box"), std::string::npos);
  for (const auto& line : out.at("lines")) EXPECT_NE(text.find(line.get<std::string>()), std::string::npos);
  for (const char* types : {"types=1,1", "types=1,3", "types=2,3", "types=3,3"}) {
    EXPECT_NE(text.find(types), std::string::npos) << types;
  }
}

TEST(DemCommand, RefusalsNameTheOptionOrTheCode) {
  const std::string set = " --young-modulus 2.1e11 --poisson-ratio 0.3 --density 7850 --eps 0.9 --velocity 1";
  for (const auto& [args, message] : std::vector<std::pair<std::string, std::string>>{
           {"dem --code yade --radius 0.002,0.004" + set, "--code yade takes one radius"},
           {"dem --code chrono --radius 0.002,0.004" + set, "--code chrono takes one radius"},
           {"dem --code mercurydpm --radius 0.002,0.004" + set, "--code mercurydpm takes one radius"},
           {"dem --code lammps --radius 0.002,0.004 --density 1,2,3 --young-modulus 2.1e11 --poisson-ratio "
            "0.3 "
            "--eps 0.9 --velocity 1",
            "--density has 3 values for 2 radii"},
           {"dem --code lammps --radius 0.002 --young-modulus 1,2 --poisson-ratio 0.3 --density 1 --eps 0.9 "
            "--velocity 1",
            "--young-modulus has 2 values for 1 radius"},
           {"dem --code lammps --radius 0.002,x" + set, "--radius expects a number, got 'x'"},
           {"dem --code lammps --radius-range 0.002:0.001:3" + set, "--radius-range must be"},
           {"dem --code lammps --radius-range 0.001,0.002" + set, "--radius-range RMIN:RMAX:N"},
       }) {
    const auto r = test_support::run_cli(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << ": " << r.err;
  }
}

}  // namespace
}  // namespace restitution
