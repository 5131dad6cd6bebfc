// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The oblique contact in the natural units of its normal law (time T, length v_n T, velocity v_n, force
// m* v_n/T; ContactLaw::physical): the state, the forces of each mode and the root functions of the switches.
// Private to the oblique module (solve_oblique's system for the event driver evaluates it).
//
// The stick/slip switches are those of LAMMPS's step (pair_granular.cpp:478-533) as dt -> 0:
//  * stick -> slip where the trial force -κξ - g s (history) or -g s (no history) reaches the cap C = μ|f_n|;
//  * slip -> stick, history models: LAMMPS rescales ξ to the cap every step, ξ = -(σC + g s)/κ, and then adds
//    s dt; the next trial force stays beyond the cap while
//        h = C' + σ(κ s + (g s)') - (κ'/κ)(C + σ g s) < 0,
//    so the contact sticks again where h crosses 0 upwards (for a constant cap without damping: where s = 0);
//  * slip -> stick, linear_nohistory: where g|s| falls below C.
// LAMMPS's mindlin/force and mindlin_rescale/force keep the elastic force H in the history instead of ξ
// (H' = -κ s, F = H - g s, reset at the cap to σC + g s: pair_granular.cpp:482-487, 503-505, 524-527), and
// the _rescale variants scale the history by a/a_old each step the contact radius a shrinks (lines 434-445),
// a rate (a'/a) H = (x'/2x) H while x' < 0. In every history model the trial force after a capped step
// changes at F' = -κ s - (g s)' + λ(σC + g s), λ the history's own relative rate at the cap (κ'/κ for ξ,
// whose force -κξ grows with κ; plus a'/a while a _rescale variant unloads), so
//        h = C' + σ(κ s + (g s)') - λ (C + σ g s).
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
// δ, δ', the history (the tangential displacement ξ; the elastic force H for LAMMPS's /force variants), u,
// R1 ω1, R2 ω2, each in natural units, and the angle θ the line of centres has turned through.
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
  TangentialRule rule;     // the model's row (tangential_models.hpp)
  double friction = 0.0;   // μ
  bool uncapped = false;   // the sticking limit μ → ∞ (ObliqueOptions::sticking_limit): stick throughout
  double stiffness = 0.0;  // κ (linear_history), or κ_m with κ = κ_m sqrt(x) (the mindlin family)
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

  [[nodiscard]] bool has_history() const { return rule.history != HistoryKind::none; }
  // LIGGGHTS and YADE: the cap tests and caps the elastic force alone.
  [[nodiscard]] bool caps_elastic_force() const { return rule.cap_test == CapTest::elastic_force; }
  // κ = κ_m sqrt(x): LAMMPS's mindlin family (k_t a), LIGGGHTS's hertz/stiffness kt sqrt(R* δ) and YADE's
  // Mindlin kso sqrt(δ).
  [[nodiscard]] bool stiffness_grows_with_overlap() const { return rule.growth != StiffnessGrowth::constant; }
  // LAMMPS's /force variants and YADE's Mindlin (`shearElastic -= ks (v_s dt)`): the history is the elastic
  // force H (pair_granular.cpp:482-487).
  [[nodiscard]] bool history_is_force() const { return rule.history == HistoryKind::force; }
  // LAMMPS's _rescale variants: the history scaled by a/a_old where a shrinks (pair_granular.cpp:434-445).
  [[nodiscard]] bool rescales_on_unloading() const { return rule.rescales_on_unloading; }
  // The rescale as a rate, a'/a = x'/(2x) while the contact radius shrinks (x' < 0), else 0.
  [[nodiscard]] double rescale_rate(double x, double v) const {
    return rescales_on_unloading() && v < 0.0 && x > 0.0 ? 0.5 * v / x : 0.0;
  }
  // λ: the history's relative rate at the cap that h carries (the header): κ'/κ for a displacement, whose
  // force -κξ grows with κ, none for a force; plus the _rescale variants' a'/a.
  [[nodiscard]] double history_log_rate(double x, double v) const {
    if (!rescales_on_unloading()) return history_is_force() ? 0.0 : stiffness_log_rate(x, v);
    return (history_is_force() ? 0.0 : stiffness_log_rate(x, v)) + rescale_rate(x, v);
  }
  // The history at first contact τ0 = x (x' = 1 there): ξ = s τ0, or H = -∫κ s = -(2/3) κ(x) x s.
  [[nodiscard]] double initial_history(const State& y, double slip) const {
    const double x = y[kOverlap];
    return history_is_force() ? -2.0 / 3.0 * tangential_stiffness(x) * x * slip : slip * x;
  }
  // The rate of the history while sticking: ξ' = s (+ (a'/a) ξ), or H' = -κ s (+ (a'/a) H).
  [[nodiscard]] double history_rate(const State& y) const {
    const double s = contact_slip(y);
    if (!history_is_force() && !rescales_on_unloading()) return s;
    const double x = y[kOverlap];
    const double rescale = rescale_rate(x, y[kOverlapRate]) * y[kDisplacement];
    return (history_is_force() ? -tangential_stiffness(x) * s : s) + rescale;
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
  // The force below the cap: -κξ - g s or H - g s (history) or -g s (no history).
  [[nodiscard]] double trial_force(const State& y) const {
    const double s = contact_slip(y);
    const double viscous = -tangential_damping(y[kOverlap]) * s;
    if (history_is_force()) return viscous + y[kDisplacement];
    return has_history() ? viscous - tangential_stiffness(y[kOverlap]) * y[kDisplacement] : viscous;
  }
  // The force the cap is tested against, whose direction a slip takes: the trial force, or LIGGGHTS's -κξ
  // (YADE's Mindlin: its elastic force H).
  [[nodiscard]] double cap_test_force(const State& y) const {
    if (!caps_elastic_force()) return trial_force(y);
    return history_is_force() ? y[kDisplacement] : -tangential_stiffness(y[kOverlap]) * y[kDisplacement];
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
    dy[kDisplacement] = mode == ContactMode::stick && has_history() ? history_rate(y) : 0.0;
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
    return cap_rate(y) + sign * (tangential_stiffness(x) * s + dgs) -
           history_log_rate(x, v) * (c + sign * g * s);
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
    return std::abs(cap_rate(y)) + tangential_stiffness(x) * std::abs(s) +
           std::abs(capped_damping_rate(x, v) * s) + std::abs(g * ds) +
           std::abs(history_log_rate(x, v)) * (c + g * std::abs(s));
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
  // The history a history model carries from a slip into a stick: the capped force, -κξ - g s = σC
  // (LIGGGHTS: -κξ = σC; the /force variants: H = σC + g s, pair_granular.cpp:524-527).
  [[nodiscard]] double displacement_at_cap(const State& y, double sign) const {
    const double x = y[kOverlap];
    if (history_is_force()) return sign * cap(x, y[kOverlapRate]) + capped_damping(x) * contact_slip(y);
    const double k = tangential_stiffness(x);
    if (!(k > 0.0)) return 0.0;
    return -(sign * cap(x, y[kOverlapRate]) + capped_damping(x) * contact_slip(y)) / k;
  }
};

}  // namespace restitution::oblique::detail
