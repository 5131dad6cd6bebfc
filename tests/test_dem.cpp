// SPDX-License-Identifier: BSD-3-Clause
// The DEM bridge: each code's parameters, read back the way the code reads them (docs/dem.md), give the
// material's law; the unit conversions from first principles; YADE's Padé inversion; refusals; the CLI.
// LAMMPS and LIGGGHTS themselves run in tests/dem/dem_integration.cpp.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "dem/deck.hpp"
#include "dem/deck_eps.hpp"
#include "dem/lines_check.hpp"
#include "dem/yade_conversion.hpp"
#include "material_examples.hpp"
#include "restitution/errors.hpp"
#include "restitution/material.hpp"
#include "restitution/series.hpp"
#include "restitution/units.hpp"
#include "scene/scene.hpp"
#include "scene/scene_dem.hpp"
#include "scene/scene_sections.hpp"
#include "scene_errors.hpp"

namespace restitution {
namespace {

using dem::Code;

constexpr double kA = 5.8e-5;  // the rubber-like example's dissipative constant [s]

double law_beta(const dem::Pair& p, double a) {
  const double k = 4.0 / 3.0 * p.effective_modulus_pa * std::sqrt(p.effective_radius_m) / p.effective_mass_kg;
  return hertz_constants(k, a).beta;
}

bool contains(const std::vector<std::string>& lines, const std::string& text) {
  for (const auto& line : lines) {
    if (line.find(text) != std::string::npos) return true;
  }
  return false;
}

TEST(DemUnits, EffectiveModulusGivesThePapersElasticConstant) {
  // 1999 paper Eq. 1: ρ = 2 Y sqrt(R_eff) / (3 (1 - ν²)) must equal (4/3) E* sqrt(R_eff).
  const Material m = test_support::rubber_like();
  const ElasticConstants e = elastic_constants(m);
  const double e_star = effective_modulus_pa(m.young_modulus_pa, m.poisson_ratio);
  EXPECT_NEAR(4.0 / 3.0 * e_star * std::sqrt(e.effective_radius_m), e.elastic_constant,
              1e-14 * e.elastic_constant);
  // Two spheres in series: 1/E* = (1 - ν²)/Y + (1 - ν²)/Y.
  EXPECT_NEAR(1.0 / e_star, 2.0 * (1.0 - 0.45 * 0.45) / 1e7, 1e-20);
}

TEST(DemUnits, DampingPerMassTimesMassAndContactRadiusIsTheLawsDissipativeCoefficient) {
  // The law's dissipative force (3/2) A ρ sqrt(ξ) ξ' written as c m_eff sqrt(R_eff ξ) ξ'.
  const Material m = test_support::rubber_like();
  const ElasticConstants e = elastic_constants(m);
  const double e_star = effective_modulus_pa(m.young_modulus_pa, m.poisson_ratio);
  const double c = damping_per_mass(kA, e_star, e.effective_mass_kg);
  EXPECT_NEAR(c * e.effective_mass_kg * std::sqrt(e.effective_radius_m), 1.5 * kA * e.elastic_constant,
              1e-14 * 1.5 * kA * e.elastic_constant);
  EXPECT_NEAR(dissipative_constant_from_damping_per_mass(c, e_star, e.effective_mass_kg), kA, 1e-18);
  EXPECT_NEAR(beta_of_coefficients(e.elastic_constant, 1.5 * kA * e.elastic_constant, e.effective_mass_kg),
              hertz_constants(e.k, kA).beta, 1e-14);
}

TEST(DemUnits, BadInputIsNamed) {
  EXPECT_THROW(effective_modulus_pa(-1.0, 0.3), InvalidInput);
  EXPECT_THROW(effective_modulus_pa(1e9, 0.5), InvalidInput);
  EXPECT_THROW(damping_per_mass(-1.0, 1e9, 1.0), InvalidInput);
  EXPECT_THROW(beta_of_coefficients(1.0, 1.0, 0.0), InvalidInput);
}

class EachCode : public testing::TestWithParam<Code> {};

TEST_P(EachCode, ParametersGiveTheLawToTheirOwnPair) {
  const dem::Pair pair = dem::pair_of(test_support::rubber_like());
  const dem::Deck deck = dem::make_deck(GetParam(), CollisionEnd::delayed_recovery, pair, kA, 2.0);
  EXPECT_NEAR(dem::deck_beta(deck, pair), law_beta(pair, kA), 1e-9 * law_beta(pair, kA));
  EXPECT_FALSE(deck.lines.empty());
  for (const auto& p : deck.parameters) EXPECT_FALSE(p.meaning.empty()) << p.name;
}

// Every code of the table (dem/dem_codes.cpp), so that a new one is tested without a change here.
std::vector<Code> every_code() {
  std::vector<Code> codes;
  for (const dem::CodeEntry& e : dem::dem_codes()) codes.push_back(e.code);
  return codes;
}

INSTANTIATE_TEST_SUITE_P(Dem, EachCode, testing::ValuesIn(every_code()),
                         [](const auto& info) { return std::string(dem::code_name(info.param)); });

TEST(DemLines, CalibratedLinesGiveTheMeasuredEpsAtItsSpeed) {
  // Calibrated to ε = 0.7 at 2 m/s, the lines give that ε at 2 m/s, and the speeds and the A agree with an
  // independent solve of the law.
  for (const Code code : {Code::lammps, Code::yade}) {
    dem::LinesRequest request;
    request.code = code;
    request.material = test_support::rubber_like();
    request.damping.eps = 0.7;
    request.damping.velocity_m_s = 2.0;
    request.speeds_m_s = {0.5, 2.0, 8.0};
    const dem::LinesResult r = dem::check_lines(request);
    ASSERT_EQ(r.eps.size(), 3U);
    EXPECT_NEAR(r.eps[1].eps, 0.7, 1e-9) << dem::code_name(code);
    const dem::Pair pair = dem::pair_of(request.material);
    CollisionSolver solver;
    for (const auto& e : r.eps) {
      EXPECT_NEAR(e.eps,
                  dem::eps_for(law_beta(pair, r.dissipative_constant_s), e.velocity_m_s,
                               CollisionEnd::delayed_recovery, 1e-10, solver),
                  1e-9);
    }
    EXPECT_EQ(r.yade.has_value(), code == Code::yade);
  }
}

TEST(DemLines, ComparisonWithoutTheCodeCarriesOnlyThePrediction) {
  const Material m = test_support::rubber_like();
  const dem::CodeComparison c =
      dem::compare_with_code(Code::lammps, m, {kA, std::nullopt, std::nullopt},
                             CollisionEnd::delayed_recovery, {0.1, 1.0}, 0.0, 1e-10, Method::automatic, "");
  EXPECT_EQ(c.dissipative_constant_s, kA);
  EXPECT_FALSE(c.measured.has_value());
  EXPECT_TRUE(c.relative_difference.empty());
  ASSERT_EQ(c.predicted_eps.size(), 2U);
  CollisionSolver solver;
  const double beta = law_beta(dem::pair_of(m), kA);
  EXPECT_NEAR(c.predicted_eps[0], dem::eps_for(beta, 0.1, CollisionEnd::delayed_recovery, 1e-10, solver),
              1e-9);
  EXPECT_GT(c.predicted_eps[0], c.predicted_eps[1]);  // ε falls with the impact speed
  EXPECT_THROW(dem::compare_with_code(Code::lammps, m, {kA, 0.5, 1.0}, CollisionEnd::delayed_recovery, {1.0},
                                      0.0, 1e-10, Method::automatic, ""),
               InvalidInput);  // A given and calibrated: which one?
}

TEST(DemDeck, OtherSizesGetWhatEachConventionImplies) {
  const dem::Pair pair = dem::pair_of(test_support::rubber_like());
  const dem::Pair half = dem::scaled(pair, 0.5);
  auto beta = [&](Code code) {
    return dem::deck_beta(dem::make_deck(code, CollisionEnd::delayed_recovery, pair, kA, 1.0), half);
  };
  // MercuryDPM takes A itself: exact at every size.
  EXPECT_NEAR(beta(Code::mercurydpm), law_beta(half, kA), 1e-12 * law_beta(half, kA));
  // LAMMPS and LIGGGHTS multiply a fixed η_n0 by m_eff: A' = A m_eff'/m_eff = A / 8.
  EXPECT_NEAR(beta(Code::lammps), law_beta(half, kA / 8.0), 1e-12 * law_beta(half, kA));
  EXPECT_NEAR(beta(Code::liggghts), law_beta(half, kA / 8.0), 1e-12 * law_beta(half, kA));
  // YADE keeps β = σ² vn^{-1/5}: the same β for every pair.
  EXPECT_NEAR(beta(Code::yade), law_beta(pair, kA), 1e-9 * law_beta(pair, kA));
  // Chrono: k = R' Kn / m', γ = R' Gn with Kn, Gn made for R: k' = k (R'/R)^{1/2} (m/m') sqrt(R'/R) ...
  // i.e. K' = (4/3) E* R'/sqrt(R), D' = 2 A E* R' m'/(m sqrt(R)).
  const double r = pair.effective_radius_m;
  const double rh = half.effective_radius_m;
  const double mh = half.effective_mass_kg;
  const double e = pair.effective_modulus_pa;
  const double expected =
      beta_of_coefficients(4.0 / 3.0 * e * rh / std::sqrt(r),
                           2.0 * kA * e * rh * mh / (pair.effective_mass_kg * std::sqrt(r)), mh);
  EXPECT_NEAR(beta(Code::chrono), expected, 1e-12 * expected);
}

TEST(DemDeck, ClampFollowsTheEndInLammpsAndLiggghts) {
  const dem::Pair pair = dem::pair_of(test_support::rubber_like());
  const auto lammps_delayed = dem::make_deck(Code::lammps, CollisionEnd::delayed_recovery, pair, kA, 1.0);
  const auto lammps_naive = dem::make_deck(Code::lammps, CollisionEnd::naive, pair, kA, 1.0);
  EXPECT_TRUE(contains(lammps_delayed.lines, "limit_damping"));
  EXPECT_FALSE(contains(lammps_naive.lines, "limit_damping"));
  EXPECT_TRUE(contains(lammps_naive.lines, "pair_coeff * * hertz/material"));
  EXPECT_TRUE(contains(dem::make_deck(Code::liggghts, CollisionEnd::delayed_recovery, pair, kA, 1.0).lines,
                       "limitForce on"));
  EXPECT_TRUE(
      contains(dem::make_deck(Code::liggghts, CollisionEnd::naive, pair, kA, 1.0).lines, "limitForce off"));
}

TEST(DemDeck, CodesThatAlwaysClampRefuseTheNaiveEnd) {
  const dem::Pair pair = dem::pair_of(test_support::rubber_like());
  for (Code code : {Code::mercurydpm, Code::yade, Code::chrono}) {
    try {
      (void)dem::make_deck(code, CollisionEnd::naive, pair, kA, 1.0);
      ADD_FAILURE() << dem::code_name(code) << " accepted --end naive";
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find(dem::code_name(code)), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW((void)dem::code_from_name("lammps2"), InvalidInput);
}

TEST(DemYade, NewtonInvertsThePade) {
  for (double en : {0.99, 0.9, 0.7, 0.5, 0.3}) {
    const double sigma = dem::yade_sigma(en);
    EXPECT_NEAR(series::pade_2011_3_6(sigma * sigma).eps, en, 4e-16) << en;
  }
  EXPECT_EQ(dem::yade_sigma(1.0), 0.0);
  EXPECT_THROW(dem::yade_sigma(0.0), InvalidInput);
  EXPECT_THROW(dem::yade_sigma(1.5), InvalidInput);
}

TEST(DemYade, TheTrueEpsGivesYadeAnAThatIsOffByThePadesError) {
  // YADE fed the law's true ε(vn) at the delayed-recovery end makes an A whose β differs from the law's
  // by exactly the Padé's error in ζ: σ_Padé(ε)² / ζ_true.
  const dem::Pair pair = dem::pair_of(test_support::rubber_like());
  const double k =
      4.0 / 3.0 * pair.effective_modulus_pa * std::sqrt(pair.effective_radius_m) / pair.effective_mass_kg;
  const double vn = 1.0;
  CollisionSolver solver;
  const double beta = hertz_constants(k, kA).beta;
  const double true_eps = dem::eps_for(beta, vn, CollisionEnd::delayed_recovery, 1e-11, solver);
  const double a_yade = dem::yade_dissipative_constant(true_eps, vn, k);
  const double sigma = dem::yade_sigma(true_eps);
  EXPECT_NEAR(a_yade / kA, sigma * sigma / zeta_from(beta, vn), 1e-12);
  EXPECT_NE(a_yade, kA);
}

TEST(DemCli, JsonCarriesCodeEndParametersAndLines) {
  const auto outcome = test_support::run_cli(
      "dem --code lammps --eps 0.8 --velocity 1 --young-modulus 1e7 --poisson-ratio 0.45 --radius 0.01 "
      "--density 1100 --json");
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  const auto j = nlohmann::json::parse(outcome.out);
  EXPECT_EQ(j.at("code"), "lammps");
  EXPECT_EQ(j.at("end"), "delayed-recovery");
  EXPECT_TRUE(j.at("parameters").contains("eta_n0"));
  bool pair_coeff = false;
  for (const auto& line : j.at("lines"))
    pair_coeff = pair_coeff || line.get<std::string>().rfind("pair_coeff", 0) == 0;
  EXPECT_TRUE(pair_coeff);
  // The calibration speed's ε is the one asked for.
  EXPECT_NEAR(j.at("eps")[1].at("eps").get<double>(), 0.8, 1e-8);
}

TEST(DemCli, TextHasACommentPerParameter) {
  const auto outcome = test_support::run_cli(
      "dem --code liggghts --dissipative-constant 5.8e-5 --young-modulus 1e7 --poisson-ratio 0.45 --radius "
      "0.01 "
      "--density 1100");
  ASSERT_EQ(outcome.status, 0) << outcome.err;
  EXPECT_NE(outcome.out.find("# kn = "), std::string::npos) << outcome.out;
  EXPECT_NE(outcome.out.find("# gamman = "), std::string::npos) << outcome.out;
  EXPECT_NE(outcome.out.find("frictionless"), std::string::npos) << outcome.out;
}

TEST(DemCli, BadInputExitsWithTwoAndNamesTheProblem) {
  const std::string material = " --young-modulus 1e7 --poisson-ratio 0.45 --radius 0.01 --density 1100";
  auto naive_chrono =
      test_support::run_cli("dem --code chrono --end naive --dissipative-constant 1e-5" + material);
  EXPECT_EQ(naive_chrono.status, 2);
  EXPECT_NE(naive_chrono.err.find("chrono"), std::string::npos) << naive_chrono.err;
  auto both = test_support::run_cli("dem --code lammps --eps 0.8 --velocity 1 --dissipative-constant 1e-5" +
                                    material);
  EXPECT_EQ(both.status, 2);
  EXPECT_NE(both.err.find("--dissipative-constant"), std::string::npos) << both.err;
  auto no_material = test_support::run_cli("dem --code lammps --dissipative-constant 1e-5");
  EXPECT_EQ(no_material.status, 2);
  EXPECT_NE(no_material.err.find("--young-modulus"), std::string::npos) << no_material.err;
}

// Each code's name for the Coulomb coefficient in `parameters`, and the text its lines carry it as.
struct FrictionSpelling {
  const char* code;
  const char* parameter;
  double parameter_value;  // for mu = 0.5
  const char* line_text;
};

TEST(DemCli, FrictionReachesEachCodesParametersAndLinesAndLeavesEpsAlone) {
  const std::string material =
      " --dissipative-constant 5.8e-5 --young-modulus 1e7 --poisson-ratio 0.45 --radius 0.01 --density 1100 "
      "--json";
  const double angle = std::atan(0.5);
  for (const FrictionSpelling& f : {
           FrictionSpelling{"lammps", "mu_s", 0.5, "tangential mindlin NULL 1 0.5 "},
           FrictionSpelling{"liggghts", "coefficientFriction", 0.5,
                            "coefficientFriction peratomtypepair 1 0.5"},
           FrictionSpelling{"mercurydpm", "sliding_friction_coefficient", 0.5,
                            "setSlidingFrictionCoefficient(0.5)"},
           FrictionSpelling{"yade", "frictionAngle", angle, "frictionAngle=0.4636476090008061"},
           FrictionSpelling{"chrono", "friction", 0.5, "SetFriction(0.5)"},
       }) {
    const auto with =
        test_support::run_cli(std::string("dem --code ") + f.code + " --friction 0.5" + material);
    const auto without = test_support::run_cli(std::string("dem --code ") + f.code + material);
    ASSERT_EQ(with.status, 0) << with.err;
    ASSERT_EQ(without.status, 0) << without.err;
    const auto j = nlohmann::json::parse(with.out);
    const auto j0 = nlohmann::json::parse(without.out);
    EXPECT_EQ(j.at("friction").get<double>(), 0.5) << f.code;
    EXPECT_NEAR(j.at("parameters").at(f.parameter).get<double>(), f.parameter_value, 1e-15) << f.code;
    EXPECT_EQ(j0.at("parameters").at(f.parameter).get<double>(), 0.0) << f.code;
    EXPECT_TRUE(contains(j.at("lines").get<std::vector<std::string>>(), f.line_text)) << f.code << "\n"
                                                                                      << with.out;
    EXPECT_TRUE(contains(j.at("notes").get<std::vector<std::string>>(), "does not change the normal eps"))
        << f.code;
    // Friction is tangential: the normal law, hence every ε, is untouched.
    EXPECT_EQ(j.at("eps"), j0.at("eps")) << f.code;
  }
}

TEST(DemDeck, FrictionStiffnessIsMindlinsAndFrictionlessLinesAreUnchanged) {
  const dem::Pair pair = dem::pair_of(test_support::rubber_like());
  // k_t = 8 G* with 1/G* = 2 (2 - nu) / G, G = Y / (2 (1 + nu)), against LIGGGHTS's kn = (4/3) E*.
  const double nu = pair.poisson_ratio;
  const double g_star = pair.young_modulus_pa / (2.0 * (1.0 + nu)) / (2.0 * (2.0 - nu));
  const auto liggghts = dem::make_deck(Code::liggghts, CollisionEnd::delayed_recovery, pair, kA, 1.0, 0.3);
  EXPECT_NEAR(liggghts.parameter("kt"), 8.0 * g_star, 1e-12 * 8.0 * g_star);
  EXPECT_EQ(liggghts.parameter("gammat"), liggghts.parameter("gamman"));
  EXPECT_TRUE(contains(liggghts.lines, "tangential history"));
  const auto chrono = dem::make_deck(Code::chrono, CollisionEnd::delayed_recovery, pair, kA, 1.0, 0.3);
  EXPECT_NEAR(chrono.parameter("Kt"), 8.0 * g_star / std::sqrt(pair.effective_radius_m),
              1e-12 * chrono.parameter("Kt"));
  for (Code code : {Code::lammps, Code::liggghts, Code::mercurydpm, Code::yade, Code::chrono}) {
    const auto rough = dem::make_deck(code, CollisionEnd::delayed_recovery, pair, kA, 1.0, 0.3);
    EXPECT_EQ(dem::deck_beta(rough, pair),
              dem::deck_beta(dem::make_deck(code, CollisionEnd::delayed_recovery, pair, kA, 1.0), pair))
        << dem::code_name(code);
  }
  const auto smooth = dem::make_deck(Code::lammps, CollisionEnd::delayed_recovery, pair, kA, 1.0);
  EXPECT_TRUE(contains(smooth.lines, "tangential linear_nohistory 0 0"));
  EXPECT_THROW((void)dem::make_deck(Code::yade, CollisionEnd::delayed_recovery, pair, kA, 1.0, -0.1),
               InvalidInput);
}

TEST(DemCli, BadFrictionExitsWithTwoAndNamesFriction) {
  const std::string material =
      " --dissipative-constant 5.8e-5 --young-modulus 1e7 --poisson-ratio 0.45 --radius 0.01 --density 1100";
  for (const char* bad : {"-0.1", "nan", "inf"}) {
    const auto r = test_support::run_cli(std::string("dem --code lammps --friction ") + bad + material);
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_NE(r.err.find("--friction"), std::string::npos) << bad << ": " << r.err;
  }
}

}  // namespace
}  // namespace restitution

namespace restitution {
namespace {

const std::string kSceneHead = std::string("output = \"out\"\n") + test_support::kRubberLikeToml;

std::string scene_error(const std::string& dem_table) {
  return scene_errors::scene_error(kSceneHead + "[[dem]]\n" + dem_table, "dem.toml");
}

TEST(DemScene, ParsesATaskAndNamesWhatIsWrong) {
  const scene::Scene s = scene::parse_scene(
      std::string(kSceneHead) +
          "[[dem]]\nname = \"d\"\ncode = \"yade\"\nmaterial = \"rubber\"\nspeeds = [1, 2]\n",
      "dem.toml");
  ASSERT_EQ(scene::tasks_of<scene::DemTask>(s, "dem").size(), 1U);
  EXPECT_EQ(scene::tasks_of<scene::DemTask>(s, "dem")[0]->inputs.code, "yade");
  EXPECT_EQ(scene::tasks_of<scene::DemTask>(s, "dem")[0]->inputs.end, "delayed-recovery");
  EXPECT_NE(scene_error("code = \"gromacs\"\nmaterial = \"rubber\"\nspeeds = [1]\n").find("code"),
            std::string::npos);
  EXPECT_NE(scene_error("code = \"lammps\"\nspeeds = [1]\n").find("material"), std::string::npos);
  EXPECT_NE(
      scene_error("code = \"lammps\"\nmaterial = \"rubber\"\neps = 0.5\nspeeds = [1]\n").find("velocity"),
      std::string::npos);
  EXPECT_NE(scene_error("code = \"lammps\"\nmaterial = \"rubber\"\n").find("speeds"), std::string::npos);
  EXPECT_NE(scene_error("code = \"lammps\"\nmaterial = \"rubber\"\nspeeds = [-1]\n").find("speeds"),
            std::string::npos);
  EXPECT_EQ(scene::tasks_of<scene::DemTask>(s, "dem")[0]->inputs.friction, 0.0);
  EXPECT_NE(scene_error("code = \"lammps\"\nmaterial = \"rubber\"\nspeeds = [1]\nfriction = -0.5\n")
                .find("friction"),
            std::string::npos);
  const scene::Scene rough = scene::parse_scene(
      std::string(kSceneHead) +
          "[[dem]]\nname = \"d\"\ncode = \"lammps\"\nmaterial = \"rubber\"\nspeeds = [1]\nfriction = 0.5\n",
      "dem.toml");
  EXPECT_EQ(scene::tasks_of<scene::DemTask>(rough, "dem")[0]->inputs.friction, 0.5);
}

}  // namespace
}  // namespace restitution
