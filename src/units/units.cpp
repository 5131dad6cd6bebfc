// SPDX-License-Identifier: BSD-3-Clause
#include "restitution/units.hpp"

#include <fmt/core.h>

#include <cmath>

#include "restitution/errors.hpp"
#include "restitution/series.hpp"

namespace restitution {
namespace {

double positive(double value, const char* name) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw InvalidInput(fmt::format("{} must be finite and > 0, got {}", name, value));
  }
  return value;
}

double nonnegative(double value, const char* name) {
  if (!std::isfinite(value) || value < 0.0) {
    throw InvalidInput(fmt::format("{} must be finite and >= 0, got {}", name, value));
  }
  return value;
}

}  // namespace

HertzConstants hertz_constants(double k, double dissipative_constant_s) {
  positive(k, "k");
  nonnegative(dissipative_constant_s, "dissipative_constant");
  HertzConstants c;
  c.k = k;
  c.gamma = 1.5 * dissipative_constant_s * k;
  c.beta = beta_from_gamma(c.gamma, k);
  return c;
}

double zeta_from(double beta, double velocity_m_s) {
  return nonnegative(beta, "beta") * std::pow(positive(velocity_m_s, "velocity"), 0.2);
}

double beta_from(double zeta, double velocity_m_s) {
  return nonnegative(zeta, "zeta") / std::pow(positive(velocity_m_s, "velocity"), 0.2);
}

double dissipative_constant_from(double beta, double k) {
  return nonnegative(beta, "beta") / (1.5 * std::pow(positive(k, "k"), 0.4));
}

double hertz_modulus_pa(double effective_modulus_pa) {
  return 4.0 / 3.0 * effective_modulus_pa;
}

double hertz_stiffness(double young_modulus_pa, double poisson_ratio, double effective_radius_m) {
  return 2.0 * young_modulus_pa * std::sqrt(effective_radius_m) /
         (3.0 * (1.0 - poisson_ratio * poisson_ratio));
}

double hertz_stiffness(double effective_modulus_pa, double effective_radius_m) {
  // The modulus factor times sqrt(R): the rounding the DEM codes' numbers have always had (the form above
  // at Y = 2 E*, nu = 0 differs in the last bit, which moved printed DEM eps by up to 6e-13).
  return hertz_modulus_pa(effective_modulus_pa) * std::sqrt(effective_radius_m);
}

double sphere_mass_kg(double radius_m, double density_kg_m3) {
  return 4.0 / 3.0 * M_PI * radius_m * radius_m * radius_m * density_kg_m3;
}

double beta_from_gamma(double gamma, double k) {
  return gamma * std::pow(k, -0.6);
}

NaturalScales natural_scales(double k, double velocity_m_s) {
  positive(k, "k");
  positive(velocity_m_s, "velocity");
  NaturalScales s;
  s.length_m = std::pow(velocity_m_s * velocity_m_s / k, 0.4);
  s.time_s = s.length_m / velocity_m_s;
  return s;
}

double natural_time_scale_s(double k, double velocity_m_s) {
  return std::pow(positive(k, "k"), -0.4) * std::pow(positive(velocity_m_s, "velocity"), -0.2);
}

NaturalScales physical_scales(LawKind kind, const PhysicalCoefficients& c, double velocity_m_s) {
  NaturalScales s;
  s.time_s = physical_time_scale_s(kind, c.stiffness, c.effective_mass_kg, velocity_m_s);
  s.length_m = velocity_m_s * s.time_s;
  return s;
}

double characteristic_velocity_m_s(double beta) {
  return std::pow(series::c1_closed_form() * positive(beta, "beta"), -5.0);
}

double beta_from_characteristic_velocity(double characteristic_velocity_m_s) {
  return std::pow(positive(characteristic_velocity_m_s, "characteristic_velocity"), -0.2) /
         series::c1_closed_form();
}

}  // namespace restitution
