// SPDX-License-Identifier: BSD-3-Clause
#include "restitution_gas/cooling.hpp"
#include "gas/collision_integral.hpp"

#include <fmt/core.h>

#include <array>
#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <numbers>
#include <string>

#include "restitution/errors.hpp"

namespace restitution::gas {
namespace {

constexpr int kNodes = 12;           // Gauss–Legendre nodes per panel
constexpr double kPanelWidth = 0.5;  // in x = ln(T₀/T): e^{x/2} and J are resolved to rounding
constexpr double kLargestX = 690.0;  // T₀ e^{−x} stays a normal double for T₀ up to 1e0
constexpr double kLargestA2 = 0.5;   // the first Sonine correction is a small one

void require_positive(double value, const char* name, const char* unit) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw InvalidInput(fmt::format("{} must be finite and > 0{}, got {}", name, unit, value));
  }
}

void check(const CoolingRequest& r) {
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

// 12-point Gauss–Legendre on [-1, 1] and the barycentric weights of its nodes.
struct Rule {
  std::array<double, kNodes> node{}, weight{}, barycentric{};
  Rule() {
    using G = boost::math::quadrature::gauss<double, kNodes>;
    const auto& a = G::abscissa();
    const auto& w = G::weights();
    for (int i = 0; i < kNodes / 2; ++i) {
      const auto k = static_cast<std::size_t>(i);
      node[kNodes / 2 - 1 - k] = -a[k];
      node[kNodes / 2 + k] = a[k];
      weight[kNodes / 2 - 1 - k] = w[k];
      weight[kNodes / 2 + k] = w[k];
    }
    for (std::size_t j = 0; j < kNodes; ++j) {
      double product = 1.0;
      for (std::size_t i = 0; i < kNodes; ++i) {
        if (i != j) product *= node[j] - node[i];
      }
      barycentric[j] = 1.0 / product;
    }
  }
  // The interpolant through (node, values) at ξ.
  [[nodiscard]] double interpolate(const std::array<double, kNodes>& values, double xi) const {
    double num = 0.0;
    double den = 0.0;
    for (std::size_t j = 0; j < kNodes; ++j) {
      const double d = xi - node[j];
      if (d == 0.0) return values[j];
      const double c = barycentric[j] / d;
      num += c * values[j];
      den += c;
    }
    return num / den;
  }
  // ∫_{-1}^{ξ} of the interpolant (exact: it is a polynomial of degree 11).
  [[nodiscard]] double integral_to(const std::array<double, kNodes>& values, double xi) const {
    const double half = 0.5 * (xi + 1.0);
    double sum = 0.0;
    for (std::size_t i = 0; i < kNodes; ++i)
      sum += weight[i] * interpolate(values, -1.0 + half * (node[i] + 1.0));
    return half * sum;
  }
};

// One panel [x, x + kPanelWidth] of the quadrature: dt/dx = 1/ζ and dN/dx = ω/ζ at the nodes, and t, N at x.
struct Panel {
  double x = 0.0, time_s = 0.0, collisions = 0.0;
  std::array<double, kNodes> time_rate{}, collision_rate{};
};

class Gas {
 public:
  explicit Gas(const CoolingRequest& r)
      : r_(r),
        dissipation_(r.law, r.tolerance),
        integral_(dissipation_, r.particles.mass_kg, r.a2.value_or(0.0)) {
    const double n = number_density_m3(r.particles.packing_fraction, r.particles.diameter_m);
    const double sigma = r.particles.diameter_m;
    rate_coefficient_ = 4.0 * std::sqrt(std::numbers::pi) / 3.0 * n *
                        contact_correlation(r.particles.packing_fraction) * sigma * sigma /
                        std::sqrt(r.particles.mass_kg) * r.collision_rate_factor;
  }
  // ζ(T) [1/s].
  double cooling_rate(double temperature_j) {
    return rate_coefficient_ * std::sqrt(temperature_j) * integral_.mean_loss(temperature_j);
  }
  [[nodiscard]] double collision_frequency(double temperature_j) const {
    return r_.collision_rate_factor * collision_frequency_hz(r_.particles.packing_fraction,
                                                             r_.particles.diameter_m, r_.particles.mass_kg,
                                                             temperature_j, integral_.a2());
  }
  CollisionIntegral& integral() { return integral_; }

 private:
  const CoolingRequest& r_;
  ImpactDissipation dissipation_;
  CollisionIntegral integral_;
  double rate_coefficient_ = 0.0;
};

Panel make_panel(Gas& gas, const Rule& rule, double x, double time_s, double collisions, double t0) {
  Panel p{x, time_s, collisions, {}, {}};
  for (std::size_t j = 0; j < kNodes; ++j) {
    const double temperature = t0 * std::exp(-(x + 0.5 * kPanelWidth * (rule.node[j] + 1.0)));
    const double rate = gas.cooling_rate(temperature);
    p.time_rate[j] = 1.0 / rate;
    p.collision_rate[j] = gas.collision_frequency(temperature) / rate;
  }
  return p;
}

// ξ ∈ [-1, 1] in the panel where t(ξ) = target, by safeguarded Newton.
double solve_in_panel(const Panel& p, const Rule& rule, double target) {
  const double half = 0.5 * kPanelWidth;
  double lo = -1.0;
  double hi = 1.0;
  double xi = 0.0;
  for (int iteration = 0; iteration < 60; ++iteration) {
    const double residual = p.time_s + half * rule.integral_to(p.time_rate, xi) - target;
    if (residual == 0.0) break;
    (residual > 0.0 ? hi : lo) = xi;
    double next = xi - residual / (half * rule.interpolate(p.time_rate, xi));
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - xi) <= 1e-15) return next;
    xi = next;
  }
  return xi;
}

}  // namespace

HaffReference haff_reference(const CoolingRequest& request) {
  check(request);
  Gas gas(request);
  const double rate = gas.cooling_rate(request.initial_temperature_j);
  if (!(rate > 0.0)) {
    throw InvalidInput("the law loses no energy at these speeds (eps = 1): the gas does not cool");
  }
  const double eps = request.law.constant_eps ? *request.law.constant_eps
                                              : gas.integral().effective_eps(request.initial_temperature_j);
  return {2.0 / rate, eps};
}

CoolingCurve cooling_curve(const CoolingRequest& request) {
  check(request);
  const double t0 = request.initial_temperature_j;
  CoolingCurve c;
  c.contact_correlation = contact_correlation(request.particles.packing_fraction);
  c.number_density_m3 = number_density_m3(request.particles.packing_fraction, request.particles.diameter_m);
  c.a2 = request.a2.value_or(0.0);
  const HaffReference haff = haff_reference(request);
  c.tau0_s = haff.tau0_s;
  c.haff_eps = haff.eps;
  Gas gas(request);
  if (!std::isfinite(request.duration) || request.duration <= 0.0) {
    throw InvalidInput(fmt::format("duration must be finite and > 0, got {}", request.duration));
  }
  c.duration_s = request.duration_in_haff_times ? request.duration * c.tau0_s : request.duration;
  if (!std::isfinite(c.duration_s)) throw InvalidInput("duration: too long to represent in seconds");
  const std::vector<double> times = output_times(request, c.duration_s);

  const Rule rule;
  Panel panel = make_panel(gas, rule, 0.0, 0.0, 0.0, t0);
  for (const double t : times) {
    for (;;) {
      const double end_time = panel.time_s + 0.5 * kPanelWidth * rule.integral_to(panel.time_rate, 1.0);
      if (t <= end_time) break;
      const double end_collisions =
          panel.collisions + 0.5 * kPanelWidth * rule.integral_to(panel.collision_rate, 1.0);
      const double x = panel.x + kPanelWidth;
      if (x > kLargestX) {
        throw InvalidInput(fmt::format(
            "duration: by t = {:.6g} s the gas has cooled to T0 e^-{:g}; the time {:.6g} s lies beyond",
            end_time, kLargestX, t));
      }
      panel = make_panel(gas, rule, x, end_time, end_collisions, t0);
    }
    const double xi = solve_in_panel(panel, rule, t);
    const double temperature = t0 * std::exp(-(panel.x + 0.5 * kPanelWidth * (xi + 1.0)));
    const double rate = gas.cooling_rate(temperature);
    c.time_s.push_back(t);
    c.temperature_j.push_back(temperature);
    const double haff_factor = 1.0 + t / c.tau0_s;
    c.haff_temperature_j.push_back(t0 / (haff_factor * haff_factor));
    c.cooling_rate_hz.push_back(rate);
    c.local_exponent.push_back(-t * rate);
    c.collision_frequency_hz.push_back(gas.collision_frequency(temperature));
    c.collisions_per_particle.push_back(panel.collisions +
                                        0.5 * kPanelWidth * rule.integral_to(panel.collision_rate, xi));
    c.effective_eps.push_back(gas.integral().effective_eps(temperature));
  }
  return c;
}

}  // namespace restitution::gas
