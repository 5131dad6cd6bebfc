// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The freely cooling granular gas in its homogeneous cooling state (docs/gas.md): T(t) of monodisperse
// spheres whose collisions follow ε(u) of a contact law, from the Enskog kinetic equation dT/dt = −ζ(T) T of
// gas/collision_integral.hpp. Since the equation is one-dimensional and autonomous, the time is a quadrature,
//     t(T) = ∫_T^{T₀} dT'/(ζ(T') T') = ∫₀^x dx'/ζ(T₀ e^{−x'}),   x = ln(T₀/T),
// done with 12-point Gauss–Legendre panels of width 1/2 in x (ζ is smooth in ln T); T at the requested times
// is found by Newton's method on t(x) with the panel's interpolant of 1/ζ. A constant ε gives Haff's law
// T = T₀/(1 + t/τ₀)², 1/τ₀ = ζ(T₀)/2 (Haff, J. Fluid Mech. 134, 401 (1983)); viscoelastic Hertz cools more
// slowly, T ∝ t^{−5/3} as t -> ∞ (Brilliantov & Pöschel, PRE 61, 5573 (2000); Schwager & Pöschel, PRE 57, 650
// (1998)), the local exponent d ln T/d ln t = −t ζ(T) approaching −5/3 as ζ(T) at the thermal speed vanishes.
// With an evolving a₂ the system is two-dimensional: a₂(x) solves da₂/dx = F(x, a₂) (no time in it) by
// Gauss collocation on the same panels, and t(x) is again the quadrature of 1/ζ(T, a₂) (docs/gas.md).
#include <optional>
#include <vector>

#include "restitution_gas/impact_law.hpp"

namespace restitution::gas {

struct GasParticles {
  double mass_kg = 0.0;           // m > 0
  double diameter_m = 0.0;        // σ > 0
  double packing_fraction = 0.0;  // φ in (0, 0.5): the Enskog theory holds for a fluid, below freezing
};

struct CoolingRequest {
  GasParticles particles;
  ImpactLaw law;
  double initial_temperature_j = 0.0;  // T₀ = m⟨v²⟩/3 > 0 [J]
  // The span of time: duration in s, or in Haff times τ₀ when duration_in_haff_times.
  double duration = 0.0;
  bool duration_in_haff_times = false;
  // The log-spaced output grid from first_time (0: duration · 1e-6, six decades) to the duration, this many
  // points per decade; or, when `times_s` is not empty, exactly these times [s] (ascending, > 0).
  double first_time_s = 0.0;
  int points_per_decade = 20;
  std::vector<double> times_s;
  // The first Sonine coefficient a₂, held constant (docs/gas.md); none: Maxwellian (a₂ = 0). With
  // a2_evolving, a₂(t) follows the Sonine moment equations from this initial value (none: 0, a Maxwellian
  // start like the deck's), integrated with T (docs/gas.md, "The first Sonine correction").
  std::optional<double> a2;
  bool a2_evolving = false;
  // A factor on the collision rate (1: Enskog's); e.g. one measured on a simulation (docs/gas.md).
  double collision_rate_factor = 1.0;
  double tolerance = SolveOptions{}.tolerance;  // each solve of a law without a fast table
};

struct CoolingCurve {
  double contact_correlation = 0.0;  // g₂ (Carnahan–Starling)
  double number_density_m3 = 0.0;    // n [1/m³]
  double a2 = 0.0;                   // the Sonine coefficient used (evolving: its initial value)
  bool a2_evolving = false;
  // Haff's law tangent at t = 0: τ₀ = 2/ζ(T₀) [s], the Haff time of haff_eps, the constant ε that cools at
  // the initial rate (ε_eff(T₀); the law's ε itself when it is constant).
  double tau0_s = 0.0;
  double haff_eps = 0.0;
  double duration_s = 0.0;
  std::vector<double> time_s;
  std::vector<double> temperature_j;
  std::vector<double> haff_temperature_j;       // T₀/(1 + t/τ₀)²
  std::vector<double> cooling_rate_hz;          // ζ(T) = −d ln T/dt [1/s]
  std::vector<double> local_exponent;           // d ln T/d ln t = −t ζ(T)
  std::vector<double> collision_frequency_hz;   // ω(T) per sphere [1/s]
  std::vector<double> collisions_per_particle;  // ∫₀^t ω dt'
  std::vector<double> effective_eps;            // ε_eff(T) (collision_integral.hpp)
  std::vector<double> sonine_a2;                // a₂(t) when it evolves; empty when held constant
};

// Throws InvalidInput naming the argument (mass, diameter, packing_fraction outside (0, 0.5),
// initial_temperature, duration, times, a2, collision_rate_factor; a law without dissipation).
CoolingCurve cooling_curve(const CoolingRequest& request);

// Haff's law tangent at t = 0 alone (what a duration in Haff times multiplies): τ₀ = 2/ζ(T₀) [s] and its ε.
struct HaffReference {
  double tau0_s = 0.0;
  double eps = 0.0;
};
HaffReference haff_reference(const CoolingRequest& request);

// The Haff times the theory computes with [s]: its times are carried in units of the gas's own time scale, so
// that τ₀ anywhere in this range gives the curve to rounding (φ = 1e-300 makes τ₀ ≈ 1e292 s); beyond it τ₀
// or 1/τ₀ would leave the doubles, and cooling_curve and haff_reference refuse the request.
inline constexpr double kShortestHaffTimeS = 1e-300;
inline constexpr double kLongestHaffTimeS = 1e300;
// ln(τ₀/s), computed in logarithms: it exists for every request with valid inputs, also where τ₀ is no double
// (callers say which input to change, and by how much).
double log_haff_time(const CoolingRequest& request);

}  // namespace restitution::gas
