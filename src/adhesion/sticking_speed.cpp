// SPDX-License-Identifier: BSD-3-Clause
// The sticking speed: the impact speed at which the energy left at the break overlap reaches 0
// (docs/adhesion.md §5). Bracketed from the elastic closed form upwards, then Brent's method.
#include <fmt/format.h>

#include <cmath>
#include <utility>

#include "adhesion/adhesive_integration.hpp"
#include "adhesion/adhesive_scales.hpp"
#include "adhesion/sticking_search.hpp"
#include "restitution/adhesion.hpp"
#include "restitution/errors.hpp"

namespace restitution {
namespace {

constexpr int kMaxSolves = 200;

// Brent's method on [low, high] with margin(low) < 0 <= margin(high), to relative width `tolerance` in V.
template <typename Margin>
double brent_root(Margin& margin, double low, double f_low, double high, double f_high, double tolerance) {
  double a = low, fa = f_low, b = high, fb = f_high, c = a, fc = fa, d = b - a, e = d;
  for (;;) {
    if ((fb > 0.0) == (fc > 0.0)) {
      c = a;
      fc = fa;
      d = e = b - a;
    }
    if (std::abs(fc) < std::abs(fb)) {
      a = b, b = c, c = a;
      fa = fb, fb = fc, fc = fa;
    }
    const double half_width_limit = 0.5 * tolerance * std::abs(b);
    const double m = 0.5 * (c - b);
    if (std::abs(m) <= half_width_limit || fb == 0.0) return b;
    if (std::abs(e) >= half_width_limit && std::abs(fa) > std::abs(fb)) {
      double p = 0.0, q = 0.0;
      const double s = fb / fa;
      if (a == c) {  // secant
        p = 2.0 * m * s;
        q = 1.0 - s;
      } else {  // inverse quadratic interpolation
        const double r = fb / fc, t = fa / fc;
        p = s * (2.0 * m * t * (t - r) - (b - a) * (r - 1.0));
        q = (t - 1.0) * (r - 1.0) * (s - 1.0);
      }
      if (p > 0.0) q = -q;
      p = std::abs(p);
      if (2.0 * p < std::min(3.0 * m * q - std::abs(half_width_limit * q), std::abs(e * q))) {
        e = d;
        d = p / q;
      } else {
        d = m;
        e = d;
      }
    } else {
      d = m;
      e = d;
    }
    a = b;
    fa = fb;
    b += std::abs(d) > half_width_limit ? d : (m > 0.0 ? half_width_limit : -half_width_limit);
    fb = margin(b);
  }
}

}  // namespace

namespace adhesion {

StickingSearch search_sticking_speed(const AdhesiveContact& contact, double tolerance) {
  const auto scaled = scale_adhesion(contact);
  if (!(tolerance >= 1e-12 && tolerance <= 1e-2)) {
    throw InvalidInput(
        fmt::format("the tolerance of the sticking speed must lie in [1e-12, 1e-2] (got {})", tolerance));
  }
  StickingSearch result;
  // Elastic: the closed form sqrt(2W/m*) (W = 0 for DMT: it never sticks).
  const double elastic = std::sqrt(2.0 * scaled.break_energy);
  if (scaled.damping == 0.0) {
    result.speed_m_per_s = elastic * scaled.speed_m_per_s();
    return result;
  }
  auto margin = [&](double speed) {
    if (++result.solves > kMaxSolves) {
      throw NumericalFailure(
          fmt::format("the sticking speed was not bracketed within {} solves", kMaxSolves));
    }
    // The root is needed to T in V: the margin to a little better.
    return integrate_adhesive(scaled, speed, 0.1 * tolerance).energy_margin;
  };
  // Damping only adds losses: the elastic value is a lower bound (DMT's is 0: start from its unit speed).
  double low = elastic > 0.0 ? elastic : 1.0;
  double f_low = margin(low);
  double high = low;
  double f_high = f_low;
  while (f_low >= 0.0) {  // only for DMT, whose start is a guess
    high = low, f_high = f_low;
    low *= 0.25;
    f_low = margin(low);
  }
  while (f_high < 0.0) {
    if (high >= kLargestScaledSpeed) {  // stuck all the way up: no sticking speed
      result.largest_tried_m_per_s = high * scaled.speed_m_per_s();
      return result;
    }
    low = high, f_low = f_high;
    high *= 2.0;
    f_high = margin(high);
  }
  result.speed_m_per_s = brent_root(margin, low, f_low, high, f_high, tolerance) * scaled.speed_m_per_s();
  return result;
}

}  // namespace adhesion

StickingSpeed sticking_speed(const AdhesiveContact& contact, double tolerance) {
  const adhesion::StickingSearch search = adhesion::search_sticking_speed(contact, tolerance);
  if (!search.speed_m_per_s) {
    throw InvalidInput(fmt::format(
        "no sticking speed: the spheres stick at every impact speed tried, up to {:.6g} m/s ({} solves); the "
        "damping takes all the energy at every speed (above a critical damping eps(v) = 0 for all v)",
        search.largest_tried_m_per_s, search.solves));
  }
  return {*search.speed_m_per_s, search.solves};
}

}  // namespace restitution
