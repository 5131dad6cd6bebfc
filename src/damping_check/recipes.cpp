// SPDX-License-Identifier: BSD-3-Clause
#include "damping_check/recipes.hpp"

#include <fmt/core.h>
#include <boost/math/tools/roots.hpp>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>

#include "dem/yade_conversion.hpp"
#include "restitution/calibration.hpp"
#include "restitution/errors.hpp"
#include "restitution/series.hpp"

namespace restitution::damping_check {
namespace {

void require_eps(double eps) {
  if (!std::isfinite(eps) || eps <= 0.0 || eps >= 1.0) {
    throw InvalidInput(fmt::format("requested eps must be in (0, 1), got {}", eps));
  }
}

}  // namespace

const char* recipe_name(Recipe recipe) {
  switch (recipe) {
    case Recipe::lammps_tsuji:
      return "lammps-tsuji";
    case Recipe::lammps_viscoelastic:
      return "lammps-viscoelastic";
    case Recipe::liggghts_hertz:
      return "liggghts-hertz";
    case Recipe::thornton_2013:
      return "thornton-2013";
    case Recipe::yade_pade_3_6:
      return "yade-pade-3-6";
    case Recipe::pade_1_4:
      return "pade-1-4";
  }
  return "?";
}

std::string recipe_names() {
  std::string names;
  for (Recipe r : kRecipes) names += (names.empty() ? "" : ", ") + std::string(recipe_name(r));
  return names;
}

Recipe recipe_from_name(std::string_view name) {
  for (Recipe r : kRecipes) {
    if (name == recipe_name(r)) return r;
  }
  throw InvalidInput(fmt::format("unknown recipe '{}': the recipes are {}", name, recipe_names()));
}

const char* recipe_source(Recipe recipe) {
  switch (recipe) {
    case Recipe::lammps_tsuji:
      return "LAMMPS pair_style granular, damping tsuji (src/GRANULAR/pair_granular.cpp, PairGranular::coeff "
             "and compute)";
    case Recipe::lammps_viscoelastic:
      return "LAMMPS pair_style granular, damping viscoelastic with eta_n0 from restitution dem --code "
             "lammps "
             "(calibrated at the reference speed, delayed-recovery end)";
    case Recipe::liggghts_hertz:
      return "LIGGGHTS model hertz, coefficientRestitution (src/normal_model_hertz.h, NormalModel<HERTZ>::"
             "collision)";
    case Recipe::thornton_2013:
      return "Thornton et al. 2013, Powder Technol. 233, Eqs. (B6), (B7), as YADE's "
             "Ip2_FrictMat_FrictMat_MindlinPhys(en) uses it (pkg/dem/HertzMindlin.cpp)";
    case Recipe::yade_pade_3_6:
      return "YADE Ip2_FrictMat_FrictMat_MindlinPhys(en, vn): Newton on the Mueller-Poeschel 2011 Pade [3/6] "
             "(pkg/dem/HertzMindlin.cpp, getVstar)";
    case Recipe::pade_1_4:
      return "Granulars.jl getA.py: root of the Mueller-Poeschel 2011 Pade [1/4] (getEpsOfVStar, brentq)";
  }
  return "?";
}

// LAMMPS pair_granular.cpp, PairGranular::coeff (versions 2019 to 2022, also 29 Sep 2021 as Debian ships
// it): `damp = 1.2728 - 4.2783 cor + 11.087 cor² - 22.348 cor³ + 27.467 cor⁴ - 18.022 cor⁵ + 4.8218 cor⁶`,
// Tsuji et al.'s (1992) fit of α(e).
double lammps_tsuji_alpha(double eps) {
  require_eps(eps);
  const double e = eps;
  return 1.2728 + e * (-4.2783 + e * (11.087 + e * (-22.348 + e * (27.467 + e * (-18.022 + e * 4.8218)))));
}

// LIGGGHTS src/normal_model_hertz.h (and pair_gran_hertz_history.cpp before 3.x): the per-pair
// betaeff = log(e) / sqrt(log(e)² + π²), the damping ratio of a linear dash-pot with restitution e.
double liggghts_beta(double eps) {
  require_eps(eps);
  const double l = std::log(eps);
  return l / std::sqrt(l * l + std::numbers::pi * std::numbers::pi);
}

// Thornton, Cummins, Cleary 2013 (Powder Technol. 233, 30-46), Appendix B, as YADE's HertzMindlin.cpp
// (Ip2_FrictMat_FrictMat_MindlinPhys::go, `en` alone) codes it: α = Σ_{i=1}^{10} h_i e^i (B7),
// γ = sqrt(1/(1 - (1 + e)² exp(α)) - 1) (B6).
double thornton_2013_damping_ratio(double eps) {
  require_eps(eps);
  static constexpr std::array<double, 10> h{-6.918798, -16.41105, 146.8049,  -796.4559, 2928.711,
                                            -7206.864, 11494.29,  -11342.18, 6276.757,  -1489.915};
  double alpha = 0.0;
  for (std::size_t i = h.size(); i-- > 0;) alpha = (alpha + h[i]) * eps;  // Horner, from h_10 down
  return std::sqrt(1.0 / (1.0 - (1.0 + eps) * (1.0 + eps) * std::exp(alpha)) - 1.0);
}

// getA.py finds σ with scipy's brentq on the [1/4] ε(σ) (its getEpsOfVStar); the root is unique because
// this ε(σ) decreases from 1 at σ = 0 towards 0. Bracketed here with TOMS 748 to full precision.
double pade_1_4_sigma(double eps) {
  require_eps(eps);
  const auto residual = [eps](double sigma) { return series::pade_2011_1_4(sigma * sigma).eps - eps; };
  double high = 1.0;
  while (residual(high) > 0.0) high *= 2.0;
  std::uintmax_t iterations = 200;
  const auto [a, b] = boost::math::tools::toms748_solve(
      residual, 0.0, high, boost::math::tools::eps_tolerance<double>(), iterations);
  return 0.5 * (a + b);
}

double RecipeSetting::zeta_at(double velocity_m_s, double reference_velocity_m_s) const {
  return zeta_reference * std::pow(velocity_m_s / reference_velocity_m_s, speed_exponent(law));
}

RecipeSetting recipe_setting(Recipe recipe, double eps_requested, double tolerance, CollisionSolver& solver) {
  require_eps(eps_requested);
  RecipeSetting s;
  s.recipe = recipe;
  switch (recipe) {
    case Recipe::lammps_tsuji:
      // F = k ξ^{3/2} + α sqrt(m k) ξ^{1/4} ξ' with k = (4/3) E* sqrt(R) (knfac = E a, a = sqrt(R ξ),
      // damp_normal = sqrt(meff knfac)): the natural ζ = γ / sqrt(m k) = α.
      s.law = LawKind::tsuji_hertz;
      s.code_value = lammps_tsuji_alpha(eps_requested);
      s.code_value_name = "alpha";
      s.zeta_reference = s.code_value;
      break;
    case Recipe::liggghts_hertz: {
      // γ_n = -2 sqrt(5/6) β sqrt(S_n m), S_n = 2 Y* sqrt(R ξ) = (3/2) k ξ^{1/2}: γ_n = -sqrt(5) β sqrt(m k)
      // ξ^{1/4}, so ζ = -sqrt(5) β.
      s.law = LawKind::tsuji_hertz;
      s.code_value = liggghts_beta(eps_requested);
      s.code_value_name = "beta";
      s.zeta_reference = -std::sqrt(5.0) * s.code_value;
      break;
    }
    case Recipe::thornton_2013:
      // YADE: c_n = 2 γ sqrt(m k_n) with the tangent stiffness k_n = (3/2) k ξ^{1/2}: ζ = sqrt(6) γ.
      s.law = LawKind::tsuji_hertz;
      s.code_value = thornton_2013_damping_ratio(eps_requested);
      s.code_value_name = "gamma";
      s.zeta_reference = std::sqrt(6.0) * s.code_value;
      break;
    case Recipe::yade_pade_3_6:
      // YADE: β = σ² vn^{-1/5}, A = (2/3) β (k/m)^{-2/5}; the law's ζ = (3/2) A (k/m)^{2/5} v^{1/5} = σ² at
      // v = vn (docs/dem.md).
      s.law = LawKind::viscoelastic_hertz;
      s.code_value = dem::yade_sigma(eps_requested);
      s.code_value_name = "sigma";
      s.zeta_reference = s.code_value * s.code_value;
      break;
    case Recipe::pade_1_4:
      // getA.py: getBeta = σ² / v^{1/5}, getA = 2 β / (3 (ρ/m)^{2/5}): ζ = σ² at the reference speed.
      s.law = LawKind::viscoelastic_hertz;
      s.code_value = pade_1_4_sigma(eps_requested);
      s.code_value_name = "sigma";
      s.zeta_reference = s.code_value * s.code_value;
      break;
    case Recipe::lammps_viscoelastic: {
      // η_n0 = 2 A E*/m_eff makes the law exact (docs/dem.md): ζ is the calibrated one at v_ref.
      s.law = LawKind::viscoelastic_hertz;
      SolveOptions options;
      options.tolerance = tolerance;
      s.code_value = zeta_for_eps(eps_requested, CollisionEnd::delayed_recovery, options, solver);
      s.code_value_name = "zeta_ref";
      s.zeta_reference = s.code_value;
      break;
    }
  }
  return s;
}

}  // namespace restitution::damping_check
