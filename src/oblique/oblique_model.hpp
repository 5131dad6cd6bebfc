// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The oblique contact in the natural units of its normal law (time T, length v_n T, velocity v_n, force
// m* v_n/T; ContactLaw::physical): the state, the forces of each mode and the root functions of the switches.
// Private to the oblique module (solve_oblique's CVODE driver evaluates it).
//
// The stick/slip switches are those of LAMMPS's step (pair_granular.cpp:478-533) as dt -> 0:
//  * stick -> slip where the trial force -κξ - g s (history) or -g s (no history) reaches the cap C = μ|f_n|;
//  * slip -> stick, history models: LAMMPS rescales ξ to the cap every step, ξ = -(σC + g s)/κ, and then adds
//    s dt; the next trial force stays beyond the cap while
//        h = C' + σ(κ s + (g s)') - (κ'/κ)(C + σ g s) < 0,
//    so the contact sticks again where h crosses 0 upwards (for a constant cap without damping: where s = 0);
//  * slip -> stick, linear_nohistory: where g|s| falls below C.
#include <array>
#include <cmath>

#include "law/law_rhs.hpp"
#include "oblique/oblique_contact.hpp"

namespace restitution::oblique::detail {

inline constexpr int kStateSize = 6;
using State = std::array<double, kStateSize>;
// δ, δ', tangential displacement ξ (history), u, R1 ω1, R2 ω2, each in natural units.
enum Index {
  kOverlap = 0,
  kOverlapRate = 1,
  kDisplacement = 2,
  kTangential = 3,
  kSpinFirst = 4,
  kSpinSecond = 5
};

struct NaturalModel {
  ContactLaw law;
  TangentialKind kind = TangentialKind::linear_history;
  double friction = 0.0;        // μ
  double stiffness = 0.0;       // κ (linear_history), or κ_m with κ = κ_m sqrt(x) (mindlin)
  double damping_factor = 0.0;  // γ_t: g(x) = γ_t c_d w(x)
  // ρ_i(x) = rotation_base_i - rotation_slope_i x: d(R_i ω_i)/dτ = ρ_i f_t.
  std::array<double, 2> rotation_base{};
  std::array<double, 2> rotation_slope{};

  [[nodiscard]] bool has_history() const { return kind != TangentialKind::linear_nohistory; }

  [[nodiscard]] double normal_force(double x, double v) const { return -law_rhs::acceleration(law, x, v); }
  // d f_n/dτ along the motion (x'' = -f_n).
  [[nodiscard]] double normal_force_rate(double x, double v) const {
    const double fn = normal_force(x, v);
    return law_rhs::shape_derivative(law, x) * v * law_rhs::force_factor(law, x, v) +
           law_rhs::shape(law, x) *
               (law.damping() * -fn + law.stiffness() * law_rhs::elastic_slope(law, x) * v);
  }
  [[nodiscard]] double cap(double x, double v) const { return friction * std::abs(normal_force(x, v)); }
  [[nodiscard]] double cap_rate(double x, double v) const {
    const double fn = normal_force(x, v);
    return friction * (fn < 0.0 ? -1.0 : 1.0) * normal_force_rate(x, v);
  }
  [[nodiscard]] double tangential_damping(double x) const {
    return damping_factor * law.damping() * law_rhs::shape(law, x);
  }
  [[nodiscard]] double tangential_damping_rate(double x, double v) const {
    return damping_factor * law.damping() * law_rhs::shape_derivative(law, x) * v;
  }
  [[nodiscard]] double tangential_stiffness(double x) const {
    return kind == TangentialKind::mindlin ? stiffness * std::sqrt(std::max(x, 0.0)) : stiffness;
  }
  // κ'/κ
  [[nodiscard]] double stiffness_log_rate(double x, double v) const {
    return kind == TangentialKind::mindlin && x > 0.0 ? 0.5 * v / x : 0.0;
  }
  // d s/dτ per unit tangential force: 1 + ρ1 + ρ2.
  [[nodiscard]] double mobility(double x) const {
    return 1.0 + (rotation_base[0] - rotation_slope[0] * x) + (rotation_base[1] - rotation_slope[1] * x);
  }
  [[nodiscard]] static double slip_velocity(const State& y) {
    return y[kTangential] + y[kSpinFirst] + y[kSpinSecond];
  }
  // The force below the cap: -κξ - g s (history) or -g s.
  [[nodiscard]] double trial_force(const State& y) const {
    const double s = slip_velocity(y);
    const double viscous = -tangential_damping(y[kOverlap]) * s;
    return has_history() ? viscous - tangential_stiffness(y[kOverlap]) * y[kDisplacement] : viscous;
  }
  // The tangential force on the first body in a mode (sign: the direction of the capped force, ±1).
  [[nodiscard]] double tangential_force(const State& y, ContactMode mode, double sign) const {
    return mode == ContactMode::stick ? trial_force(y) : sign * cap(y[kOverlap], y[kOverlapRate]);
  }

  void rates(const State& y, ContactMode mode, double sign, State& dy) const {
    const double x = y[kOverlap];
    const double v = y[kOverlapRate];
    const double ft = tangential_force(y, mode, sign);
    dy[kOverlap] = v;
    dy[kOverlapRate] = law_rhs::acceleration(law, x, v);
    dy[kDisplacement] = mode == ContactMode::stick && has_history() ? slip_velocity(y) : 0.0;
    dy[kTangential] = ft;
    dy[kSpinFirst] = (rotation_base[0] - rotation_slope[0] * x) * ft;
    dy[kSpinSecond] = (rotation_base[1] - rotation_slope[1] * x) * ft;
  }

  // The root function of the switch out of `mode`: crosses 0 downwards (stick) or upwards (history slip).
  [[nodiscard]] double switch_function(const State& y, ContactMode mode, double sign) const {
    const double x = y[kOverlap];
    const double v = y[kOverlapRate];
    const double c = cap(x, v);
    if (mode == ContactMode::stick) return c - std::abs(trial_force(y));
    const double s = slip_velocity(y);
    const double g = tangential_damping(x);
    if (!has_history()) return g * std::abs(s) - c;
    const double ds = sign * c * mobility(x);
    const double dgs = tangential_damping_rate(x, v) * s + g * ds;
    return cap_rate(x, v) + sign * (tangential_stiffness(x) * s + dgs) -
           stiffness_log_rate(x, v) * (c + sign * g * s);
  }
  // Whether leaving `mode` where its switch function crossed 0 agrees with the rate of the force against the
  // cap. Just after a switch the new mode's function starts at 0 and is tangent to it, so the integration
  // error can cross it again at once: such a crossing is not a switch (the stick of a history model persists
  // where h > 0, the trial force growing no faster than the cap; linear_nohistory's viscous force leaves the
  // cap where g|s| - C falls).
  [[nodiscard]] bool leaving_is_consistent(const State& y, ContactMode mode, double sign) const {
    const double x = y[kOverlap];
    const double v = y[kOverlapRate];
    if (has_history()) {
      if (mode == ContactMode::slip) return true;
      const double trial_sign = trial_force(y) < 0.0 ? -1.0 : 1.0;
      return switch_function(y, ContactMode::slip, trial_sign) < 0.0;
    }
    const double s = slip_velocity(y);
    const double force = tangential_force(y, mode, sign);
    const double excess_rate = tangential_damping_rate(x, v) * std::abs(s) +
                               tangential_damping(x) * (s < 0.0 ? -1.0 : 1.0) * force * mobility(x) -
                               cap_rate(x, v);
    return mode == ContactMode::stick ? excess_rate > 0.0 : excess_rate < 0.0;
  }
  // The displacement a history model carries from a slip into a stick: the capped force, -κξ - g s = σC.
  [[nodiscard]] double displacement_at_cap(const State& y, double sign) const {
    const double x = y[kOverlap];
    const double k = tangential_stiffness(x);
    if (!(k > 0.0)) return 0.0;
    return -(sign * cap(x, y[kOverlapRate]) + tangential_damping(x) * slip_velocity(y)) / k;
  }
};

}  // namespace restitution::oblique::detail
