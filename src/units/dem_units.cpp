// SPDX-License-Identifier: BSD-3-Clause
// DEM codes' constants: the effective modulus and the per-mass damping coefficient (docs/dem.md).
#include <fmt/core.h>

#include <cmath>

#include "restitution/errors.hpp"
#include "restitution/units.hpp"

namespace restitution {
namespace {

double checked(double value, const char* name, bool zero_allowed) {
  if (!std::isfinite(value) || value < 0.0 || (!zero_allowed && value == 0.0)) {
    throw InvalidInput(
        fmt::format("{} must be finite and {} 0, got {}", name, zero_allowed ? ">=" : ">", value));
  }
  return value;
}

}  // namespace

double effective_modulus_pa(double young_modulus_pa, double poisson_ratio) {
  checked(young_modulus_pa, "young_modulus", false);
  if (!std::isfinite(poisson_ratio) || poisson_ratio <= -1.0 || poisson_ratio >= 0.5) {
    throw InvalidInput(fmt::format("poisson_ratio must be in (-1, 0.5), got {}", poisson_ratio));
  }
  return young_modulus_pa / (2.0 * (1.0 - poisson_ratio * poisson_ratio));
}

double damping_per_mass(double dissipative_constant_s, double effective_modulus_pa,
                        double effective_mass_kg) {
  return 2.0 * checked(dissipative_constant_s, "dissipative_constant", true) *
         checked(effective_modulus_pa, "effective_modulus", false) /
         checked(effective_mass_kg, "effective_mass", false);
}

double dissipative_constant_from_damping_per_mass(double damping_per_mass, double effective_modulus_pa,
                                                  double effective_mass_kg) {
  return checked(damping_per_mass, "damping_per_mass", true) *
         checked(effective_mass_kg, "effective_mass", false) /
         (2.0 * checked(effective_modulus_pa, "effective_modulus", false));
}

double beta_of_coefficients(double elastic_coefficient, double damping_coefficient,
                            double effective_mass_kg) {
  const double m = checked(effective_mass_kg, "effective_mass", false);
  const double k = checked(elastic_coefficient, "elastic_coefficient", false) / m;
  const double gamma = checked(damping_coefficient, "damping_coefficient", true) / m;
  return beta_from_gamma(gamma, k);
}

}  // namespace restitution
