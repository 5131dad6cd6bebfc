// SPDX-License-Identifier: BSD-3-Clause
#include "analysis/asymptotics.hpp"

#include <fmt/core.h>

#include <cmath>
#include <numbers>

#include "restitution/errors.hpp"

namespace restitution::asymptotics {
namespace {

double scaled_max_compression() {
  return std::cbrt(1.5 * 1.5);
}  // X_m = (3/2)^{2/3}
double fast_rate() {
  return std::cbrt(1.5);
}  // q = sqrt(X_m) = (3/2)^{1/3}

// ln A, where X_m - X0(T) ~ A e^{-qT} for the δ = 0 compression X0' = 1 - (2/3) X0^{3/2}:
// A = X_m e^{qK}, qK = (3/2) ∫_0^1 [1/(1 - s^{3/2}) - 2/(3(1 - s))] ds = ln 2 + ln(3)/2 - π/(2 sqrt 3).
double log_amplitude() {
  return std::log(scaled_max_compression()) + std::log(2.0) + 0.5 * std::log(3.0) -
         std::numbers::pi / (2.0 * std::sqrt(3.0));
}

void require_positive(double zeta) {
  if (!(zeta > 0.0) || !std::isfinite(zeta))
    throw InvalidInput(fmt::format("the large-zeta laws need a finite zeta > 0, got {}", zeta));
}

// T_e - 5/(2q): the scaled time of the delayed-recovery end minus the offset of the slow drift.
double delayed_end_lag(double delta) {
  const double q = fast_rate();
  return (log_amplitude() - 2.0 * std::log(delta) - 2.5) / q;
}

// Slow-manifold equation of the naive tail: dp/du = -2u²(p + u²)/p.
double slope(double u, double p) {
  return -2.0 * u * u * (p + u * u) / p;
}

// Classical Runge-Kutta from u0 down to 0 with n steps; returns p(0).
double terminal_velocity(double u0, int steps) {
  const double h = -u0 / steps;
  double u = u0;
  double p = -(u0 * u0 + u0 + 1.5);
  for (int i = 0; i < steps; ++i) {
    const double k1 = slope(u, p);
    const double k2 = slope(u + 0.5 * h, p + 0.5 * h * k1);
    const double k3 = slope(u + 0.5 * h, p + 0.5 * h * k2);
    const double k4 = slope(u + h, p + h * k3);
    p += h * (k1 + 2.0 * k2 + 2.0 * k3 + k4) / 6.0;
    u = u0 + (i + 1) * h;
  }
  return p;
}

}  // namespace

double delayed_recovery_prefactor() {
  return scaled_max_compression();
}

Correction delayed_recovery_correction() {
  const double q = fast_rate();
  return {-10.0 / (3.0 * q), (2.5 - log_amplitude()) / q};
}

double delayed_recovery_eps(double zeta, int terms) {
  require_positive(zeta);
  if (terms != 1 && terms != 2) throw InvalidInput(fmt::format("terms must be 1 or 2, got {}", terms));
  const double delta = std::pow(zeta, -5.0 / 3.0);
  const double leading = scaled_max_compression() * delta;
  return terms == 1 ? leading : leading * (1.0 - delta * delayed_end_lag(delta));
}

double delayed_recovery_local_slope(double zeta) {
  require_positive(zeta);
  const double delta = std::pow(zeta, -5.0 / 3.0);
  // d/d ln ζ of ln(1 - δ L(δ)) with dδ/d ln ζ = -(5/3) δ and dL/d ln ζ = (10/3)/q.
  return kDelayedRecoveryExponent + (5.0 / 3.0) * delta * delayed_end_lag(delta) -
         (10.0 / 3.0) * delta / fast_rate();
}

Prefactor naive_prefactor() {
  // Off the slow manifold the deviation contracts like e^{-2u}: starting at u = 40 it is below 1e-30.
  constexpr double kStart = 40.0;
  constexpr int kSteps = 40000;
  const double coarse = terminal_velocity(kStart, kSteps);
  const double fine = terminal_velocity(kStart, 2 * kSteps);
  const double extrapolated = fine + (fine - coarse) / 15.0;  // RK4: error ∝ h^4
  // Rounding errors add up like a random walk over the steps.
  return {-extrapolated,
          std::abs(fine - coarse) / 15.0 + std::abs(extrapolated) * 1e-16 * std::sqrt(2.0 * kSteps)};
}

double naive_eps(double zeta, double kappa) {
  require_positive(zeta);
  return kappa * std::pow(zeta, kNaiveExponent);
}

}  // namespace restitution::asymptotics
