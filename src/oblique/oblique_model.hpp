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
// LIGGGHTS's `tangential history` (tangential_model_history.h:147-217) and YADE's ViscElPhys
// (computeForceTorqueViscEl) test and cap the elastic force -κξ alone, so its switches are these with g = 0
// in the cap test, the rescale and h (its stick force is still -κξ - g s).
#include <algorithm>
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
  // The contact-point velocity s = u + Σ (1 - contact_arm_slope_i x) R_i ω_i: 0 for LAMMPS's arm R, (δ/2)/R_i
  // per natural length for LIGGGHTS's R_i - δ/2.
  std::array<double, 2> contact_arm_slope{};
  // R1 + R2 in natural lengths for a pair whose line of centres turns (the distance is r = centre_distance -
  // x, and in polar form δ'' = -f_n - u²/r, u' = f_t + δ' u/r, θ' = u/r); 0 for a wall or a fixed normal.
  double centre_distance = 0.0;
  bool cap_of_signed_force = false;  // true at the delayed-recovery end (see cap)
  // YADE's Mindlin takes the centres' relative velocity times (R1 + R2)/(R1 + R2 - δ) into the contact-point
  // velocity (ScGeom::getIncidentVel, avoiding granular ratcheting; a wall's radius counts as the sphere's):
  // R1 + R2 in natural lengths, 0 for no such gain (the other models).
  double velocity_gain_distance = 0.0;

  [[nodiscard]] double translation_gain(double x) const {
    return velocity_gain_distance > 0.0 ? velocity_gain_distance / (velocity_gain_distance - x) : 1.0;
  }

  [[nodiscard]] double inverse_distance(double x) const {
    return centre_distance > 0.0 ? 1.0 / (centre_distance - x) : 0.0;
  }
  [[nodiscard]] double overlap_acceleration(const State& y) const {
    const double u = y[kTangential];
    return law_rhs::acceleration(law, y[kOverlap], y[kOverlapRate]) - u * u * inverse_distance(y[kOverlap]);
  }
  // ds/dτ under the tangential force f: f (1 + ρ1 + ρ2) plus the turning frame's δ' u/r, less the shrinking
  // contact-point arm's δ' Σ λ_i R_i ω_i.
  [[nodiscard]] double slip_rate(const State& y, double force) const {
    const double x = y[kOverlap];
    const double v = y[kOverlapRate];
    const double rate = force * mobility(x) + v * y[kTangential] * inverse_distance(x) -
                        v * (contact_arm_slope[0] * y[kSpinFirst] + contact_arm_slope[1] * y[kSpinSecond]);
    if (!(velocity_gain_distance > 0.0)) return rate;
    // d(α u)/dτ - u' = (α - 1) u' + α' u, α' = α δ'/(D - x).
    const double gain = translation_gain(x);
    return rate + (gain - 1.0) * (force + v * y[kTangential] * inverse_distance(x)) +
           gain * v * y[kTangential] / (velocity_gain_distance - x);
  }

  [[nodiscard]] bool has_history() const { return kind != TangentialKind::linear_nohistory; }
  // LIGGGHTS and YADE: the cap tests and caps the elastic force alone.
  [[nodiscard]] bool caps_elastic_force() const {
    return kind == TangentialKind::liggghts_history || kind == TangentialKind::yade_viscel ||
           kind == TangentialKind::yade_mindlin;
  }
  // YADE's Mindlin spring is incremental, F_e' = -κ_m sqrt(x) s with the tangent stiffness κ_m sqrt(x): the
  // history then holds z = ∫ sqrt(x) s dτ (F_e = -κ_m z, κ_m constant), which a rescale to the cap sets as
  // it does ξ. Any other spring is -κ ξ with ξ' = s.
  [[nodiscard]] bool incremental_history() const { return kind == TangentialKind::yade_mindlin; }
  // dz/dτ per unit slip, and the tangent stiffness per κ: sqrt(x) (incremental) or 1.
  [[nodiscard]] double history_growth(double x) const {
    return incremental_history() ? std::sqrt(std::max(x, 0.0)) : 1.0;
  }
  // κ = κ_m sqrt(x): LAMMPS's mindlin (k_t a) and LIGGGHTS's hertz/stiffness kt sqrt(R* δ).
  [[nodiscard]] bool stiffness_grows_with_overlap() const {
    return kind == TangentialKind::mindlin || kind == TangentialKind::liggghts_history;
  }

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
  // The damping in the cap test, the rescale and h: none where LIGGGHTS caps the elastic force alone.
  [[nodiscard]] double capped_damping(double x) const {
    return caps_elastic_force() ? 0.0 : tangential_damping(x);
  }
  [[nodiscard]] double capped_damping_rate(double x, double v) const {
    return caps_elastic_force() ? 0.0 : tangential_damping_rate(x, v);
  }
  [[nodiscard]] double tangential_damping_rate(double x, double v) const {
    return damping_factor * law.damping() * law_rhs::shape_derivative(law, x) * v;
  }
  [[nodiscard]] double tangential_stiffness(double x) const {
    return stiffness_grows_with_overlap() ? stiffness * std::sqrt(std::max(x, 0.0)) : stiffness;
  }
  // κ'/κ
  [[nodiscard]] double stiffness_log_rate(double x, double v) const {
    return stiffness_grows_with_overlap() && x > 0.0 ? 0.5 * v / x : 0.0;
  }
  // d s/dτ per unit tangential force: 1 + Σ (1 - λ_i x) ρ_i.
  [[nodiscard]] double mobility(double x) const {
    return 1.0 + (1.0 - contact_arm_slope[0] * x) * (rotation_base[0] - rotation_slope[0] * x) +
           (1.0 - contact_arm_slope[1] * x) * (rotation_base[1] - rotation_slope[1] * x);
  }
  // u + R1 ω1 + R2 ω2: the slip before and after the contact (δ = 0).
  [[nodiscard]] static double slip_velocity(const State& y) {
    return y[kTangential] + y[kSpinFirst] + y[kSpinSecond];
  }
  // The contact-point velocity the code uses during the contact (LIGGGHTS's arm R_i - δ/2).
  [[nodiscard]] double contact_slip(const State& y) const {
    const double x = y[kOverlap];
    return y[kTangential] * translation_gain(x) + (1.0 - contact_arm_slope[0] * x) * y[kSpinFirst] +
           (1.0 - contact_arm_slope[1] * x) * y[kSpinSecond];
  }
  // The force below the cap: -κξ - g s (history) or -g s.
  [[nodiscard]] double trial_force(const State& y) const {
    const double s = contact_slip(y);
    const double viscous = -tangential_damping(y[kOverlap]) * s;
    return has_history() ? viscous - tangential_stiffness(y[kOverlap]) * y[kDisplacement] : viscous;
  }
  // The force the cap is tested against, whose direction a slip takes: the trial force, or LIGGGHTS's -κξ.
  [[nodiscard]] double cap_test_force(const State& y) const {
    return caps_elastic_force() ? -tangential_stiffness(y[kOverlap]) * y[kDisplacement] : trial_force(y);
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
    dy[kDisplacement] =
        mode == ContactMode::stick && has_history() ? contact_slip(y) * history_growth(x) : 0.0;
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
    if (mode == ContactMode::stick) return c - std::abs(cap_test_force(y));
    const double s = contact_slip(y);
    const double g = capped_damping(x);
    // -σ g s is g|s| while s keeps the sign it slid with, and negative once it crosses 0: a strong damping
    // that carries s through 0 within one step cannot hide the end of the slip.
    if (!has_history()) return -sign * g * s - c;
    const double ds = slip_rate(y, sign * c);
    const double dgs = capped_damping_rate(x, v) * s + g * ds;
    return cap_rate(y) + sign * (tangential_stiffness(x) * history_growth(x) * s + dgs) -
           stiffness_log_rate(x, v) * (c + sign * g * s);
  }
  // The size of the terms of the switch function out of `mode`, against which its distance from 0 is measured
  // (a near miss: ObliqueResult::closest_switch_approach).
  [[nodiscard]] double switch_scale(const State& y, ContactMode mode, double sign) const {
    const double x = y[kOverlap];
    const double v = y[kOverlapRate];
    const double c = cap(x, v);
    if (mode == ContactMode::stick) return c + std::abs(cap_test_force(y));
    const double s = contact_slip(y);
    const double g = capped_damping(x);
    if (!has_history()) return g * std::abs(s) + c;
    const double ds = slip_rate(y, sign * c);
    return std::abs(cap_rate(y)) + tangential_stiffness(x) * history_growth(x) * std::abs(s) +
           std::abs(capped_damping_rate(x, v) * s) + std::abs(g * ds) +
           std::abs(stiffness_log_rate(x, v)) * (c + g * std::abs(s));
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
      const double trial_sign = cap_test_force(y) < 0.0 ? -1.0 : 1.0;
      return switch_function(y, ContactMode::slip, trial_sign) < 0.0;
    }
    const double s = contact_slip(y);
    const double force = tangential_force(y, mode, sign);
    const double excess_rate = tangential_damping_rate(x, v) * std::abs(s) +
                               tangential_damping(x) * (s < 0.0 ? -1.0 : 1.0) * slip_rate(y, force) -
                               cap_rate(y);
    return mode == ContactMode::stick ? excess_rate > 0.0 : excess_rate < 0.0;
  }
  // Whether the stick a slip -> stick switch starts is driven straight back onto the cap, a sliding mode on
  // it (LIGGGHTS's and YADE's rule). The slip ends where h (its switch function) rises through 0, and h is
  // also the rate of the stick's margin C - |κξ|; the force jumps by -g s at the switch, so h's rate differs
  // between the modes by κ·mobility·(-σ g s). Where h rises under the slip's force but falls under the
  // stick's, each mode drives the contact into the other, and the code alternates capped and uncapped steps:
  // an average force the two modes here do not give. h's rate under the stick: a central difference along
  // the stick's rates (h is smooth there).
  [[nodiscard]] bool stick_falls_back_onto_cap(const State& y, double sign) const {
    if (!caps_elastic_force() || !has_history()) return false;
    State rates{};
    this->rates(y, ContactMode::stick, sign, rates);
    const double step = 1e-6 * std::max(y[kOverlap], 1e-3);
    State ahead = y;
    State behind = y;
    for (std::size_t i = 0; i < y.size(); ++i) {
      ahead[i] += step * rates[i];
      behind[i] -= step * rates[i];
    }
    return switch_function(ahead, ContactMode::slip, sign) < switch_function(behind, ContactMode::slip, sign);
  }
  // The displacement a history model carries from a slip into a stick: the capped force, -κξ - g s = σC
  // (LIGGGHTS: -κξ = σC).
  [[nodiscard]] double displacement_at_cap(const State& y, double sign) const {
    const double x = y[kOverlap];
    const double k = tangential_stiffness(x);
    if (!(k > 0.0)) return 0.0;
    return -(sign * cap(x, y[kOverlapRate]) + capped_damping(x) * contact_slip(y)) / k;
  }
};

}  // namespace restitution::oblique::detail
