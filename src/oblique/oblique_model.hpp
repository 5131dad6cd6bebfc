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

inline constexpr int kStateSize = 7;
using State = std::array<double, kStateSize>;
// δ, δ', tangential displacement ξ (history), u, R1 ω1, R2 ω2, each in natural units, and the angle θ the
// line of centres has turned through.
enum Index {
  kOverlap = 0,
  kOverlapRate = 1,
  kDisplacement = 2,
  kTangential = 3,
  kSpinFirst = 4,
  kSpinSecond = 5,
  kTurn = 6
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
  // R1 + R2 in natural lengths for a pair whose line of centres turns (the distance is r = centre_distance -
  // x, and in polar form δ'' = -f_n - u²/r, u' = f_t + δ' u/r, θ' = u/r); 0 for a wall or a fixed normal.
  double centre_distance = 0.0;
  bool cap_of_signed_force = false;  // true at the delayed-recovery end (see cap)

  [[nodiscard]] double inverse_distance(double x) const {
    return centre_distance > 0.0 ? 1.0 / (centre_distance - x) : 0.0;
  }
  [[nodiscard]] double overlap_acceleration(const State& y) const {
    const double u = y[kTangential];
    return law_rhs::acceleration(law, y[kOverlap], y[kOverlapRate]) - u * u * inverse_distance(y[kOverlap]);
  }
  // ds/dτ under the tangential force f: f (1 + ρ1 + ρ2) plus the turning frame's δ' u/r.
  [[nodiscard]] double slip_rate(const State& y, double force) const {
    const double x = y[kOverlap];
    return force * mobility(x) + y[kOverlapRate] * y[kTangential] * inverse_distance(x);
  }

  [[nodiscard]] bool has_history() const { return kind != TangentialKind::linear_nohistory; }

  [[nodiscard]] double normal_force(double x, double v) const { return -law_rhs::acceleration(law, x, v); }
  // d f_n/dτ along the motion.
  [[nodiscard]] double normal_force_rate(const State& y) const {
    const double x = y[kOverlap];
    const double v = y[kOverlapRate];
    return law_rhs::shape_derivative(law, x) * v * law_rhs::force_factor(law, x, v) +
           law_rhs::shape(law, x) * (law.damping() * overlap_acceleration(y) +
                                     law.stiffness() * law_rhs::elastic_slope(law, x) * v);
  }
  // C = μ|f_n| (LAMMPS's Fncrit = fabs(Fntot)); where the contact ends at the force-zero end f_n >= 0 until
  // the end, and μ f_n itself keeps the right-hand side smooth for the steps CVODE takes past it.
  [[nodiscard]] double cap(double x, double v) const {
    const double fn = normal_force(x, v);
    return friction * (cap_of_signed_force ? fn : std::abs(fn));
  }
  [[nodiscard]] double cap_rate(const State& y) const {
    const double fn = normal_force(y[kOverlap], y[kOverlapRate]);
    return friction * (fn < 0.0 && !cap_of_signed_force ? -1.0 : 1.0) * normal_force_rate(y);
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
    const double inverse_r = inverse_distance(x);
    dy[kOverlapRate] = overlap_acceleration(y);
    dy[kDisplacement] = mode == ContactMode::stick && has_history() ? slip_velocity(y) : 0.0;
    dy[kTangential] = ft + v * y[kTangential] * inverse_r;
    dy[kSpinFirst] = (rotation_base[0] - rotation_slope[0] * x) * ft;
    dy[kSpinSecond] = (rotation_base[1] - rotation_slope[1] * x) * ft;
    dy[kTurn] = y[kTangential] * inverse_r;
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
    const double ds = slip_rate(y, sign * c);
    const double dgs = tangential_damping_rate(x, v) * s + g * ds;
    return cap_rate(y) + sign * (tangential_stiffness(x) * s + dgs) -
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
                               tangential_damping(x) * (s < 0.0 ? -1.0 : 1.0) * slip_rate(y, force) -
                               cap_rate(y);
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
