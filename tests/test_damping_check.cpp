// SPDX-License-Identifier: BSD-3-Clause
// The damping recipes (src/damping_check): each formula against the numbers its source states or an identity
// it was built on, the ε each recipe really gives (closed form where one exists, the fit's own target
// otherwise), the map's monotonicity, speed independence where claimed, and bad input on the command line.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "damping_check/check.hpp"
#include "damping_check/inverse.hpp"
#include "damping_check/recipes.hpp"
#include "restitution/errors.hpp"
#include "restitution/series.hpp"

namespace {

using namespace restitution;
using namespace restitution::damping_check;
using nlohmann::json;

double actual_eps(Recipe recipe, double eps, Clamp clamp, double velocity_m_s = 1.0) {
  CollisionSolver solver;
  CheckRequest request;
  request.recipe = recipe;
  request.eps_requested = eps;
  request.clamps = {clamp};
  request.speeds_m_s = {velocity_m_s};
  return check_recipe(request, solver).points.at(0).actual_eps.value();
}

TEST(DampingRecipes, LammpsTsujiPolynomialAsPairGranularCodesIt) {
  // pair_granular.cpp: 1.2728 - 4.2783 e + 11.087 e² - 22.348 e³ + 27.467 e⁴ - 18.022 e⁵ + 4.8218 e⁶,
  // summed term by term at e = 0.5: 1.2728 - 2.13915 + 2.77175 - 2.7935 + 1.7166875 - 0.5631875 + 0.07534375.
  EXPECT_NEAR(lammps_tsuji_alpha(0.5), 0.34074062500, 1e-14);
  // Tsuji's fit vanishes at e = 1 up to the rounding of its printed coefficients (their sum is 0.0003).
  EXPECT_NEAR(lammps_tsuji_alpha(1.0 - 1e-12), 0.0003, 1e-10);
}

TEST(DampingRecipes, LiggghtsBetaIsTheDashpotDampingRatio) {
  // normal_model_hertz.h: betaeff = log(e)/sqrt(log(e)² + π²); β(0.5) = -0.693147/3.217150.
  EXPECT_NEAR(liggghts_beta(0.5), -0.21545376, 1e-8);
  // It is the damping ratio r of the linear dash-pot x'' + 2 r x' + x = 0 whose naive end gives ε = e.
  CollisionSolver solver;
  SolveOptions options;
  options.ends = EndSet{CollisionEnd::naive};
  for (double e : {0.1, 0.5, 0.9}) {
    const auto r = solver.solve(ContactLaw::linear_dashpot(-liggghts_beta(e)), options);
    EXPECT_NEAR(end_of(r, CollisionEnd::naive).eps, e, 1e-9 * e) << e;
  }
}

TEST(DampingRecipes, LiggghtsHertzWithoutClampIsExact) {
  // Antypov & Elliott 2011 (EPL 94, 50004): for F = k ξ^{3/2} + γ ξ^{1/4} ξ' the naive-end ε is the
  // dash-pot's with the ratio γ/(sqrt(5) sqrt(m k)) -- exactly what LIGGGHTS' sqrt(5/6) factor builds. So
  // with the clamp off the recipe is exact; a wrong ζ mapping would show here at once.
  for (double e : {0.05, 0.3, 0.5, 0.8, 0.95, 0.99}) {
    EXPECT_NEAR(actual_eps(Recipe::liggghts_hertz, e, Clamp::off), e, 1e-8 * std::min(e, 1.0 - e)) << e;
    EXPECT_GT(actual_eps(Recipe::liggghts_hertz, e, Clamp::on), e) << e;  // the clamp cuts the attraction
  }
}

TEST(DampingRecipes, ThorntonFitHitsItsTargetWithTheClamp) {
  // Thornton et al. 2013 fitted (B6)-(B7) to the clamped Hertz-Tsuji collision; its γ(0.5) = 0.2330. The fit
  // misses by 2e-4 at e = 0.3 to 0.8 and by 1.9e-3 at 0.95 (measured).
  EXPECT_NEAR(thornton_2013_damping_ratio(0.5), 0.2330249, 1e-6);
  for (double e : {0.3, 0.5, 0.8, 0.95}) {
    EXPECT_NEAR(actual_eps(Recipe::thornton_2013, e, Clamp::on), e, 2.5e-3) << e;
    EXPECT_LT(actual_eps(Recipe::thornton_2013, e, Clamp::off), e) << e;
  }
}

TEST(DampingRecipes, PadeInversionsSolveTheirPade) {
  for (double e : {0.1, 0.5, 0.9, 0.99}) {
    const double s14 = pade_1_4_sigma(e);
    EXPECT_NEAR(series::pade_2011_1_4(s14 * s14).eps, e, 1e-14) << e;
    CollisionSolver solver;
    const RecipeSetting yade = recipe_setting(Recipe::yade_pade_3_6, e, 1e-10, solver);
    EXPECT_NEAR(series::pade_2011_3_6(yade.zeta_reference).eps, e, 1e-14) << e;
  }
  // At the reference speed the Padé's own error is all that is left: [3/6] within 5e-4, [1/4] within 8e-3
  // of the clamped (delayed-recovery) ε they approximate.
  for (double e : {0.3, 0.5, 0.8, 0.95}) {
    EXPECT_NEAR(actual_eps(Recipe::yade_pade_3_6, e, Clamp::on), e, 5e-4) << e;
    EXPECT_NEAR(actual_eps(Recipe::pade_1_4, e, Clamp::on), e, 8e-3) << e;
  }
}

TEST(DampingRecipes, LammpsViscoelasticIsExactAtItsCalibrationOnly) {
  for (double e : {0.3, 0.8}) {
    EXPECT_NEAR(actual_eps(Recipe::lammps_viscoelastic, e, Clamp::on, 1.0), e, 1e-8) << e;
    // ε falls with the impact speed (ζ ∝ v^{1/5}) and the clamp raises it.
    EXPECT_GT(actual_eps(Recipe::lammps_viscoelastic, e, Clamp::on, 0.1), e);
    EXPECT_LT(actual_eps(Recipe::lammps_viscoelastic, e, Clamp::on, 10.0), e);
    EXPECT_LT(actual_eps(Recipe::lammps_viscoelastic, e, Clamp::off, 1.0), e);
  }
}

TEST(DampingRecipes, TsujiRecipesAreSpeedIndependentInPhysicalUnits) {
  // The code's own damping coefficient for a steel pair, γ = α sqrt(m k) (LAMMPS), solved at three speeds in
  // physical units: one ε, the natural one.
  const double k = 1.4e10;   // k = (4/3) E* sqrt(R_eff) [N m^{-3/2}], any value
  const double m = 2.05e-3;  // m_eff [kg]
  CollisionSolver solver;
  const RecipeSetting s = recipe_setting(Recipe::lammps_tsuji, 0.5, 1e-10, solver);
  ASSERT_TRUE(s.speed_independent());
  const double gamma = s.code_value * std::sqrt(m * k);
  SolveOptions options;
  options.ends = EndSet{CollisionEnd::delayed_recovery};
  const double natural = actual_eps(Recipe::lammps_tsuji, 0.5, Clamp::on);
  for (double v : {0.01, 1.0, 100.0}) {
    const auto r = solver.solve(ContactLaw::physical(LawKind::tsuji_hertz, k, gamma, m, v), options);
    EXPECT_NEAR(end_of(r, CollisionEnd::delayed_recovery).eps, natural, 1e-9) << v;
  }
  for (Recipe recipe : {Recipe::lammps_tsuji, Recipe::liggghts_hertz, Recipe::thornton_2013}) {
    CheckRequest request;
    request.recipe = recipe;
    request.speeds_m_s = {0.1, 1.0, 10.0};
    EXPECT_EQ(check_recipe(request, solver).points.size(), 2U) << recipe_name(recipe);  // one per clamp
  }
}

TEST(DampingRecipes, MapIsMonotoneInTheRequestedEps) {
  CollisionSolver solver;
  for (Recipe recipe : kRecipes) {
    for (Clamp clamp : {Clamp::on, Clamp::off}) {
      double previous = 0.0;
      for (double e : map_eps_grid()) {
        CheckRequest request;
        request.recipe = recipe;
        request.eps_requested = e;
        request.clamps = {clamp};
        request.tolerance = 1e-8;
        const auto actual = check_recipe(request, solver).points.at(0).actual_eps;
        // Only an overdamped Tsuji member without the clamp has no end, and only at the small requested ε.
        if (!actual) {
          EXPECT_EQ(clamp, Clamp::off) << recipe_name(recipe) << " eps " << e;
          EXPECT_EQ(previous, 0.0) << recipe_name(recipe) << " has an end below eps " << e
                                   << " but none there";
          continue;
        }
        EXPECT_GT(*actual, previous) << recipe_name(recipe) << " clamp " << clamp_name(clamp) << " eps " << e;
        previous = *actual;
      }
    }
  }
}

TEST(DampingRecipes, NamesRoundTripAndUnknownOnesListTheRecipes) {
  for (Recipe r : kRecipes) EXPECT_EQ(recipe_from_name(recipe_name(r)), r);
  try {
    (void)recipe_from_name("tsuji");
    FAIL() << "an unknown recipe was accepted";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("lammps-tsuji, lammps-viscoelastic"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)lammps_tsuji_alpha(1.0), InvalidInput);
  EXPECT_THROW((void)clamps_from_name("maybe"), InvalidInput);
  EXPECT_THROW((void)speed_grid(1.0, 0.5, 3), InvalidInput);
}

// The inverse gives back its target: the request it finds, checked forward, gives the target ε at the target
// speed, for every recipe and clamp; elsewhere a speed-dependent recipe's ε moves with the speed.
TEST(DampingInverse, RequestFoundGivesTheTargetForEveryRecipe) {
  CollisionSolver solver;
  for (const Recipe recipe : kRecipes) {
    for (const Clamp clamp : {Clamp::on, Clamp::off}) {
      InverseRequest r;
      r.recipe = recipe;
      r.target_eps = 0.7;
      r.target_velocity_m_s = 2.0;
      r.clamp = clamp;
      r.speeds_m_s = {0.2, 2.0, 20.0};
      const InverseResult inv = invert_recipe(r, solver);
      const std::string what = std::string(recipe_name(recipe)) + " clamp " + clamp_name(clamp);
      CheckRequest forward;
      forward.recipe = recipe;
      forward.eps_requested = inv.eps_to_request;
      forward.clamps = {clamp};
      forward.reference_velocity_m_s = 2.0;
      forward.speeds_m_s = {2.0};
      EXPECT_NEAR(check_recipe(forward, solver).points.front().actual_eps.value(), 0.7, 1e-9) << what;
      const auto& points = inv.check.points;
      if (inv.check.setting.speed_independent()) {
        ASSERT_EQ(points.size(), 1U) << what;
        EXPECT_NEAR(points[0].actual_eps.value(), 0.7, 1e-9) << what;
      } else {
        ASSERT_EQ(points.size(), 3U) << what;
        EXPECT_NEAR(points[1].actual_eps.value(), 0.7, 1e-9) << what;
        EXPECT_GT(points[0].actual_eps.value(), points[2].actual_eps.value()) << what;  // ε falls with v
      }
    }
  }
}

TEST(DampingInverse, TargetOutOfReachNamesTheRange) {
  CollisionSolver solver;
  InverseRequest r;
  r.recipe = Recipe::lammps_tsuji;  // α(0) = 1.27 is the most it damps: small ε are out of reach
  r.target_eps = 0.01;
  try {
    (void)invert_recipe(r, solver);
    FAIL() << "no throw";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("out of reach"), std::string::npos) << e.what();
  }
  r.target_eps = 1.0;
  EXPECT_THROW((void)invert_recipe(r, solver), InvalidInput);
}

TEST(DampingCheckCli, JsonHasTheContractFields) {
  const auto r = test_support::run_cli(
      "damping-check --recipe yade-pade-3-6 --eps 0.8 --velocity-range 0.1:10:3 "
      "--json");
  ASSERT_EQ(r.status, 0) << r.err;
  const json out = json::parse(r.out);
  EXPECT_EQ(out.at("recipe"), "yade-pade-3-6");
  EXPECT_EQ(out.at("clamp"), "both");
  EXPECT_EQ(out.at("requested_eps"), 0.8);
  ASSERT_EQ(out.at("points").size(), 6U);
  for (const auto& p : out.at("points")) {
    const double eps = p.at("actual_eps");
    const double at_cal = p.at("eps_at_calibration_speed");
    EXPECT_NEAR(p.at("recipe_error_at_calibration_speed").get<double>(), (at_cal - 0.8) / 0.8, 1e-15);
    EXPECT_NEAR(p.at("speed_dependence").get<double>(), eps / at_cal - 1.0, 1e-15);
    EXPECT_GT(p.at("velocity_m_s").get<double>(), 0.0);
  }
  // The middle of the three log-spaced speeds is the calibration speed (1 m/s): no speed dependence there.
  EXPECT_NEAR(out.at("points")[1].at("speed_dependence").get<double>(), 0.0, 1e-15);
  const auto tsuji =
      test_support::run_cli("damping-check --recipe lammps-tsuji --eps 0.5 --clamp off --json");
  ASSERT_EQ(tsuji.status, 0) << tsuji.err;
  const json t = json::parse(tsuji.out);
  EXPECT_TRUE(t.at("speed_independent").get<bool>());
  ASSERT_EQ(t.at("points").size(), 1U);
  EXPECT_TRUE(t.at("points")[0].at("velocity_m_s").is_null());
}

TEST(DampingCheckCli, BadInputExitsTwoNamingTheProblem) {
  const std::vector<std::pair<std::string, std::string>> cases{
      {"--recipe tsuji --eps 0.5", "liggghts-hertz"},
      {"--recipe lammps-tsuji --eps 1.2", "(0, 1)"},
      {"--recipe lammps-tsuji --eps 0", "(0, 1)"},
      {"--recipe lammps-tsuji", "--map"},
      {"--recipe lammps-tsuji --eps 0.5 --map", "--map"},
      {"--recipe lammps-tsuji --eps 0.5 --clamp sometimes", "clamp"},
      {"--recipe pade-1-4 --eps 0.5 --velocity-min -1", "--velocity-min"},
      {"--recipe pade-1-4 --eps 0.5 --points 0", "--points"},
      {"--recipe pade-1-4 --eps 0.5 --velocity 0", "reference velocity"},
      {"--recipe pade-1-4 --eps 0.5 --tolerance 1", "tolerance"},
  };
  for (const auto& [args, needle] : cases) {
    const auto r = test_support::run_cli("damping-check " + args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_NE(r.err.find(needle), std::string::npos) << args << ": " << r.err;
  }
}

// The shipped scene: every recipe in the map, an error map per speed-dependent recipe, the findings table;
// liggghts-hertz without the clamp on the diagonal (it is exact there).
TEST(DampingCheckScene, ShippedSceneWritesTheMapsAndTheFindings) {
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("restitution-damping-scene-" + std::to_string(::getpid()));
  std::filesystem::remove_all(folder);
  setenv("RESTITUTION_PYTHON", "/nonexistent/python3", 1);  // the plots are not what is tested here
  const auto r = test_support::run_cli(
      "run " RESTITUTION_SOURCE_DIR "/scenes/damping_check.toml --quick --out " + folder.string());
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream csv(folder / "recipes.csv");
  std::string line;
  std::getline(csv, line);
  std::vector<std::string> header;
  std::stringstream names(line);
  for (std::string name; std::getline(names, name, ',');) header.push_back(name);
  ASSERT_EQ(header.size(), 1 + 2 * kRecipes.size());
  const auto exact = static_cast<std::size_t>(
      std::find(header.begin(), header.end(), "liggghts-hertz_clamp_off") - header.begin());
  ASSERT_LT(exact, header.size());
  int rows = 0;
  while (std::getline(csv, line)) {
    std::vector<double> cells;
    std::stringstream values(line);
    for (std::string cell; std::getline(values, cell, ',');) cells.push_back(std::stod(cell));
    EXPECT_NEAR(cells[exact], cells[0], 1e-8) << line;
    ++rows;
  }
  EXPECT_GE(rows, 3);
  for (const char* recipe : {"lammps-viscoelastic", "yade-pade-3-6", "pade-1-4"}) {
    EXPECT_TRUE(std::filesystem::exists(folder / (std::string("recipes_") + recipe + "_error.csv")))
        << recipe;
  }
  EXPECT_FALSE(std::filesystem::exists(folder / "recipes_lammps-tsuji_error.csv"));  // speed-independent
  const std::string report = test_support::slurp((folder / "report.md").string());
  EXPECT_NE(report.find("| lammps-tsuji | on | 0.5026 | 0.6458 | 0.8577 | 0.9654 |"), std::string::npos)
      << report;
  std::filesystem::remove_all(folder);
}

TEST(DampingCheckScene, MisspelledKeysAndUnknownRecipesNameFileAndLine) {
  const std::filesystem::path scene = std::filesystem::temp_directory_path() /
                                      ("restitution-damping-bad-" + std::to_string(::getpid()) + ".toml");
  std::ofstream(scene)
      << "output = \"never\"\n[[damping_check]]\nname = \"x\"\nrecipe = [\"lammps-tsuji\"]\n";
  auto r = test_support::run_cli("run " + scene.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(":4: damping_check[0].recipe: unknown key"), std::string::npos) << r.err;
  std::ofstream(scene) << "output = \"never\"\n[[damping_check]]\nrecipes = [\"tsuji\"]\neps = [0.5]\n";
  r = test_support::run_cli("run " + scene.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(":3: damping_check[0].recipes: unknown recipe 'tsuji'"), std::string::npos) << r.err;
  std::ofstream(scene) << "output = \"never\"\n[[damping_check]]\neps = [0.5, 1.0]\n";
  r = test_support::run_cli("run " + scene.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(":3: damping_check[0].eps"), std::string::npos) << r.err;
  std::filesystem::remove(scene);
}

}  // namespace

namespace {

TEST(DampingCheckLists, EachRequestedEpsInTurnAsAlone) {
  CheckRequest request;
  request.recipe = Recipe::lammps_tsuji;
  request.clamps = {Clamp::on};
  CollisionSolver solver;
  const std::vector<double> eps{0.3, 0.6, 0.9};
  const std::vector<CheckResult> results = check_recipe_at(request, eps, solver);
  ASSERT_EQ(results.size(), eps.size());
  for (std::size_t i = 0; i < eps.size(); ++i) {
    request.eps_requested = eps[i];
    const CheckResult alone = check_recipe(request, solver);
    ASSERT_EQ(results[i].points.size(), alone.points.size());
    EXPECT_EQ(results[i].setting.code_value, alone.setting.code_value);
    EXPECT_EQ(results[i].points[0].actual_eps, alone.points[0].actual_eps);
    // A larger requested ε gives a larger actual ε (less damping).
    if (i > 0) EXPECT_GT(*results[i].points[0].actual_eps, *results[i - 1].points[0].actual_eps);
  }
}

TEST(DampingCheckLists, TheInverseForEachClampGivesTheTarget) {
  InverseRequest request;
  request.recipe = Recipe::lammps_tsuji;
  request.target_eps = 0.6;
  CollisionSolver solver;
  const std::vector<Clamp> clamps{Clamp::off, Clamp::on};
  const std::vector<InverseResult> results = invert_recipe_for(request, clamps, solver);
  ASSERT_EQ(results.size(), clamps.size());
  for (std::size_t i = 0; i < clamps.size(); ++i) {
    ASSERT_FALSE(results[i].check.points.empty());
    EXPECT_EQ(results[i].check.points.front().clamp, clamps[i]);
    EXPECT_NEAR(*results[i].check.points.front().actual_eps, request.target_eps, 1e-8);
  }
  // Clamped and unclamped ends differ, so do the ε to request for the same target.
  EXPECT_NE(results[0].eps_to_request, results[1].eps_to_request);
}

}  // namespace
