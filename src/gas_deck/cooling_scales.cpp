// SPDX-License-Identifier: BSD-3-Clause
#include "gas_deck/cooling_scales.hpp"

#include <fmt/core.h>

#include <cmath>
#include <numbers>

#include "gas/collision_integral.hpp"
#include "restitution/errors.hpp"

namespace restitution::gas_deck {

GasScales gas_scales(double diameter_m, double mass_kg, double packing_fraction, double temperature_j,
                     double eps) {
  const double phi = packing_fraction;
  if (!(phi > 0.0 && phi < 0.5))
    throw InvalidInput(fmt::format("--packing-fraction must be in (0, 0.5), got {}", phi));
  if (!(eps >= 0.0 && eps < 1.0)) throw InvalidInput(fmt::format("eps must be in [0, 1), got {}", eps));
  const double pi = std::numbers::pi;
  const double sigma = diameter_m;
  GasScales s;
  s.number_density_m3 = gas::number_density_m3(phi, sigma);
  s.pair_correlation = gas::contact_correlation(phi);
  const double n = s.number_density_m3;
  const double g2 = s.pair_correlation;
  s.mean_free_path_m = 1.0 / (std::numbers::sqrt2 * pi * n * sigma * sigma * g2);
  const double b_rho = 4.0 * phi;  // (2 pi / 3) n σ^3
  s.viscosity_factor = 1.0 / g2 + 0.8 * b_rho + 0.7614 * b_rho * b_rho * g2;
  // The kinetic theory's cooling rate for a constant ε (src/gas): ζ = ω (1 − ε²)/3, ω the collision
  // frequency.
  const double cooling_rate =
      gas::collision_frequency_hz(phi, sigma, mass_kg, temperature_j, 0.0) * (1.0 - eps * eps) / 3.0;
  s.haff_time_s = 2.0 / cooling_rate;
  s.shear_critical_length_m = 2.0 * pi * s.mean_free_path_m *
                              std::sqrt(15.0 * pi / 16.0 * g2 * s.viscosity_factor / (1.0 - eps * eps));
  return s;
}

double shear_mode_growth(const GasScales& scales, double box_m, double duration_s) {
  const double ratio = scales.shear_critical_length_m / box_m;
  if (ratio >= 1.0) return 1.0;
  return std::pow(1.0 + duration_s / scales.haff_time_s, 1.0 - ratio * ratio);
}

}  // namespace restitution::gas_deck
