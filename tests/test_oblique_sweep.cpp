// SPDX-License-Identifier: BSD-3-Clause
// Sweeps over impact angle and initial spin (restitution_oblique/oblique_study.hpp, `restitution oblique
// --angle-range --spin`) and Maw, Barber & Fawcett's normalisation ψ = 2(1 − ν)/(μ(2 − ν)) s/v_n: for the
// elastic Mindlin contact the outgoing ψ₂ is a function of the incoming ψ₁ alone (given χ), whatever the
// size, modulus, speed, friction and spin that make ψ₁; a contact that slides throughout lands on ψ₂ = ψ₁ −
// 2(1 + ε)χ.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "restitution/errors.hpp"
#include "restitution_oblique/oblique_study.hpp"

namespace {

using namespace restitution::oblique;
using restitution::test_support::run_cli;

constexpr double kDegree = std::numbers::pi / 180.0;

ObliqueInputs steel_on_wall(double friction) {
  ObliqueInputs in;
  in.material.young_modulus_pa = 2e11;
  in.material.poisson_ratio = 0.3;
  in.material.radius1_m = in.material.radius2_m = 1e-3;
  in.material.density_kg_m3 = 7800.0;
  in.dissipative_constant_s = 0.0;  // elastic
  in.wall = true;                   // rigid: Maw's κ = 2(1 − ν)/(2 − ν) as for a pair of one material
  in.tangential = "mindlin";
  in.friction = friction;
  in.angles_deg = {10.0};
  return in;
}

// ψ₂ of one impact.
double psi_out(const ObliqueInputs& in) {
  return oblique_sweep(oblique_setup(in, ArgumentStyle::keyword)).front().psi_out;
}

TEST(ObliqueSweep, ChiOfAHomogeneousSphereIsSevenHalvesTimesTheStiffnessRatio) {
  const ObliqueSetup wall = oblique_setup(steel_on_wall(0.3), ArgumentStyle::keyword);
  EXPECT_NEAR(maw_chi(wall), 3.5 * 0.7 / 1.7, 1e-15);
  ObliqueInputs pair = steel_on_wall(0.3);
  pair.wall = false;  // two equal spheres: m* = m/2, each arm R, 1 + (m/2)(2 R²/I) = 7/2 as on the wall
  EXPECT_NEAR(maw_chi(oblique_setup(pair, ArgumentStyle::keyword)), 3.5 * 0.7 / 1.7, 1e-15);
}

TEST(ObliqueSweep, ElasticMindlinPsiOutIsAFunctionOfPsiInAlone) {
  // One ψ₁ from four different impacts: the steel sphere at 1 m/s, μ = 0.3, 20° without spin; the same with
  // μ = 0.15 at the angle of half the tangent; a 5 mm sphere of another modulus at 3 m/s with μ = 0.6; and
  // the first at 10° with the spin that makes up the rest of the slip. Each sticks, slides, sticks and slides
  // again.
  const ObliqueInputs reference = [] {
    ObliqueInputs in = steel_on_wall(0.3);
    in.angles_deg = {20.0};
    return in;
  }();
  const ObliqueSetup setup = oblique_setup(reference, ArgumentStyle::keyword);
  const ObliqueImpact expected = oblique_sweep(setup).front();
  ASSERT_GE(expected.result.switches.size(), 3U);  // not a gross slide: the curved part of the diagram
  const double tangent = std::tan(20.0 * kDegree);

  ObliqueInputs half_friction = reference;
  half_friction.friction = 0.15;
  half_friction.angles_deg = {std::atan(tangent / 2.0) / kDegree};

  ObliqueInputs other_sphere = reference;
  other_sphere.material.radius1_m = other_sphere.material.radius2_m = 5e-3;
  other_sphere.material.young_modulus_pa = 7e10;
  other_sphere.material.density_kg_m3 = 2700.0;
  other_sphere.speed_m_s = 3.0;
  other_sphere.friction = 0.6;
  other_sphere.angles_deg = {std::atan(2.0 * tangent) / kDegree};

  ObliqueInputs spinning = reference;
  spinning.angles_deg = {10.0};
  const double v_n = std::cos(10.0 * kDegree);
  spinning.spins_rad_s = {(tangent * v_n - std::sin(10.0 * kDegree)) / 1e-3};  // R ω = s − u

  for (const ObliqueInputs* in : {&half_friction, &other_sphere, &spinning}) {
    const ObliqueImpact impact = oblique_sweep(oblique_setup(*in, ArgumentStyle::keyword)).front();
    EXPECT_NEAR(impact.psi_in, expected.psi_in, 1e-12);
    EXPECT_NEAR(impact.psi_out, expected.psi_out, 1e-7);
  }
  // And a ψ₁ of another friction alone does move ψ₂ (the test can fail).
  ObliqueInputs other_psi = reference;
  other_psi.friction = 0.25;
  EXPECT_GT(std::abs(psi_out(other_psi) - expected.psi_out), 1e-2);
}

TEST(ObliqueSweep, GrossSlideLandsOnTheClosedFormLine) {
  // Elastic: with damping the contact sticks for its first ~1e-8 s (the damping's part of the cap), which
  // moves it off the line.
  ObliqueInputs in = steel_on_wall(0.3);
  in.angles_deg = {70.0, 80.0};
  in.spins_rad_s = {0.0, -100.0, 300.0};
  const ObliqueSetup setup = oblique_setup(in, ArgumentStyle::keyword);
  const std::vector<ObliqueImpact> impacts = oblique_sweep(setup);
  ASSERT_EQ(impacts.size(), 6U);
  for (const ObliqueImpact& i : impacts) {
    ASSERT_EQ(i.result.switches.size(), 1U) << i.angle_deg << " " << i.initial_spin_rad_s;
    const double eps = i.result.normal_restitution;
    EXPECT_NEAR(i.psi_out, i.psi_in - 2.0 * (1.0 + eps) * maw_chi(setup), 1e-9 * i.psi_in);
  }
}

TEST(ObliqueSweep, GrossSlipBeginsWhereTheEndOfContactKeepsSliding) {
  // LAMMPS's mindlin, F_t = -8G* a ξ, keeps sliding to the end while μ(4/3)E* δ' + σ 8G* s < 0 (the slip's h
  // of docs/oblique.md at δ → 0): the elastic contact slides throughout from ψ₂ = −2/3 on, ψ₁ = 4χ − 2/3
  // (Maw, Barber & Fawcett's incremental Mindlin stiffness, dF_t = 8G* a dξ, gives −1 and 4χ − 1).
  ObliqueInputs in = steel_on_wall(0.3);
  const ObliqueSetup setup = oblique_setup(in, ArgumentStyle::keyword);
  const double kappa_over_mu = 2.0 * 0.7 / (1.7 * 0.3);
  const double onset = 4.0 * maw_chi(setup) - 2.0 / 3.0;
  for (const double psi : {onset - 0.02, onset + 0.02})
    in.angles_deg.push_back(std::atan(psi / kappa_over_mu) / kDegree);
  in.angles_deg.erase(in.angles_deg.begin());  // steel_on_wall's 10°
  const std::vector<ObliqueImpact> impacts = oblique_sweep(oblique_setup(in, ArgumentStyle::keyword));
  EXPECT_EQ(impacts[0].result.switches.size(), 3U);  // slip, stick, slip
  EXPECT_EQ(impacts[1].result.switches.size(), 1U);  // slip throughout
  EXPECT_NEAR(impacts[1].psi_out, -2.0 / 3.0 + 0.02, 1e-6);
}

// The sticking limit (issue 44 item 8): the stick mode without a cap, which cannot fail near a cap of 1e12
// F_n as the μ = 1e12 solve did (README steel, A = 1e-8 … 1e-6 s, mindlin, linear_nohistory, mindlin/force).
// It is the e_t of a finite μ whose cap the contact reaches only as the normal force vanishes at the end, and
// the 1e12 solve it replaces failed there.
TEST(ObliqueSweep, StickingLimitIsTheUncappedStickAndDoesNotFail) {
  for (const double a : {1e-8, 1e-7, 1e-6}) {
    for (const char* model : {"mindlin", "linear_nohistory", "mindlin/force"}) {
      ObliqueInputs in = steel_on_wall(0.3);
      in.dissipative_constant_s = a;
      in.tangential = model;
      in.tangential_damping = 0.5;
      const ObliqueSetup setup = oblique_setup(in, ArgumentStyle::keyword);
      const StickingLimit limit = sticking_limit_restitution(setup);
      ASSERT_TRUE(limit.failure.empty()) << model << " A = " << a << ": " << limit.failure;
      // A finite μ the contact at 1° never reaches: 1e3 against a slip of tan 1° of the normal speed.
      TangentialForce capped = setup.tangential;
      capped.friction = 1e3;
      const ImpactVelocity v = impact_at(setup, 1.0, 0.0);
      const ObliqueResult finite = solve_oblique(setup.geometry, setup.normal, capped, v, setup.options);
      // It sticks but for the last instants, where the normal force, and with it any cap, vanishes.
      ASSERT_EQ(finite.switches[0].mode, ContactMode::stick) << model;
      EXPECT_GT(finite.stick_time_s, 0.999 * finite.contact_time_s) << model;
      // The finite cap's last instants of slip move e_t by up to 3e-5 (mindlin/force, whose history is the
      // force the slip resets).
      EXPECT_NEAR(limit.tangential_restitution, finite.tangential_restitution, 1e-4) << model << " A = " << a;
      if (a == 1e-7) {  // the README's steel: the capped solve at μ = 1e12 fails
        capped.friction = 1e12;
        EXPECT_THROW((void)solve_oblique(setup.geometry, setup.normal, capped, v, setup.options),
                     restitution::NumericalFailure)
            << model;
      }
    }
  }
}

TEST(ObliqueSweep, CliGivesEveryAnglesWithEverySpinInOrder) {
  const std::string steel =
      "oblique --young-modulus 2e11 --poisson-ratio 0.3 --radius 1e-3 --density 7800 --dissipative-constant "
      "0 "
      "--wall --tangential mindlin --friction 0.3 --json";
  const auto sweep = run_cli(steel + " --angle-range 10:50:3 --spin 0,-150.5");
  ASSERT_EQ(sweep.status, 0) << sweep.err;
  const auto impacts = nlohmann::json::parse(sweep.out)["impacts"];
  ASSERT_EQ(impacts.size(), 6U);
  std::size_t row = 0;
  for (const double angle : {10.0, 30.0, 50.0}) {
    for (const double spin : {0.0, -150.5}) {
      const auto& impact = impacts[row++];
      EXPECT_EQ(impact["angle_deg"].get<double>(), angle);
      EXPECT_EQ(impact["initial_spin_rad_s"].get<double>(), spin);
      // Each row is the impact solved alone.
      const auto one =
          run_cli(steel + " --angle " + std::to_string(angle) + " --spin " + std::to_string(spin));
      ASSERT_EQ(one.status, 0) << one.err;
      const auto alone = nlohmann::json::parse(one.out)["impacts"][0];
      EXPECT_EQ(impact["tangential_restitution"], alone["tangential_restitution"]);
      EXPECT_EQ(impact["spin_rad_s"], alone["spin_rad_s"]);
      EXPECT_EQ(impact["psi_out"], alone["psi_out"]);
      const double psi_in =
          2.0 * 0.7 / (0.3 * 1.7) * (std::tan(angle * kDegree) + spin * 1e-3 / std::cos(angle * kDegree));
      EXPECT_NEAR(impact["psi_in"].get<double>(), psi_in, 1e-12 * std::abs(psi_in) + 1e-15);
    }
  }
}

TEST(ObliqueSweep, BadRangesAndSpinsExitWithStatus2) {
  const std::string steel =
      "oblique --young-modulus 2e11 --poisson-ratio 0.3 --radius 1e-3 --density 7800 --dissipative-constant "
      "0 "
      "--tangential mindlin";
  const struct {
    std::string arguments, message;
  } cases[] = {
      {" --angle-range 10:50 --friction 0.3", "--angle-range must be FROM:TO:N"},
      {" --angle-range 10:50:1 --friction 0.3", "N must be a whole number"},
      {" --angle-range 10:x:4 --friction 0.3", "not a number"},
      {" --angle-range 10:95:4 --friction 0.3", "--angle-range '10:95:4': the angles must be in [0, 90)"},
      {" --angle 10 --angle-range 10:50:3 --friction 0.3", "not both"},
      {" --angle 10 --spin inf --friction 0.3", "--spin must be finite"},
  };
  for (const auto& c : cases) {
    const auto r = run_cli(steel + c.arguments);
    EXPECT_EQ(r.status, 2) << c.arguments;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.arguments << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << c.arguments;
  }
  // Without friction ψ is undefined: the CSV is written, the figure is not (a warning, as every plot).
  const restitution::test_support::TempFolder folder;
  const auto csv = folder.path / "oblique.csv";
  const auto frictionless = run_cli(steel + " --angle 10 --friction 0 --out " + csv.string() + " --plot " +
                                    (folder.path / "maw.png").string());
  EXPECT_EQ(frictionless.status, 0) << frictionless.err;
  EXPECT_NE(frictionless.err.find("needs friction > 0"), std::string::npos) << frictionless.err;
  EXPECT_TRUE(std::filesystem::exists(csv));
  EXPECT_FALSE(std::filesystem::exists(folder.path / "maw.png"));
}

}  // namespace
