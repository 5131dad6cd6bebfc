// SPDX-License-Identifier: BSD-3-Clause
// Physical units: the scalings of docs/design.md §1 checked against closed forms (Hertz's elastic collision),
// an independent integration of the dimensional equation in SI units, and the 1999 paper's g*.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "material_examples.hpp"
#include "reference_values.hpp"
#include "restitution/collision_solver.hpp"
#include "restitution/errors.hpp"
#include "restitution/material.hpp"
#include "restitution/series.hpp"
#include "restitution/units.hpp"

namespace restitution {
namespace {

Material rubber() {
  return test_support::rubber_like();
}

TEST(Units, MaterialConstantsFollowTheirDefinitions) {
  const MaterialConstants c = material_constants(rubber());
  const double mass = 4.0 / 3.0 * M_PI * 1e-6 * 1100.0;
  EXPECT_DOUBLE_EQ(c.elastic.effective_radius_m, 0.005);
  EXPECT_NEAR(c.elastic.effective_mass_kg, mass / 2.0, 1e-18);
  EXPECT_NEAR(c.elastic.elastic_constant, 2e7 * std::sqrt(0.005) / (3.0 * (1.0 - 0.45 * 0.45)), 1e-6);
  EXPECT_NEAR(c.hertz.k, c.elastic.elastic_constant / c.elastic.effective_mass_kg, 1e-6 * c.hertz.k);
  EXPECT_NEAR(c.hertz.gamma, 1.5 * 5.8e-5 * c.hertz.k, 1e-12 * c.hertz.gamma);
  // β = γ k^{-3/5} = (3/2) A k^{2/5}: the same number by two routes.
  EXPECT_NEAR(c.hertz.beta, 1.5 * 5.8e-5 * std::pow(c.hertz.k, 0.4), 1e-13);
  EXPECT_NEAR(dissipative_constant_from(c.hertz.beta, c.hertz.k), 5.8e-5, 1e-18);
}

TEST(Units, MassesMayBeGivenInsteadOfDensity) {
  Material m = rubber();
  m.density_kg_m3.reset();
  m.mass1_kg = 2.0;
  m.mass2_kg = 6.0;
  m.radius2_m = 0.03;
  const MaterialConstants c = material_constants(m);
  EXPECT_DOUBLE_EQ(c.elastic.effective_mass_kg, 1.5);
  EXPECT_DOUBLE_EQ(c.elastic.effective_radius_m, 0.0075);
}

TEST(Units, ViscositiesGiveTheDissipativeConstantOfThe1999Paper) {
  Material m = rubber();
  m.dissipative_constant_s.reset();
  m.viscosities = Viscosities{2.0, 3.0};
  // A = (1/3)(3η2 - η1)²/(3η2 + 2η1) · (1-ν²)(1-2ν)/(Y ν²) = (1/3)·49/13 · 0.7975·0.1/(1e7·0.2025).
  const double expected = 49.0 / 39.0 * 0.7975 * 0.1 / (1e7 * 0.2025);
  EXPECT_NEAR(material_constants(m).dissipative_constant_s, expected, 1e-15 * expected + 1e-25);
}

void expect_invalid(const Material& m, const char* key) {
  try {
    (void)material_constants(m);
    ADD_FAILURE() << "accepted a material with a bad " << key;
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
  }
}

TEST(Units, BadMaterialsAreRejectedNamingTheKey) {
  Material m = rubber();
  m.poisson_ratio = 0.5;
  expect_invalid(m, "poisson_ratio");
  m.poisson_ratio = -1.0;
  expect_invalid(m, "poisson_ratio");
  m = rubber();
  m.young_modulus_pa = 0.0;
  expect_invalid(m, "young_modulus");
  m = rubber();
  m.radius2_m = -1.0;
  expect_invalid(m, "radius2");
  m = rubber();
  m.density_kg_m3 = -5.0;
  expect_invalid(m, "density");
  m = rubber();
  m.dissipative_constant_s = -1e-5;
  expect_invalid(m, "dissipative_constant");
  m = rubber();
  m.viscosities = Viscosities{1.0, 1.0};
  expect_invalid(m, "dissipative_constant and viscosities");
  m = rubber();
  m.mass1_kg = 1.0;
  expect_invalid(m, "mass2");
  m = rubber();
  m.dissipative_constant_s.reset();
  m.viscosities = Viscosities{1.0, 1.0};
  m.poisson_ratio = 0.0;
  expect_invalid(m, "poisson_ratio");
  EXPECT_THROW((void)zeta_from(-0.1, 1.0), InvalidInput);
  EXPECT_THROW((void)zeta_from(0.1, 0.0), InvalidInput);
  EXPECT_THROW((void)natural_scales(0.0, 1.0), InvalidInput);
  EXPECT_THROW((void)beta_from_characteristic_velocity(-1.0), InvalidInput);
}

// The Hertz stiffness ρ = (4/3) E* sqrt(R) has one formula (units.cpp), which the material and the DEM decks
// share. Checked at exact points, against an independent computation through E* in long double (64-bit
// mantissa, so its own rounding is far below the tolerance), and for the material's k being that formula.
TEST(Units, HertzStiffnessHasOneFormula) {
  // Exact in binary: Y = 3, ν = 0, R = 4 gives E* = 3/2, ρ = (4/3)(3/2)(2) = 4; Y = 9, ν = -1/2 gives E* = 6,
  // ρ = (4/3)(6)(2) = 16; E* = 6 alone gives the same.
  EXPECT_EQ(hertz_stiffness(3.0, 0.0, 4.0), 4.0);
  EXPECT_EQ(hertz_stiffness(9.0, -0.5, 4.0), 16.0);
  EXPECT_EQ(hertz_stiffness(6.0, 4.0), 16.0);
  std::mt19937_64 random(26);
  std::uniform_real_distribution<double> log10_young(5.0, 12.0);
  std::uniform_real_distribution<double> poisson(-0.99, 0.499);
  std::uniform_real_distribution<double> log10_radius(-7.0, 1.0);
  for (int i = 0; i < 2000; ++i) {
    const double y = std::pow(10.0, log10_young(random));
    const double nu = poisson(random);
    const double r = std::pow(10.0, log10_radius(random));
    const long double e_star =
        static_cast<long double>(y) / (2.0L * (1.0L - static_cast<long double>(nu) * nu));
    const long double expected = 4.0L / 3.0L * e_star * std::sqrt(static_cast<long double>(r));
    const double rho = hertz_stiffness(y, nu, r);
    // A few roundings, and the one of ν² amplified by ν² / (1 - ν²) in 1 - ν² (large as ν -> -1).
    const double ulps = 4.0 + 2.0 * nu * nu / (1.0 - nu * nu);
    EXPECT_NEAR(rho, static_cast<double>(expected), ulps * std::numeric_limits<double>::epsilon() * rho)
        << "Y = " << y << ", nu = " << nu << ", R = " << r;
    const auto e_star_double = static_cast<double>(e_star);
    const auto from_e_star =
        static_cast<double>(4.0L / 3.0L * e_star_double * std::sqrt(static_cast<long double>(r)));
    EXPECT_NEAR(hertz_stiffness(e_star_double, r), from_e_star,
                4.0 * std::numeric_limits<double>::epsilon() * from_e_star);
    // The material's ρ is this formula bit for bit (equal spheres: R_eff = R / 2).
    Material m = rubber();
    m.young_modulus_pa = y;
    m.poisson_ratio = nu;
    m.radius1_m = m.radius2_m = 2.0 * r;
    const ElasticConstants e = elastic_constants(m);
    EXPECT_EQ(e.elastic_constant, hertz_stiffness(y, nu, e.effective_radius_m));
  }
}

TEST(Units, ElasticCollisionMatchesHertzInSiUnits) {
  // Hertz: ξ_max = (5 m_eff v² / (4 ρ))^{2/5}; duration t_c = 2.8683 (m_eff² / (R E*² v))^{1/5} with
  // ρ = (4/3) E* sqrt(R) (Landau & Lifshitz, Theory of Elasticity §9; 2.8683 to the digits quoted there).
  const MaterialConstants c = material_constants(rubber());
  const double v = 0.7;
  const NaturalScales s = natural_scales(c.hertz.k, v);
  const double m = c.elastic.effective_mass_kg;
  const double rho = c.elastic.elastic_constant;
  EXPECT_NEAR(test_support::undamped_max_compression() * s.length_m, std::pow(1.25 * m * v * v / rho, 0.4),
              1e-14);
  const double e_star_sq_r = 9.0 / 16.0 * rho * rho;
  const double t_c = 2.8683 * std::pow(m * m / (e_star_sq_r * v), 0.2);
  EXPECT_NEAR(2.0 * test_support::undamped_max_time() * s.time_s, t_c, 2e-4 * t_c);
}

// The dimensional equation ξ'' + γ sqrt(ξ) ξ' + k ξ^{3/2} = 0 in SI units by classical RK4 with a fine fixed
// step, naive end located by cubic Hermite interpolation: independent of the scalings under test.
struct SiCollision {
  double duration_s, rebound_m_s, max_compression_m;
};
struct State {
  double x;  // ξ [m]
  double u;  // ξ' [m/s]
};
SiCollision integrate_si(double k, double gamma, double v) {
  auto rate = [&](const State& s) {
    return State{s.u, s.x > 0.0 ? -std::sqrt(s.x) * (gamma * s.u + k * s.x) : 0.0};
  };
  auto shifted = [](const State& s, const State& d, double h) { return State{s.x + h * d.x, s.u + h * d.u}; };
  const double h = 2e-9;
  double t = 0.0;
  double x_max = 0.0;
  State s{0.0, v};
  while (true) {
    const State k1 = rate(s);
    const State k2 = rate(shifted(s, k1, 0.5 * h));
    const State k3 = rate(shifted(s, k2, 0.5 * h));
    const State k4 = rate(shifted(s, k3, h));
    const State next{s.x + h / 6.0 * (k1.x + 2 * k2.x + 2 * k3.x + k4.x),
                     s.u + h / 6.0 * (k1.u + 2 * k2.u + 2 * k3.u + k4.u)};
    x_max = std::max(x_max, next.x);
    if (next.x <= 0.0 && t > 0.0) {
      const double f =
          s.x / (s.x - next.x);  // linear in the last step; the rebound speed barely changes there
      return {t + f * h, -(s.u + f * (next.u - s.u)), x_max};
    }
    t += h;
    s = next;
  }
}

TEST(Units, NaturalUnitsConvertBackToSecondsAndMetres) {
  const MaterialConstants c = material_constants(rubber());
  const double v = 1.3;
  const SiCollision si = integrate_si(c.hertz.k, c.hertz.gamma, v);
  CollisionSolver solver;
  SolveOptions options;
  options.ends = EndSet{CollisionEnd::naive};
  const CollisionResult r = solver.solve(ContactLaw::hertz_natural(zeta_from(c.hertz.beta, v)), options);
  const NaturalScales s = natural_scales(c.hertz.k, v);
  EXPECT_NEAR(r[CollisionEnd::naive]->tau * s.time_s, si.duration_s, 1e-6 * si.duration_s);
  EXPECT_NEAR(r.max_compression.x * s.length_m, si.max_compression_m, 1e-6 * si.max_compression_m);
  EXPECT_NEAR(r[CollisionEnd::naive]->eps, si.rebound_m_s / v, 1e-6);
  // The (β, v) form of Eq. 23 gives the same ε (τ unchanged, x reported in natural units).
  const CollisionResult scaled = solver.solve(ContactLaw::hertz_scaled(c.hertz.beta, v), options);
  EXPECT_NEAR(scaled[CollisionEnd::naive]->eps, r[CollisionEnd::naive]->eps, 1e-9);
  EXPECT_NEAR(scaled[CollisionEnd::naive]->tau, r[CollisionEnd::naive]->tau, 1e-8);
}

TEST(Units, CharacteristicVelocityOfThe1999Paper) {
  EXPECT_NEAR(series::c1_closed_form(), 1.15344885809, 1e-10);  // 1999 paper Eq. 31 and A32 (1.153449)
  const double beta = 0.2;
  const double g_star = characteristic_velocity_m_s(beta);
  EXPECT_NEAR(beta_from_characteristic_velocity(g_star), beta, 1e-15);
  // w = (g/g*)^{1/5} = C1 ζ for every impact speed g.
  for (const double g : {1e-3, 0.5, 30.0}) {
    EXPECT_NEAR(std::pow(g / g_star, 0.2), series::c1_closed_form() * zeta_from(beta, g), 1e-14);
  }
  // Ice (1999 paper, Fig. 1): g* = 0.32 cm/s.
  EXPECT_NEAR(beta_from_characteristic_velocity(0.0032), std::pow(0.0032, -0.2) / 1.15344885809, 1e-9);
}

}  // namespace
}  // namespace restitution
