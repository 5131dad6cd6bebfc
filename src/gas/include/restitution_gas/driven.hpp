// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The driven granular gas (docs/gas.md, "The driven gas"): the gas of cooling.hpp kept hot by a thermostat,
// its steady temperature T_s, stationary Sonine coefficient a₂ and the relaxation T(t), a₂(t) from any T₀.
//   Langevin bath (LAMMPS `fix langevin T_b T_b τ_b seed`: drag −m v/τ_b and a random force of variance
//   2 m T_b/(τ_b dt) per component): dT/dt = (2/τ_b)(T_b − T) − ζ(T) T,
//   white noise (power P per particle, the limit τ_b, T_b → ∞ at T_b/τ_b = P/3): dT/dt = 2P/3 − ζ(T) T,
// ζ(T) the collisional cooling rate of collision_integral.hpp with the exact ε(u). Written as
// dT/dt = q − 2γT − ζT with the heating q = 2T_b/τ_b or 2P/3 [J/s] and the drag γ = 1/τ_b or 0 [1/s].
// The Sonine coefficient follows the moment equations of cooling.hpp plus the bath's exact term
// −(4T_b/(τ_b T)) a₂ (for white noise −(2q/T) a₂), linearised in a₂ as the collisional part is
// (van Noije & Ernst, Granular Matter 1, 57 (1998)); its stationary value is the root of
//     2(μ₂ + a₂ μ₂') − (2/5)(μ₄ + a₂ μ₄') = 4γ a₂/ν,   ν = (4√π/3) n g₂ σ² √(T/m),
// which for white noise and a constant ε is van Noije & Ernst's a₂ = 16(1 − ε)(1 − 2ε²)/(241 − 177ε
// + 30ε²(1 − ε)).
#include <optional>

#include "restitution_gas/cooling.hpp"

namespace restitution::gas {

enum class ThermostatKind { langevin, white_noise };

struct Thermostat {
  ThermostatKind kind = ThermostatKind::langevin;
  double bath_temperature_j = 0.0;  // Langevin: T_b [J] (LAMMPS reads T_b/k_B in K under `units si`)
  double bath_time_s = 0.0;         // Langevin: τ_b, LAMMPS's damp [s]
  double power_w = 0.0;             // white noise: the energy put in per particle [W]
  // q [J/s] and γ [1/s] of dT/dt = q − 2γT − ζT.
  [[nodiscard]] double heating_j_s() const;
  [[nodiscard]] double drag_hz() const;
  // The driving strength the exponent d ln T_s/d ln (driving) refers to: T_b (at fixed τ_b) or P.
  [[nodiscard]] double driving() const;
};

struct DrivenRequest {
  CoolingRequest gas;  // the spheres, the law, T₀, the span of time and the a₂ (held, or evolving)
  Thermostat thermostat;
};

struct SteadyState {
  double temperature_j = 0.0;  // T_s: q = (2γ + ζ(T_s)) T_s, with a₂ held or (evolving) stationary
  double a2 = 0.0;             // the stationary a₂ at T_s (whether the curve holds a₂ or not)
  // 1/λ, λ = −∂(dT/dt)/∂T at T_s: T − T_s decays as e^{−t/τ} near the steady state (τ_b/2 without loss).
  double relaxation_time_s = 0.0;
  double driving_exponent = 0.0;               // d ln T_s/d ln(driving)
  double constant_eps_driving_exponent = 0.0;  // the same for the constant ε = effective_eps
  double effective_eps = 0.0;                  // ε_eff(T_s)
  double collision_frequency_hz = 0.0;         // ω(T_s) per sphere
  double power_w = 0.0;                        // the energy put in (= dissipated) per sphere at T_s
};

// Throws InvalidInput naming the argument (those of cooling_curve; bath_temperature, bath_time, power; a
// white-noise gas whose law loses no energy has no steady state).
SteadyState steady_state(const DrivenRequest& request);

struct DrivenCurve {
  // The columns of the cooling gas: temperature T(t), cooling_rate ζ(T) (the collisions' part), the local
  // exponent d ln T/d ln t, the collisions, ε_eff and (evolving) a₂(t); Haff's τ₀ and curve of the same
  // gas without the thermostat for reference (τ₀ infinite for a law without loss).
  CoolingCurve curve;
  SteadyState steady;
};
DrivenCurve driven_curve(const DrivenRequest& request);

// The gas a front end describes: driven_curve with `thermostat`, else the freely cooling gas's cooling_curve
// (its steady state left empty).
DrivenCurve gas_curve(const CoolingRequest& request, const std::optional<Thermostat>& thermostat);

}  // namespace restitution::gas
