// SPDX-License-Identifier: BSD-3-Clause
#include "gas/collision_integral.hpp"

#include <fmt/core.h>

#include <cmath>
#include <numbers>

#include "restitution/errors.hpp"

namespace restitution::gas {
namespace {

constexpr double kLowestZ = 1e-7;   // the z² tail below holds 5e-15 of J
constexpr double kHighestZ = 60.0;  // the e^{−z} tail above holds 1e-23
constexpr double kStep = 0.25;      // in ln z: discretization error ~exp(−π²/h) = 7e-18

}  // namespace

double contact_correlation(double packing_fraction) {
  const double phi = packing_fraction;
  return (1.0 - 0.5 * phi) / ((1.0 - phi) * (1.0 - phi) * (1.0 - phi));
}

double number_density_m3(double packing_fraction, double diameter_m) {
  return 6.0 * packing_fraction / (std::numbers::pi * diameter_m * diameter_m * diameter_m);
}

double collision_frequency_hz(double packing_fraction, double diameter_m, double mass_kg,
                              double temperature_j, double a2) {
  const double n = number_density_m3(packing_fraction, diameter_m);
  return 4.0 * std::sqrt(std::numbers::pi) * n * contact_correlation(packing_fraction) * diameter_m *
         diameter_m * std::sqrt(temperature_j / mass_kg) * (1.0 - a2 / 16.0);
}

double sonine_a2_constant_eps(double eps) {
  return 16.0 * (1.0 - eps) * (1.0 - 2.0 * eps * eps) / (81.0 - 17.0 * eps + 30.0 * eps * eps * (1.0 - eps));
}

CollisionIntegral::CollisionIntegral(ImpactDissipation& dissipation, double mass_kg, double a2)
    : dissipation_(&dissipation), mass_kg_(mass_kg), a2_(a2) {
  const double half_exponent = 0.5 * dissipation.speed_exponent();
  const double lo = std::log(kLowestZ);
  const auto count = static_cast<int>(std::ceil((std::log(kHighestZ) - lo) / kStep)) + 1;
  for (int k = 0; k < count; ++k) {
    const double z = std::exp(lo + kStep * k);
    const double sonine = 1.0 + 0.5 * a2 * (0.5 * z * z - 1.5 * z + 0.375);
    weights_.push_back(kStep * z * z * std::exp(-z) * sonine);
    zeta_factors_.push_back(std::pow(z, half_exponent));
  }
}

double CollisionIntegral::mean_loss(double temperature_j) {
  if (!(temperature_j > 0.0) || !std::isfinite(temperature_j)) {
    throw InvalidInput(fmt::format("temperature must be finite and > 0 J, got {}", temperature_j));
  }
  const double thermal_zeta = dissipation_->zeta_at_speed(2.0 * std::sqrt(temperature_j / mass_kg_));
  double sum = 0.0;
  for (std::size_t k = 0; k < weights_.size(); ++k) {
    sum += weights_[k] * dissipation_->loss_at_zeta(thermal_zeta * zeta_factors_[k]);
  }
  return sum;
}

double CollisionIntegral::effective_eps(double temperature_j) {
  const double loss = mean_loss(temperature_j) / (1.0 + 3.0 * a2_ / 16.0);
  return std::sqrt(std::max(0.0, 1.0 - loss));
}

}  // namespace restitution::gas
