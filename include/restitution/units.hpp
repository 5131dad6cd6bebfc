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

namespace restitution {

// The Hertz constants of a pair of spheres, in SI units.
struct HertzConstants {
  double k = 0.0;      // ρ / m_eff [s^-2 m^-1/2]
  double gamma = 0.0;  // (3/2) A ρ / m_eff [s^-1 m^-1/2]
  double beta = 0.0;   // γ k^{-3/5} [s^{1/5} m^{-1/5}]
};

// k and the dissipative constant A [s] -> γ and β. Throws InvalidInput naming k or A when not finite and > 0
// (A = 0 is allowed: elastic spheres).
HertzConstants hertz_constants(double k, double dissipative_constant_s);

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

// The 1999 paper's characteristic velocity g* [m/s]: (g*)^{-1/5} = C1 (3/2) A (ρ/m_eff)^{2/5} = C1 β
// (C1 in closed form: series::c1_closed_form)
// (its Eq. 31), so that (g/g*)^{1/5} = C1 ζ. Throws InvalidInput naming beta when not > 0.
double characteristic_velocity_m_s(double beta);
// The inverse: β = (g*)^{-1/5} / C1. Throws InvalidInput naming characteristic_velocity when not > 0.
double beta_from_characteristic_velocity(double characteristic_velocity_m_s);

}  // namespace restitution
