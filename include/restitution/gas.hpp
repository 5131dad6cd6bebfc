// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The freely cooling granular gas (docs/gas.md), three parts: ε(u) of a law at any impact speed, the Enskog
// collision integral of the homogeneous cooling state, and T(t) from it.
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "restitution/collision_solver.hpp"
#include "restitution/contact_law.hpp"

namespace restitution::gas {

// The energy a collision of the gas loses, 1 − ε(u)², as a function of the normal impact speed u [m/s], for
// one member of the contact-law family (docs/gas.md). A member with fixed physical coefficients has
// ζ(u) = ζ_ref (u / v_ref)^p with p = speed_exponent(kind) (1/5 for viscoelastic Hertz: ζ = β u^{1/5}), so
// one ζ at one speed fixes ε(u) at every speed. Viscoelastic Hertz is read from the certified fast table
// (restitution/fast.hpp, |Δε| <= 1e-13 min(ε, 1 − ε)); the other members are solved with the collision
// solver, once for the speed-independent ones, on a grid in ln ζ interpolated for constant damping.

struct ImpactLaw {
  LawKind kind = LawKind::viscoelastic_hertz;
  double zeta_at_reference = 0.0;    // ζ of the natural form at reference_speed_m_s
  double reference_speed_m_s = 1.0;  // v_ref [m/s]
  CollisionEnd end = CollisionEnd::delayed_recovery;
  // Set: ε is this constant at every speed (Haff's gas); kind and ζ are then unused.
  std::optional<double> constant_eps;
};

// Viscoelastic Hertz with ζ = β u^{1/5} (β in s^{1/5} m^{-1/5}, units.hpp).
ImpactLaw hertz_impact_law(double beta, CollisionEnd end);
// The member `kind` calibrated so that ε(velocity_m_s) = eps (InvalidInput naming eps or velocity).
ImpactLaw impact_law_from_eps(LawKind kind, double eps, double velocity_m_s, CollisionEnd end,
                              double tolerance = SolveOptions{}.tolerance);
// ε = eps at every speed, eps in (0, 1].
ImpactLaw constant_eps_law(double eps);

// 1 − ε² of a law at any impact speed. Holds a solver and a cache: one per thread.
class ImpactDissipation {
 public:
  // tolerance: accuracy of each solve for the members without a fast table (SolveOptions::tolerance).
  explicit ImpactDissipation(const ImpactLaw& law, double tolerance = SolveOptions{}.tolerance);
  ~ImpactDissipation();
  ImpactDissipation(ImpactDissipation&& other) noexcept;
  ImpactDissipation& operator=(ImpactDissipation&& other) noexcept;
  ImpactDissipation(const ImpactDissipation&) = delete;
  ImpactDissipation& operator=(const ImpactDissipation&) = delete;

  [[nodiscard]] const ImpactLaw& law() const { return law_; }
  // ζ(u) = ζ_ref (u / v_ref)^p.
  [[nodiscard]] double zeta_at_speed(double speed_m_s) const;
  // The speed exponent p of ε(u) (0 for a constant ε).
  [[nodiscard]] double speed_exponent() const { return exponent_; }
  // 1 − ε² at ζ of the natural form, and at impact speed u [m/s].
  double loss_at_zeta(double zeta);
  double loss_at_speed(double speed_m_s) { return loss_at_zeta(zeta_at_speed(speed_m_s)); }

 private:
  double solved_loss(double zeta);
  double interpolated_loss(double zeta);

  ImpactLaw law_;
  double exponent_ = 0.0;
  double tolerance_ = 0.0;
  double constant_loss_ = -1.0;  // the speed-independent members: 1 − ε², once solved
  std::unique_ptr<CollisionSolver> solver_;
  std::map<long, double> grid_;  // ln(1 − ε²) at ln ζ = k · kGridStep, computed when first needed
};

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

// The freely cooling granular gas in its homogeneous cooling state (docs/gas.md): T(t) of monodisperse
// spheres whose collisions follow ε(u) of a contact law, from the Enskog kinetic equation dT/dt = −ζ(T) T of
// gas/collision_integral.hpp. Since the equation is one-dimensional and autonomous, the time is a quadrature,
//     t(T) = ∫_T^{T₀} dT'/(ζ(T') T') = ∫₀^x dx'/ζ(T₀ e^{−x'}),   x = ln(T₀/T),
// done with 12-point Gauss–Legendre panels of width 1/2 in x (ζ is smooth in ln T); T at the requested times
// is found by Newton's method on t(x) with the panel's interpolant of 1/ζ. A constant ε gives Haff's law
// T = T₀/(1 + t/τ₀)², 1/τ₀ = ζ(T₀)/2 (Haff, J. Fluid Mech. 134, 401 (1983)); viscoelastic Hertz cools more
// slowly, T ∝ t^{−5/3} as t -> ∞ (Brilliantov & Pöschel, PRE 61, 5573 (2000); Schwager & Pöschel, PRE 57, 650
// (1998)), the local exponent d ln T/d ln t = −t ζ(T) approaching −5/3 as ζ(T) at the thermal speed vanishes.

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
  // The first Sonine coefficient a₂, held constant (docs/gas.md); none: Maxwellian (a₂ = 0).
  std::optional<double> a2;
  // A factor on the collision rate (1: Enskog's); e.g. one measured on a simulation (docs/gas.md).
  double collision_rate_factor = 1.0;
  double tolerance = SolveOptions{}.tolerance;  // each solve of a law without a fast table
};

struct CoolingCurve {
  double contact_correlation = 0.0;  // g₂ (Carnahan–Starling)
  double number_density_m3 = 0.0;    // n [1/m³]
  double a2 = 0.0;                   // the Sonine coefficient used
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

}  // namespace restitution::gas
