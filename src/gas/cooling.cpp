// SPDX-License-Identifier: BSD-3-Clause
#include "restitution_gas/cooling.hpp"
#include "gas/collision_integral.hpp"
#include "gas/cooling_checks.hpp"

#include <fmt/core.h>

#include <Eigen/Dense>
#include <algorithm>
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
// With an evolving a₂ its relaxation is stiff when the dissipation is small (the rate in x, |∂F/∂a₂| with
// F = da₂/dx, grows as 1/(1 − ε²)). Gauss collocation is A-stable but does not damp a fast transient (its
// amplification, the (12, 12) Padé approximant of e^{λw}, tends to 1), so panels are narrowed to
// |∂F/∂a₂| · width <= kLargestStiffness until the transient from the initial a₂ has decayed by
// e^{−kTransientDecay}; after that a₂ is smooth on the slow scale of the cooling and full panels resolve it.
// (Measured for a constant ε = 0.95 against the exact a₂: 9e-13 with 4, 4e-10 with 8.)
constexpr double kLargestStiffness = 4.0;
constexpr double kTransientDecay = 40.0;

using Matrix = Eigen::Matrix<double, kNodes, kNodes>;

// 12-point Gauss–Legendre on [-1, 1], the barycentric weights of its nodes and the collocation matrix
// A_jk = ∫_{-1}^{ξ_j} ℓ_k (ℓ_k the Lagrange polynomial of node k). A point of a panel is given by its
// distance s = ξ + 1 ∈ [0, 2] from the panel's start, not by ξ: near the start ξ = −1 + s would round s to
// 1e-16 absolute, and with it the time and the collisions of the first instants (t = 1e-12 τ₀ was off by
// 1e-4 relative, and no count fell below 2e-15).
struct Rule {
  std::array<double, kNodes> node{}, weight{}, barycentric{};
  Matrix collocation;
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
    for (std::size_t k = 0; k < kNodes; ++k) {
      std::array<double, kNodes> unit{};
      unit[k] = 1.0;
      for (std::size_t j = 0; j < kNodes; ++j) {
        collocation(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(k)) =
            integral_to(unit, node[j] + 1.0);
      }
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
  // ∫_{-1}^{-1+s} of the interpolant (exact: it is a polynomial of degree 11), relative to rounding for
  // every s in [0, 2].
  [[nodiscard]] double integral_to(const std::array<double, kNodes>& values, double s) const {
    const double half = 0.5 * s;
    double sum = 0.0;
    for (std::size_t i = 0; i < kNodes; ++i)
      sum += weight[i] * interpolate(values, -1.0 + half * (node[i] + 1.0));
    return half * sum;
  }
};

// One panel [x, x + width] of the quadrature: dt/dx = 1/ζ (in the gas's unit of time, Gas below), dN/dx = ω/ζ
// and (evolving) da₂/dx at the nodes, and t, N, a₂ at x.
struct Panel {
  double x = 0.0, width = kPanelWidth, time = 0.0, collisions = 0.0, a2 = 0.0;  // time in the gas's unit
  double relaxation = 0.0;  // evolving a₂: ∫|∂F/∂a₂| dx up to x + width, how far its transient has decayed
  std::array<double, kNodes> time_rate{}, collision_rate{}, a2_rate{};
  // The integral over [x, x + s width/2] of the interpolant of these rates at the nodes.
  [[nodiscard]] double integral(const Rule& rule, const std::array<double, kNodes>& rates, double s) const {
    return 0.5 * width * rule.integral_to(rates, s);
  }
};

// da₂/dx = (da₂/dt)/ζ and its derivative in a₂. With B = n g₂ σ² v_T the moment equations of Brilliantov &
// Pöschel (2000) are dT/dt = −(2/3) B μ₂ T and da₂/dt = (4/3) B μ₂ (1 + a₂) − (4/15) B μ₄, the latter
// linearised in a₂ as there; ζ = (2/3) B μ₂, so B cancels (and with it the collision-rate factor):
//     F = [2(μ₂ + a₂(μ₂ + μ₂')) − (2/5)(μ₄ + a₂ μ₄')]/(μ₂ + a₂ μ₂'),  μ' the a₂ parts (SonineMoments).
struct Slope {
  double value = 0.0, derivative = 0.0;
};
Slope sonine_slope(const SonineMoments& m, double a2) {
  const double p = 2.0 * m.mu2 - 0.4 * m.mu4;
  const double q = 2.0 * (m.mu2 + m.mu2_a2) - 0.4 * m.mu4_a2;
  const double d = m.mu2 + a2 * m.mu2_a2;
  return {(p + q * a2) / d, (q * m.mu2 - m.mu2_a2 * p) / (d * d)};
}

// a₂ at the panel's nodes: the Gauss collocation Y_j = a₂(x) + (w/2) Σ_k A_jk F(x_k, Y_k) (A-stable, order 24
// at the end), solved by Newton's method.
std::array<double, kNodes> collocate_a2(const Rule& rule, const std::array<SonineMoments, kNodes>& moments,
                                        double a2_start, double width) {
  using Vector = Eigen::Matrix<double, kNodes, 1>;
  Vector y = Vector::Constant(a2_start);
  for (int iteration = 0; iteration < 50; ++iteration) {
    Vector slope;
    Vector derivative;
    for (Eigen::Index j = 0; j < kNodes; ++j) {
      const Slope f = sonine_slope(moments[static_cast<std::size_t>(j)], y(j));
      slope(j) = f.value;
      derivative(j) = f.derivative;
    }
    const Vector residual = y - Vector::Constant(a2_start) - 0.5 * width * rule.collocation * slope;
    const Matrix jacobian = Matrix::Identity() - 0.5 * width * rule.collocation * derivative.asDiagonal();
    const Vector step = jacobian.partialPivLu().solve(residual);
    y -= step;
    if (step.cwiseAbs().maxCoeff() <= 1e-15) break;
  }
  std::array<double, kNodes> out{};
  for (std::size_t j = 0; j < kNodes; ++j) out[j] = y(static_cast<Eigen::Index>(j));
  return out;
}

// The gas's rates in units of its own time scale: ζ(T) = ζ̂(T)/time_unit with ζ̂ = √(T/T₀) J(T) and
// time_unit = 1/((4√π/3) n g₂ σ² √(T₀/m)) [s], taken in logarithms (n σ² = 6φ/(πσ)). In seconds the rates
// and their interpolation overflow where the gas is dilute enough (φ = 1e-300: τ₀ ≈ 1e292 s, 1/ζ beyond a
// double after some cooling); scaled they are of order e^{x/2}/J whatever φ, σ, m and T₀.
class Gas {
 public:
  explicit Gas(const CoolingRequest& r)
      : r_(r),
        dissipation_(r.law, r.tolerance),
        integral_(dissipation_, r.particles.mass_kg, r.a2.value_or(0.0)) {
    const GasParticles& p = r.particles;
    const double log_rate_coefficient =
        std::log(4.0 * std::sqrt(std::numbers::pi) / 3.0 * 6.0 / std::numbers::pi) +
        std::log(p.packing_fraction) + std::log(contact_correlation(p.packing_fraction)) -
        std::log(p.diameter_m) - 0.5 * std::log(p.mass_kg) + std::log(r.collision_rate_factor);
    log_time_unit_ = -log_rate_coefficient - 0.5 * std::log(r.initial_temperature_j);
    time_unit_s_ = std::exp(log_time_unit_);
  }
  // ζ(T) · time_unit with the mean loss J of the moment.
  [[nodiscard]] double scaled_cooling_rate(double temperature_j, double mean_loss) const {
    return std::sqrt(temperature_j / r_.initial_temperature_j) * mean_loss;
  }
  // ω/ζ, the collisions per unit of ln(T₀/T): ω = 4√π n g₂ σ² √(T/m) (1 − a₂/16) (collision_frequency_hz)
  // and ζ = (4√π/3) n g₂ σ² √(T/m) J share all but 3 (1 − a₂/16)/J, and their ratio never underflows.
  [[nodiscard]] static double collisions_per_cooling(double mean_loss, double a2) {
    return 3.0 * (1.0 - a2 / 16.0) / mean_loss;
  }
  [[nodiscard]] double collision_frequency(double temperature_j, double a2) const {
    return r_.collision_rate_factor * collision_frequency_hz(r_.particles.packing_fraction,
                                                             r_.particles.diameter_m, r_.particles.mass_kg,
                                                             temperature_j, a2);
  }
  [[nodiscard]] double time_unit_s() const { return time_unit_s_; }
  [[nodiscard]] double log_time_unit() const { return log_time_unit_; }
  CollisionIntegral& integral() { return integral_; }

 private:
  const CoolingRequest& r_;
  ImpactDissipation dissipation_;
  CollisionIntegral integral_;
  double log_time_unit_ = 0.0, time_unit_s_ = 0.0;
};

// The panel from x with a₂ held constant.
Panel make_panel(Gas& gas, const Rule& rule, double x, double time, double collisions, double t0) {
  Panel p{x, kPanelWidth, time, collisions, gas.integral().a2(), {}, {}, {}};
  for (std::size_t j = 0; j < kNodes; ++j) {
    const double temperature = t0 * std::exp(-(x + 0.5 * p.width * (rule.node[j] + 1.0)));
    const double loss = gas.integral().mean_loss(temperature);
    p.time_rate[j] = 1.0 / gas.scaled_cooling_rate(temperature, loss);
    p.collision_rate[j] = Gas::collisions_per_cooling(loss, p.a2);
  }
  return p;
}

// The panel from x with a₂ evolving from a2 there, narrowed while its initial transient is stiff; relaxation:
// how far the transient has decayed by x.
Panel make_evolving_panel(Gas& gas, const Rule& rule, double x, double time, double collisions, double a2,
                          double relaxation, double t0) {
  const double stiffness = std::abs(sonine_slope(gas.integral().moments(t0 * std::exp(-x)), a2).derivative);
  const double width =
      relaxation < kTransientDecay ? std::min(kPanelWidth, kLargestStiffness / stiffness) : kPanelWidth;
  Panel p{x, width, time, collisions, a2, {}, {}, {}};
  p.relaxation = relaxation + stiffness * width;
  std::array<SonineMoments, kNodes> moments{};
  std::array<double, kNodes> temperature{};
  for (std::size_t j = 0; j < kNodes; ++j) {
    temperature[j] = t0 * std::exp(-(x + 0.5 * p.width * (rule.node[j] + 1.0)));
    moments[j] = gas.integral().moments(temperature[j]);
  }
  const std::array<double, kNodes> a2_nodes = collocate_a2(rule, moments, a2, p.width);
  for (std::size_t j = 0; j < kNodes; ++j) {
    const double loss = moments[j].mean_loss(a2_nodes[j]);
    p.time_rate[j] = 1.0 / gas.scaled_cooling_rate(temperature[j], loss);
    p.collision_rate[j] = Gas::collisions_per_cooling(loss, a2_nodes[j]);
    p.a2_rate[j] = sonine_slope(moments[j], a2_nodes[j]).value;
  }
  return p;
}

Panel next_panel(Gas& gas, const Rule& rule, const Panel& p, bool evolving, double t0) {
  const double x = p.x + p.width;
  const double time = p.time + p.integral(rule, p.time_rate, 2.0);
  if (x > kLargestX) {
    throw InvalidInput(fmt::format(
        "duration: by t = {:.6g} s the gas has cooled to T0 e^-{:g}; the times asked for lie beyond",
        time * gas.time_unit_s(), kLargestX));
  }
  const double collisions = p.collisions + p.integral(rule, p.collision_rate, 2.0);
  if (!evolving) return make_panel(gas, rule, x, time, collisions, t0);
  return make_evolving_panel(gas, rule, x, time, collisions, p.a2 + p.integral(rule, p.a2_rate, 2.0),
                             p.relaxation, t0);
}

// s = ξ + 1 ∈ [0, 2] in the panel where its time (in the gas's unit) is `target`, by safeguarded Newton, to
// rounding relative to s (the time is convex and increasing in s, so Newton's steps approach the root from
// above without overshooting it).
double solve_in_panel(const Panel& p, const Rule& rule, double target) {
  const double half = 0.5 * p.width;
  double lo = 0.0;
  double hi = 2.0;
  double s = 1.0;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double residual = p.time + half * rule.integral_to(p.time_rate, s) - target;
    if (residual == 0.0) break;
    (residual > 0.0 ? hi : lo) = s;
    double next = s - residual / (half * rule.interpolate(p.time_rate, s - 1.0));
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - s) <= 1e-15 * next) return next;
    s = next;
  }
  return s;
}

// ln τ₀ = ln(2 time_unit/J(T₀)) of the gas, and τ₀ refused outside [kShortestHaffTimeS, kLongestHaffTimeS].
double checked_log_haff_time(Gas& gas, const CoolingRequest& request) {
  const double loss = gas.integral().mean_loss(request.initial_temperature_j);
  if (!(loss > 0.0)) {
    throw InvalidInput("the law loses no energy at these speeds (eps = 1): the gas does not cool");
  }
  return std::log(2.0) + gas.log_time_unit() - std::log(loss);
}

void check_haff_time(double log_tau0) {
  if (log_tau0 < std::log(kShortestHaffTimeS) || log_tau0 > std::log(kLongestHaffTimeS)) {
    throw InvalidInput(fmt::format(
        "the Haff time tau0 = 1e{:.0f} s of these spheres, packing_fraction and initial_temperature lies "
        "outside [{:g}, {:g}] s, where the theory's times and rates are doubles",
        log_tau0 / std::log(10.0), kShortestHaffTimeS, kLongestHaffTimeS));
  }
}

}  // namespace

double log_haff_time(const CoolingRequest& request) {
  check_cooling_request(request);
  Gas gas(request);
  return checked_log_haff_time(gas, request);
}

HaffReference haff_reference(const CoolingRequest& request) {
  check_cooling_request(request);
  Gas gas(request);
  const double log_tau0 = checked_log_haff_time(gas, request);
  check_haff_time(log_tau0);
  const double eps = request.law.constant_eps ? *request.law.constant_eps
                                              : gas.integral().effective_eps(request.initial_temperature_j);
  return {std::exp(log_tau0), eps};
}

CoolingCurve cooling_curve(const CoolingRequest& request) {
  check_cooling_request(request);
  const double t0 = request.initial_temperature_j;
  CoolingCurve c;
  c.contact_correlation = contact_correlation(request.particles.packing_fraction);
  c.number_density_m3 = number_density_m3(request.particles.packing_fraction, request.particles.diameter_m);
  c.a2 = request.a2.value_or(0.0);
  c.a2_evolving = request.a2_evolving;
  const HaffReference haff = haff_reference(request);
  c.tau0_s = haff.tau0_s;
  c.haff_eps = haff.eps;
  Gas gas(request);
  c.duration_s = duration_in_seconds(request, c.tau0_s);
  const std::vector<double> times = output_times(request, c.duration_s);

  const Rule rule;
  const bool evolving = request.a2_evolving;
  const double unit = gas.time_unit_s();
  Panel panel = evolving ? make_evolving_panel(gas, rule, 0.0, 0.0, 0.0, c.a2, 0.0, t0)
                         : make_panel(gas, rule, 0.0, 0.0, 0.0, t0);
  for (const double t : times) {
    const double target = t / unit;
    while (target > panel.time + panel.integral(rule, panel.time_rate, 2.0)) {
      panel = next_panel(gas, rule, panel, evolving, t0);
    }
    const double s = solve_in_panel(panel, rule, target);
    const double temperature = t0 * std::exp(-(panel.x + 0.5 * panel.width * s));
    const double a2 = evolving ? panel.a2 + panel.integral(rule, panel.a2_rate, s) : c.a2;
    const double mean_loss =
        evolving ? gas.integral().moments(temperature).mean_loss(a2) : gas.integral().mean_loss(temperature);
    const double scaled_rate = gas.scaled_cooling_rate(temperature, mean_loss);
    c.time_s.push_back(t);
    c.temperature_j.push_back(temperature);
    const double haff_factor = 1.0 + t / c.tau0_s;
    c.haff_temperature_j.push_back(t0 / (haff_factor * haff_factor));
    c.cooling_rate_hz.push_back(scaled_rate / unit);
    c.local_exponent.push_back(-target * scaled_rate);
    c.collision_frequency_hz.push_back(gas.collision_frequency(temperature, a2));
    c.collisions_per_particle.push_back(panel.collisions + panel.integral(rule, panel.collision_rate, s));
    c.effective_eps.push_back(effective_eps_of(mean_loss, a2));
    if (evolving) c.sonine_a2.push_back(a2);
  }
  return c;
}

}  // namespace restitution::gas
