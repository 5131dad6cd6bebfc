// SPDX-License-Identifier: BSD-3-Clause
// Adhesive collisions (restitution/adhesion.hpp) against closed forms, the non-adhesive limit and an
// independent long-double integration (tests/adhesion_reference.hpp). docs/adhesion.md derives the numbers.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "adhesion_reference.hpp"
#include "restitution/adhesion.hpp"
#include "restitution/collision_solver.hpp"
#include "restitution/contact_law.hpp"
#include "restitution/errors.hpp"

namespace {

using restitution::AdhesiveContact;
using restitution::AdhesiveModel;
using restitution::AdhesiveOutcome;
constexpr double kPi = std::numbers::pi;

// µm water ice (docs/adhesion.md §7): Y = 7 GPa, ν = 0.25, ρ = 920 kg/m³, R = 1.5 µm, γ = 0.19 J/m².
AdhesiveContact ice(AdhesiveModel model, double damping = 0.0, double gamma = 0.19) {
  const double young = 7e9, poisson = 0.25, density = 920.0, radius = 1.5e-6;
  const double mass = 4.0 / 3.0 * kPi * radius * radius * radius * density;
  return {model, young / (2.0 * (1.0 - poisson * poisson)), radius / 2.0, mass / 2.0, gamma, damping};
}

// The JKR units recomputed here: A³ = πwR²/E*, w = 2γ; energy πwA², speed sqrt(πwA²/m*).
struct JkrUnits {
  double energy, speed, time;
};
JkrUnits jkr_units(const AdhesiveContact& c) {
  const double w = 2.0 * c.surface_energy_j_per_m2;
  const double a = std::cbrt(kPi * w * c.effective_radius_m * c.effective_radius_m / c.effective_modulus_pa);
  const double energy = kPi * w * a * a;
  const double speed = std::sqrt(energy / c.effective_mass_kg);
  return {energy, speed, (a * a / c.effective_radius_m) / speed};
}

// The hysteresis works in units of πwA², from the closed forms (3/5)2^{2/3} − (2/5)(9/8)^{2/3} and
// 1/10 + (3/5)2^{2/3}, evaluated in 30 digits (mpmath).
constexpr double kWorkForceControlled = 0.519765760088697170154531890329;
constexpr double kWorkDisplacementControlled = 1.05244063118091968485102338356;

double work_units(AdhesiveModel model) {
  return model == AdhesiveModel::jkr_lammps ? kWorkForceControlled : kWorkDisplacementControlled;
}

TEST(Adhesion, BreakRulesClosedForms) {
  for (const auto model : {AdhesiveModel::jkr_lammps, AdhesiveModel::jkr}) {
    const auto c = ice(model);
    const auto units = jkr_units(c);
    EXPECT_NEAR(restitution::elastic_hysteresis_work_j(c) / units.energy, work_units(model), 1e-15);
    // The break overlap in units of (γ/E*)^{2/3} R^{1/3}: LAMMPS's −1.2277, the textbook −2.5538 (=
    // −(3/4)A²/R).
    const double unit = std::pow(c.surface_energy_j_per_m2 / c.effective_modulus_pa, 2.0 / 3.0) *
                        std::cbrt(c.effective_radius_m);
    const double expected = model == AdhesiveModel::jkr_lammps ? -1.22772285078428889 : -2.55376644110756605;
    EXPECT_NEAR(restitution::break_overlap_m(c) / unit, expected, 1e-14);
  }
  // The ratio of the two elastic sticking speeds, sqrt(W_LAMMPS/W_textbook) = 0.702757 (issue 48: 0.702757 ±
  // 7e-6 measured in LAMMPS).
  const double ratio = restitution::sticking_speed(ice(AdhesiveModel::jkr_lammps)).speed_m_per_s /
                       restitution::sticking_speed(ice(AdhesiveModel::jkr)).speed_m_per_s;
  EXPECT_NEAR(ratio, 0.702756757175372957, 1e-15);
  EXPECT_NEAR(restitution::jkr_pull_off_force_n(ice(AdhesiveModel::jkr)), 3.0 * kPi * 0.19 * 0.75e-6, 1e-20);
}

// Elastic JKR: ε(v) = sqrt(1 − W/(½m*v²)) above v_s = sqrt(2W/m*), stuck below, for both break rules.
TEST(Adhesion, ElasticJkrFollowsTheEnergyBalance) {
  for (const auto model : {AdhesiveModel::jkr_lammps, AdhesiveModel::jkr}) {
    const auto c = ice(model);
    const double work = work_units(model) * jkr_units(c).energy;
    const double v_s = std::sqrt(2.0 * work / c.effective_mass_kg);
    EXPECT_NEAR(restitution::sticking_speed(c).speed_m_per_s / v_s, 1.0, 1e-14);
    for (const double k : {1.0001, 1.03, 1.5, 3.0, 10.0, 100.0}) {
      const double v = k * v_s;
      const auto r = restitution::solve_adhesive(c, v, 1e-11);
      ASSERT_EQ(r.outcome, AdhesiveOutcome::bounced) << k;
      const double exact = std::sqrt(1.0 - work / (0.5 * c.effective_mass_kg * v * v));
      EXPECT_NEAR(r.eps, exact, 1e-10 * std::min(1.0, exact))
          << restitution::adhesive_model_name(model) << " k " << k;
      EXPECT_NEAR(r.one_minus_eps, 1.0 - exact, 1e-10 * std::max(1e-6, 1.0 - exact)) << k;
      EXPECT_EQ(r.viscous_work_j, 0.0);
      EXPECT_NEAR(r.hysteresis_work_j / work, 1.0, 1e-15);
    }
    for (const double k : {0.9999, 0.97, 0.5, 0.1}) {
      const auto r = restitution::solve_adhesive(c, k * v_s);
      EXPECT_EQ(r.outcome, AdhesiveOutcome::stuck) << k;
      EXPECT_EQ(r.eps, 0.0);
    }
  }
}

// The elastic sticking speed scales as γ^{5/6} R^{2/3} E*^{-1/3} m*^{-1/2}, i.e. γ^{5/6} R^{-5/6} E*^{-1/3}
// ρ^{-1/2} for spheres of density ρ (docs/adhesion.md §3).
TEST(Adhesion, ElasticStickingSpeedScaling) {
  const auto base = ice(AdhesiveModel::jkr);
  const double v0 = restitution::sticking_speed(base).speed_m_per_s;
  for (const double f : {0.1, 3.0, 1000.0}) {
    auto c = base;
    c.surface_energy_j_per_m2 *= f;
    c.effective_radius_m *= 2.0 * f;
    c.effective_modulus_pa /= f;
    c.effective_mass_kg *= 3.0 * f;
    const double expected = v0 * std::pow(f, 5.0 / 6.0) * std::pow(2.0 * f, 2.0 / 3.0) *
                            std::pow(f, 1.0 / 3.0) * std::pow(3.0 * f, -0.5);
    EXPECT_NEAR(restitution::sticking_speed(c).speed_m_per_s / expected, 1.0, 1e-14) << f;
  }
}

// Undamped DMT is conservative: the attraction's work in and out cancels, ε = 1 at every speed.
TEST(Adhesion, ElasticDmtReturnsEveryImpact) {
  const auto c = ice(AdhesiveModel::dmt);
  for (const double v : {1e-3, 0.1, 1.0, 30.0}) {
    const auto r = restitution::solve_adhesive(c, v, 1e-11);
    ASSERT_EQ(r.outcome, AdhesiveOutcome::bounced) << v;
    EXPECT_EQ(r.one_minus_eps, 0.0);
    EXPECT_EQ(r.eps, 1.0);
  }
  EXPECT_EQ(restitution::sticking_speed(c).speed_m_per_s, 0.0);
}

// γ → 0: the adhesive laws become viscoelastic Hertz (naive end; LAMMPS's damping damp·m*·sqrt(Rδ)·δ̇ and
// A·δ̇·dF/dδ = (3/2)Aρ sqrt(δ)·δ̇ are both of the form γ_h sqrt(δ)δ̇ there), to the adhesion's share
// W/(½m*v²) ~ 1e-14 of ε.
TEST(Adhesion, VanishingSurfaceEnergyGivesViscoelasticHertz) {
  const double v = 1.0;
  for (const auto model : {AdhesiveModel::jkr_lammps, AdhesiveModel::jkr, AdhesiveModel::dmt}) {
    const double damping = model == AdhesiveModel::jkr ? 2e-9 : 1e15;
    const auto c = ice(model, damping, 1e-26);
    const double rho = 4.0 / 3.0 * c.effective_modulus_pa * std::sqrt(c.effective_radius_m);
    const double k = rho / c.effective_mass_kg;
    const double gamma_h =
        model == AdhesiveModel::jkr ? 1.5 * damping * k : damping * std::sqrt(c.effective_radius_m);
    const double zeta = gamma_h * std::pow(k, -0.6) * std::pow(v, 0.2);
    restitution::CollisionSolver solver;
    restitution::SolveOptions options;
    options.tolerance = 1e-11;
    options.ends = restitution::EndSet{restitution::CollisionEnd::naive};
    const auto hertz = solver.solve(
        restitution::ContactLaw::natural(restitution::LawKind::viscoelastic_hertz, zeta), options);
    const double eps = restitution::end_of(hertz, restitution::CollisionEnd::naive).eps;
    const auto r = restitution::solve_adhesive(c, v, 1e-12);
    ASSERT_EQ(r.outcome, AdhesiveOutcome::bounced);
    EXPECT_NEAR(r.eps, eps, 1e-12) << restitution::adhesive_model_name(model) << " zeta " << zeta;
    EXPECT_GT(r.kinetic_to_adhesion_energy, 1e40) << "the test's premise";
  }
}

// Damped JKR against the independent long-double integration, to T·min(ε, 1 − ε) at T = 1e-10.
TEST(Adhesion, DampedJkrMatchesTheReference) {
  for (const auto model : {AdhesiveModel::jkr_lammps, AdhesiveModel::jkr}) {
    for (const double c_scaled : {0.05, 0.5}) {
      for (const double speed : {1.6, 3.0, 10.0}) {
        // Scaled c and V to SI: c = damp·A·t0 (LAMMPS), c = A_visc/t0 (viscoelastic).
        auto contact = ice(model);
        const auto units = jkr_units(contact);
        const double a_unit = std::sqrt(units.speed * units.time * contact.effective_radius_m);
        contact.damping =
            model == AdhesiveModel::jkr_lammps ? c_scaled / (a_unit * units.time) : c_scaled * units.time;
        const double break_radius = model == AdhesiveModel::jkr_lammps ? std::cbrt(9.0 / 8.0) : 0.5;
        const auto kind = model == AdhesiveModel::jkr_lammps
                              ? restitution::test::ReferenceDamping::lammps
                              : restitution::test::ReferenceDamping::viscoelastic;
        const auto ref = restitution::test::adhesion_reference(kind, c_scaled, speed, break_radius, 2e-4L);
        const auto coarse = restitution::test::adhesion_reference(kind, c_scaled, speed, break_radius, 4e-4L);
        const auto r = restitution::solve_adhesive(contact, speed * units.speed, 1e-10);
        ASSERT_EQ(ref.stuck, coarse.stuck);
        ASSERT_EQ(r.outcome == AdhesiveOutcome::stuck, ref.stuck) << c_scaled << " " << speed;
        if (ref.stuck) continue;
        const double eps = static_cast<double>(ref.eps);
        ASSERT_LT(std::fabs(static_cast<double>(ref.eps - coarse.eps)), 1e-13) << "reference converged";
        EXPECT_NEAR(r.eps, eps, 1e-10 * std::min(eps, 1.0 - eps))
            << restitution::adhesive_model_name(model) << " c " << c_scaled << " V " << speed;
        EXPECT_NEAR(r.contact_time_s / units.time, static_cast<double>(ref.time),
                    1e-8 * static_cast<double>(ref.time));
        EXPECT_NEAR(r.viscous_work_j / units.energy, static_cast<double>(ref.viscous_work),
                    1e-8 * 0.5 * speed * speed);
      }
    }
  }
}

// The damped sticking speed to T = 1e-8 in at most 30 solves, and the outcome flips across it.
TEST(Adhesion, DampedStickingSpeed) {
  for (const auto model : {AdhesiveModel::jkr_lammps, AdhesiveModel::jkr, AdhesiveModel::dmt}) {
    const double damping = model == AdhesiveModel::jkr ? 2e-9 : 1e15;
    const auto c = ice(model, damping);
    const auto v_s = restitution::sticking_speed(c, 1e-8);
    EXPECT_LE(v_s.solves, 30) << restitution::adhesive_model_name(model);
    EXPECT_GT(v_s.speed_m_per_s, 0.0);
    EXPECT_EQ(restitution::solve_adhesive(c, v_s.speed_m_per_s * (1.0 + 1e-6)).outcome,
              AdhesiveOutcome::bounced);
    EXPECT_EQ(restitution::solve_adhesive(c, v_s.speed_m_per_s * (1.0 - 1e-6)).outcome,
              AdhesiveOutcome::stuck);
    if (model != AdhesiveModel::dmt) {
      EXPECT_GT(v_s.speed_m_per_s, restitution::sticking_speed(ice(model)).speed_m_per_s);
    }
  }
}

TEST(Adhesion, EnergyBalanceOfADampedBounce) {
  const auto c = ice(AdhesiveModel::jkr_lammps, 1e15);
  const auto r = restitution::solve_adhesive(c, 3.0 * restitution::sticking_speed(c, 1e-8).speed_m_per_s);
  ASSERT_EQ(r.outcome, AdhesiveOutcome::bounced);
  const double kinetic =
      0.5 * c.effective_mass_kg * std::pow(3.0 * restitution::sticking_speed(c, 1e-8).speed_m_per_s, 2);
  EXPECT_NEAR(r.eps * r.eps * kinetic + r.hysteresis_work_j + r.viscous_work_j, kinetic, 1e-9 * kinetic);
  EXPECT_GT(r.max_compression_m, 0.0);
  EXPECT_GT(r.contact_time_s, 0.0);
}

TEST(Adhesion, RefusesBadInput) {
  const auto good = ice(AdhesiveModel::jkr);
  auto expect_refused = [](AdhesiveContact c, const std::string& word) {
    try {
      (void)restitution::solve_adhesive(c, 1.0);
      ADD_FAILURE() << "accepted " << word;
    } catch (const restitution::InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
    }
  };
  auto c = good;
  c.surface_energy_j_per_m2 = -0.1;
  expect_refused(c, "surface energy");
  c.surface_energy_j_per_m2 = 0.0;
  expect_refused(c, "non-adhesive");
  c = good;
  c.effective_modulus_pa = std::nan("");
  expect_refused(c, "effective modulus");
  c = good;
  c.damping = -1.0;
  expect_refused(c, "dissipative constant");
  c = good;
  c.effective_radius_m = 0.0;
  expect_refused(c, "effective radius");
  EXPECT_THROW((void)restitution::solve_adhesive(good, -1.0), restitution::InvalidInput);
  EXPECT_THROW((void)restitution::solve_adhesive(good, 1.0, 1e-13), restitution::InvalidInput);
  EXPECT_THROW((void)restitution::adhesive_model_from_name("jkr2"), restitution::InvalidInput);
  EXPECT_EQ(restitution::adhesive_model_from_name("jkr-lammps"), AdhesiveModel::jkr_lammps);
}

}  // namespace
