#pragma once
// Contact laws: the equation of motion of the compression x(τ), written once for every engine.
//
// Every law here has the form
//     x'' = -w(x) · (c_d · x' + c_s · x),   x(0) = 0,  x'(0) = v0,
// with w(x) = sqrt(x) for viscoelastic Hertz spheres and w(x) = 1 for the linear dash-pot. For Hertz
// spheres w(x) = 0 at x <= 0 (no force without overlap; sqrt of a trial step's negative x is never taken).
// The dash-pot keeps its smooth continuation past x = 0: only trial steps and the root finder see x < 0,
// and a force switched off there would put a jump exactly at the naive end and spoil its location. The force
// vanishes where c_d x' + c_s x = 0: that is the root function of the delayed-recovery end (docs/design.md
// §1). The dissipated energy per unit (scaled) mass grows as dD/dτ = c_d · w(x) · x'^2, so D = c_d ∫ w(x)
// x'^2 dτ; the elastic energy is U(x) = c_s ∫_0^x w(s) s ds.
#include <cmath>

namespace restitution {

enum class LawKind { viscoelastic_hertz, linear_dashpot };

// The contracted range of ζ: every ζ in [0, kLargestCheckedZeta] is checked against the reference solutions
// (docs/accuracy.md). The front ends (CLI, sweeps, scenes, calibration) refuse larger ζ with
// require_checked_zeta; the solver itself still accepts them (tests probe beyond the range).
inline constexpr double kLargestCheckedZeta = 1e6;
// Throws InvalidInput naming ζ and the checked range when zeta > kLargestCheckedZeta (or is not finite).
void require_checked_zeta(double zeta);

const char* law_name(LawKind kind);  // "viscoelastic-hertz" | "linear-dashpot"

struct ContactLaw {
  LawKind kind = LawKind::viscoelastic_hertz;
  double damping = 0.0;           // c_d
  double stiffness = 1.0;         // c_s
  double initial_velocity = 1.0;  // v0 = x'(0) in the law's own units
  double parameter = 0.0;         // ζ = β v^{1/5} (Hertz) or the damping ratio r (dash-pot)
  // Natural scaling (x'(0) = 1): x_natural = x / length_scale, τ_natural = τ / time_scale.
  double length_scale = 1.0;
  double time_scale = 1.0;

  // Viscoelastic Hertz in natural units: x'' + ζ x' sqrt(x) + x^{3/2} = 0, x'(0) = 1.
  static ContactLaw hertz_natural(double zeta);
  // Viscoelastic Hertz in the 2008 paper's scaling (its Eq. 23):
  // x'' + β v^{-1/5} x' sqrt(x) + v^{-2/5} x^{3/2} = 0, x'(0) = v^{4/5};
  // β in s^{1/5} m^{-1/5} (after the paper's scaling of length and time), v the impact speed.
  static ContactLaw hertz_scaled(double beta, double velocity);
  // Linear dash-pot x'' + 2 r x' + x = 0, x'(0) = 1 (time in units of 1/ω0; r = β/ω0 of the 2008 paper).
  static ContactLaw linear_dashpot(double damping_ratio);

  [[nodiscard]] double shape(double x) const {
    if (kind == LawKind::linear_dashpot) return 1.0;
    return x > 0.0 ? std::sqrt(x) : 0.0;
  }
  [[nodiscard]] double shape_derivative(double x) const {
    if (x <= 0.0 || kind == LawKind::linear_dashpot) return 0.0;
    return 0.5 / std::sqrt(x);
  }
  // c_d x' + c_s x: the force divided by w(x); it changes sign at the delayed-recovery end.
  [[nodiscard]] double force_factor(double x, double v) const { return damping * v + stiffness * x; }
  [[nodiscard]] double acceleration(double x, double v) const { return -shape(x) * force_factor(x, v); }
  [[nodiscard]] double dacceleration_dx(double x, double v) const {
    return -(shape_derivative(x) * force_factor(x, v) + shape(x) * stiffness);
  }
  [[nodiscard]] double dacceleration_dv(double x) const { return -shape(x) * damping; }
  // The dissipated energy is D = c_d · ∫ w(x) x'^2 dτ; the integrand is kept free of c_d so that it stays
  // of order one as c_d -> 0 and D keeps full relative accuracy.
  [[nodiscard]] double dissipation_integrand(double x, double v) const { return shape(x) * v * v; }
  [[nodiscard]] double ddissipation_integrand_dx(double x, double v) const {
    return shape_derivative(x) * v * v;
  }
  [[nodiscard]] double ddissipation_integrand_dv(double x, double v) const { return 2.0 * shape(x) * v; }
  [[nodiscard]] double elastic_energy(double x) const {
    if (x <= 0.0) return 0.0;
    return kind == LawKind::viscoelastic_hertz ? stiffness * 0.4 * x * x * std::sqrt(x)
                                               : stiffness * 0.5 * x * x;
  }
};

}  // namespace restitution
