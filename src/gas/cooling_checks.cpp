// SPDX-License-Identifier: BSD-3-Clause
#include "gas/cooling_checks.hpp"

#include <fmt/core.h>

#include <cmath>

#include "restitution/errors.hpp"

namespace restitution::gas {
namespace {

constexpr double kLargestA2 = 0.5;  // the first Sonine correction is a small one

}  // namespace

void require_positive(double value, const char* name, const char* unit) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw InvalidInput(fmt::format("{} must be finite and > 0{}, got {}", name, unit, value));
  }
}

void check_cooling_request(const CoolingRequest& r) {
  require_positive(r.particles.mass_kg, "mass", " kg");
  require_positive(r.particles.diameter_m, "diameter", " m");
  const double phi = r.particles.packing_fraction;
  if (!std::isfinite(phi) || phi <= 0.0 || phi >= 0.5) {
    throw InvalidInput(fmt::format(
        "packing_fraction must be in (0, 0.5) (a homogeneous fluid, below freezing), got {}", phi));
  }
  require_positive(r.initial_temperature_j, "initial_temperature", " J");
  if (r.a2 && (!std::isfinite(*r.a2) || std::abs(*r.a2) > kLargestA2)) {
    throw InvalidInput(
        fmt::format("a2 must be finite with |a2| <= {} (a first correction), got {}", kLargestA2, *r.a2));
  }
  require_positive(r.collision_rate_factor, "collision_rate_factor", "");
}

// The output times: the requested ones, or the log-spaced grid.
std::vector<double> output_times(const CoolingRequest& r, double duration_s) {
  if (!r.times_s.empty()) {
    for (std::size_t i = 0; i < r.times_s.size(); ++i) {
      const double t = r.times_s[i];
      if (!std::isfinite(t) || t <= 0.0 || (i > 0 && t <= r.times_s[i - 1])) {
        throw InvalidInput(fmt::format("times must be finite, > 0 s and ascending; times[{}] = {}", i, t));
      }
    }
    return r.times_s;
  }
  if (r.points_per_decade < 1 || r.points_per_decade > 1000) {
    throw InvalidInput(fmt::format("points_per_decade must be in [1, 1000], got {}", r.points_per_decade));
  }
  const double first = r.first_time_s == 0.0 ? 1e-6 * duration_s : r.first_time_s;
  if (!std::isfinite(first) || first <= 0.0 || first >= duration_s) {
    throw InvalidInput(fmt::format("first_time must be finite, > 0 s and below the duration {} s, got {}",
                                   duration_s, first));
  }
  const double decades = std::log10(duration_s / first);
  const auto intervals = static_cast<int>(std::ceil(decades * r.points_per_decade - 1e-9));
  std::vector<double> times;
  // Counted down from the duration, so that a whole number of decades gives round times.
  for (int i = 0; i <= intervals; ++i) {
    times.push_back(duration_s * std::pow(10.0, -decades * (intervals - i) / intervals));
  }
  return times;
}

double duration_in_seconds(const CoolingRequest& r, double tau0_s) {
  if (!std::isfinite(r.duration) || r.duration <= 0.0) {
    throw InvalidInput(fmt::format("duration must be finite and > 0, got {}", r.duration));
  }
  const double seconds = r.duration_in_haff_times ? r.duration * tau0_s : r.duration;
  if (!std::isfinite(seconds)) throw InvalidInput("duration: too long to represent in seconds");
  return seconds;
}

}  // namespace restitution::gas
