// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The Enskog collision integral of the homogeneous cooling state (docs/gas.md). Monodisperse spheres of mass
// m [kg] and diameter σ [m] at packing fraction φ (number density n = 6φ/(πσ³)), granular temperature T =
// m⟨v²⟩/3 [J]. A pair meeting with normal relative speed u loses (m/4) u² (1 − ε(u)²); summing over the
// collisions of a Maxwellian gas (the normal relative speed is Gaussian with variance 2T/m) gives
//     dT/dt = −(π/3) n g₂ σ² m ∫₀^∞ p(u) u³ (1 − ε(u)²) du = −ζ(T) T,
//     ζ(T) = (4√π/3) n g₂ σ² √(T/m) · J(T),   J(T) = ∫₀^∞ z e^{−z} (1 − ε(u)²) dz,  u = 2 √(z T/m),
// J the Maxwellian mean of 1 − ε² weighted with u³ (J = 1 − ε² for a constant ε: Haff 1983, 1/τ₀ = ζ(T₀)/2;
// Brilliantov & Pöschel, PRE 61, 5573 (2000) for ε(u)). With the first Sonine correction a₂ of the velocity
// distribution the normal relative speed carries the factor 1 + (a₂/2) S(z), S(z) = z²/2 − 3z/2 + 3/8 (the
// one-dimensional second Sonine polynomial: the relative velocity halves a₂, its normal component keeps it),
// which for a constant ε gives the known factor 1 + 3a₂/16 of the cooling rate (van Noije & Ernst, Granular
// Matter 1, 57 (1998)) and 1 − a₂/16 of the collision frequency.
#include "gas/impact_law.hpp"

namespace restitution::gas {

// The Enskog factor: the pair correlation at contact, Carnahan–Starling g₂ = (1 − φ/2)/(1 − φ)³.
double contact_correlation(double packing_fraction);
// n = 6φ/(πσ³) [1/m³].
double number_density_m3(double packing_fraction, double diameter_m);
// The Enskog collision frequency of one sphere, ω = 4√π n g₂ σ² √(T/m) (1 − a₂/16) [1/s].
double collision_frequency_hz(double packing_fraction, double diameter_m, double mass_kg,
                              double temperature_j, double a2);
// a₂ of the homogeneous cooling state for a constant ε in three dimensions, to first order in the Sonine
// expansion: 16(1 − ε)(1 − 2ε²)/(81 − 17ε + 30ε²(1 − ε)) (van Noije & Ernst 1998, their Eq. for d = 3).
double sonine_a2_constant_eps(double eps);

// J(T) by the trapezoidal rule in ln z on [1e-7, 60] with step 1/4 (82 nodes): the integrand is analytic
// in ln z and decays as z^2 below and as e^{−z} above, so the rule converges geometrically; against an
// adaptive quadrature of the solver's ε its relative error is below 1e-12 (tests/test_gas.cpp).
class CollisionIntegral {
 public:
  // a2: the first Sonine coefficient (0: Maxwellian). Keeps a reference to `dissipation`.
  CollisionIntegral(ImpactDissipation& dissipation, double mass_kg, double a2);
  // J(T), T > 0 [J].
  double mean_loss(double temperature_j);
  // The effective constant ε that cools at the same rate at T: 1 − ε_eff² = J(T)/(1 + 3a₂/16).
  double effective_eps(double temperature_j);
  [[nodiscard]] double a2() const { return a2_; }

 private:
  ImpactDissipation* dissipation_;
  double mass_kg_ = 0.0;
  double a2_ = 0.0;
  std::vector<double> weights_;       // h z² e^{−z} (1 + (a₂/2) S(z)) at the nodes
  std::vector<double> zeta_factors_;  // z^{p/2}: ζ(u) = ζ(2√(T/m)) · z^{p/2}
};

}  // namespace restitution::gas
