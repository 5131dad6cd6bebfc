// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Derived large-ζ laws of ε for both ends of the collision. Natural units (x'(0) = 1); the derivation is in
// docs/asymptotics.md.
//
// With x = ζ^{-2/3} X, τ = ζ^{-2/3} T the equation becomes X'' + sqrt(X) X' + δ X^{3/2} = 0, δ = ζ^{-5/3}.
//  * delayed recovery (X' = -δX): ε = δ X_m [1 - δ (T_e - 5/(2q)) + O(δ² ln² δ)], X_m = (3/2)^{2/3},
//    q = sqrt(X_m), q T_e = ln A - 2 ln δ, A = X_m exp(ln 2 + ln(3)/2 - π/(2 sqrt 3)).
//  * naive: x = ζ^{-4} Y, τ = ζ σ maps the equation onto itself with ζ = 1 and Y'(0) = ζ^5; the trajectory
//    falls onto the slow manifold of Y'' + sqrt(Y)(Y' + Y) = 0 and reaches Y = 0 with speed κ, so
//    ε = κ ζ^{-5} up to corrections that fall off like exp(-2 q ζ^{5/3}).
namespace restitution::asymptotics {

inline constexpr double kDelayedRecoveryExponent = -5.0 / 3.0;
inline constexpr double kNaiveExponent = -5.0;

// X_m = (3/2)^{2/3}: the maximal compression of the undamped-elastic limit in the scaled variables.
double delayed_recovery_prefactor();

// The first correction ε/(X_m ζ^{-5/3}) - 1 ≈ ζ^{-5/3} (a ln ζ + b): a = -10/(3q), b = (5/2 - ln A)/q.
struct Correction {
  double log_coefficient = 0.0;  // a
  double constant = 0.0;         // b
};
Correction delayed_recovery_correction();

// ε at the delayed-recovery end from the derived law: terms = 1 (leading) or 2 (with the first correction).
// Throws InvalidInput for zeta <= 0 or terms outside {1, 2}.
double delayed_recovery_eps(double zeta, int terms);

// d ln ε / d ln ζ of the two-term law: -5/3 + (5/3) δ (T_e - 5/(2q)) - (10/(3q)) δ + O(δ² ln² δ).
double delayed_recovery_local_slope(double zeta);

// κ = lim ζ^5 ε_naive, the speed with which the slow-manifold solution of dp/du = -2u²(p + u²)/p
// (p = Y', u = sqrt(Y), p ~ -(u² + u + 3/2) as u -> ∞) reaches u = 0. Computed by classical Runge-Kutta from
// u = 40 with two step sizes and Richardson extrapolation (independent of CVODE).
struct Prefactor {
  double value = 0.0;
  double error_estimate = 0.0;
};
Prefactor naive_prefactor();

// κ ζ^{-5}; throws InvalidInput for zeta <= 0.
double naive_eps(double zeta, double kappa);

}  // namespace restitution::asymptotics
