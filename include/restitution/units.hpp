// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Physical units <-> the scaled equations, in one place (docs/design.md §1; 2008 paper Eq. 23; 1999 paper Eq.
// 30).
//
// Newton's equation for the compression ξ [m] of two viscoelastic spheres, divided by m_eff:
//     ξ'' + γ sqrt(ξ) ξ' + k ξ^{3/2} = 0,   ξ(0) = 0, ξ'(0) = v [m/s],
// k = ρ/m_eff [s^-2 m^-1/2], γ = (3/2) A k [s^-1 m^-1/2]. With ξ = L x, t = T τ the natural scaling
// x'(0) = 1 needs L = T v and k T² sqrt(L) = 1, hence
//     L = (v²/k)^{2/5} [m],   T = L / v = k^{-2/5} v^{-1/5} [s],   ζ = γ T sqrt(L) = β v^{1/5},
//     β = γ k^{-3/5} = (3/2) A k^{2/5} [s^{1/5} m^{-1/5}].
// The 2008 paper's Eq. 23 uses the velocity-independent length k^{-2/5} instead of L: its x equals
// v^{4/5} times the natural x (same τ), which is how ContactLaw::hertz_scaled reports natural units.

#include "restitution/contact_law.hpp"

namespace restitution {

// One degree in radians: the angles of the oblique impacts are given and printed in degrees. (π spelled out:
// the installed headers compile as C++17, which has no std::numbers.)
inline constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;

// The Hertz constants of a pair of spheres, in SI units.
struct HertzConstants {
  double k = 0.0;      // ρ / m_eff [s^-2 m^-1/2]
  double gamma = 0.0;  // (3/2) A ρ / m_eff [s^-1 m^-1/2]
  double beta = 0.0;   // γ k^{-3/5} [s^{1/5} m^{-1/5}]
};

// k and the dissipative constant A [s] -> γ and β. Throws InvalidInput naming k or A when not finite and > 0
// (A = 0 is allowed: elastic spheres).
HertzConstants hertz_constants(double k, double dissipative_constant_s);

// The Hertz facts of two spheres, each written once (docs/dem.md): the modulus factor (4/3) E* [Pa], the
// stiffness ρ = (4/3) E* sqrt(R_eff) [N m^-3/2] of F = ρ ξ^{3/2}, a sphere's mass (4/3) π R³ ρ_mass [kg], and
// β = γ k^{-3/5} [s^{1/5} m^{-1/5}] from the per-mass coefficients γ [s^-1 m^-1/2] and k [s^-2 m^-1/2].
double hertz_modulus_pa(double effective_modulus_pa);
// ρ of two spheres of one material (Young's modulus Y [Pa], Poisson ratio ν; E* = Y / (2 (1 - ν²))), the one
// formula of the stiffness, evaluated as 2 Y sqrt(R_eff) / (3 (1 - ν²)): the rounding every material's k has
// had, which elastic_constants (material.hpp) keeps by calling it.
double hertz_stiffness(double young_modulus_pa, double poisson_ratio, double effective_radius_m);
// ρ from E* alone (a DEM code's parameter): the same fact, (4/3) E* sqrt(R_eff), evaluated as
// hertz_modulus_pa(E*) sqrt(R_eff), the rounding the DEM outputs have had (equal to the form above within an
// ulp).
double hertz_stiffness(double effective_modulus_pa, double effective_radius_m);
double sphere_mass_kg(double radius_m, double density_kg_m3);
double beta_from_gamma(double gamma, double k);

// ζ = β v^{1/5}, β in s^{1/5} m^{-1/5}, v in m/s. Throws InvalidInput naming beta or velocity.
double zeta_from(double beta, double velocity_m_s);
// β = ζ / v^{1/5}.
double beta_from(double zeta, double velocity_m_s);
// A [s] = β / ((3/2) k^{2/5}): the dissipative constant a DEM code needs for a calibrated β.
double dissipative_constant_from(double beta, double k);

// Natural units -> SI for one impact speed: T = k^{-2/5} v^{-1/5} [s], L = (v²/k)^{2/5} [m].
struct NaturalScales {
  double time_s = 0.0;
  double length_m = 0.0;
};
NaturalScales natural_scales(double k, double velocity_m_s);
// T alone, evaluated as k^{-2/5} · v^{-1/5}: the rounding the DEM check decks' time steps and YADE's k have
// had (natural_scales' time_s, L / v, may differ in the last bit). Throws InvalidInput naming k or velocity.
double natural_time_scale_s(double k, double velocity_m_s);

// The coefficients of ContactLaw::physical for one pair: F = k ξ^a + γ ξ^b ξ' on the effective mass m.
struct PhysicalCoefficients {
  double stiffness = 0.0;          // k [N/m^a]
  double damping = 0.0;            // γ [N s/m^{1+b}]
  double effective_mass_kg = 0.0;  // m
};
// The natural scales of ContactLaw::physical at impact speed v: T = physical_time_scale_s, L = v T.
NaturalScales physical_scales(LawKind kind, const PhysicalCoefficients& c, double velocity_m_s);

// The 1999 paper's characteristic velocity g* [m/s]: (g*)^{-1/5} = C1 (3/2) A (ρ/m_eff)^{2/5} = C1 β
// (C1 in closed form: series::c1_closed_form)
// (its Eq. 31), so that (g/g*)^{1/5} = C1 ζ. Throws InvalidInput naming beta when not > 0.
double characteristic_velocity_m_s(double beta);
// The inverse: β = (g*)^{-1/5} / C1. Throws InvalidInput naming characteristic_velocity when not > 0.
double beta_from_characteristic_velocity(double characteristic_velocity_m_s);

// DEM codes' constants (docs/dem.md). Every code below writes the law for two spheres of one material as
//     F = (4/3) E* sqrt(R_eff) ξ^{3/2} + 2 A E* sqrt(R_eff ξ) ξ'   [N],
// which is ρ ξ^{3/2} + (3/2) A ρ sqrt(ξ) ξ' with ρ = (4/3) E* sqrt(R_eff).
// The effective modulus E* [Pa] of two spheres of one material: 1/E* = 2 (1 - ν²) / Y. Throws InvalidInput
// naming young_modulus or poisson_ratio.
double effective_modulus_pa(double young_modulus_pa, double poisson_ratio);
// The damping coefficient per effective mass and contact radius, c = 2 A E* / m_eff [m^-1 s^-1]: the
// dissipative force is c m_eff sqrt(R_eff ξ) ξ' (LAMMPS η_n0, LIGGGHTS γ_n). Throws InvalidInput naming a
// non-finite or negative argument.
double damping_per_mass(double dissipative_constant_s, double effective_modulus_pa, double effective_mass_kg);
// The inverse: A [s] = c m_eff / (2 E*).
double dissipative_constant_from_damping_per_mass(double damping_per_mass, double effective_modulus_pa,
                                                  double effective_mass_kg);
// β [s^{1/5} m^{-1/5}] of the equation m_eff ξ'' = -K ξ^{3/2} - D sqrt(ξ) ξ' with K [N m^-3/2] and
// D [N s m^-3/2] the coefficients a DEM code's parameters give one pair: k = K/m_eff, γ = D/m_eff.
double beta_of_coefficients(double elastic_coefficient, double damping_coefficient, double effective_mass_kg);

}  // namespace restitution
