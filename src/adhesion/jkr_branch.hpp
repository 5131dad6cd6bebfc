// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The JKR equilibrium branch in scaled form, parametrised by the contact radius s = a/A, A³ = πwR²/E*
// (docs/adhesion.md §2). Overlap in units of A²/R, force in πwR, energy in πwA²:
//   δ(s) = s² − √2 s^{1/2},   f(s) = (4/3)s³ − 2√2 s^{3/2},   U(s) = G(s) − G(s0) = ∫_{0}^{δ(s)} f dδ,
//   G(s) = (8/15)s⁵ − (4√2/3)s^{7/2} + s².
// Every function is analytic for s > 0; the collision lives on s ≥ 1/2. Private to the library.
#include <cmath>

namespace restitution::adhesion {

inline const double kSqrt2 = std::sqrt(2.0);
// Snap-in at first touch: δ(s0) = 0.
inline const double kSnapInRadius = std::cbrt(2.0);
// Force-controlled pull-off, df/ds = 0: s³ = 9/8 (LAMMPS's break point, f = −F_c).
inline const double kForceControlledBreakRadius = std::cbrt(9.0 / 8.0);
// Displacement-controlled break, dδ/ds = 0: s = 1/2 (the textbook rule, f = −(5/9)F_c).
inline constexpr double kDisplacementControlledBreakRadius = 0.5;

[[nodiscard]] inline double jkr_overlap(double s) {
  return s * s - kSqrt2 * std::sqrt(s);
}
[[nodiscard]] inline double jkr_overlap_slope(double s) {
  return 2.0 * s - 1.0 / (kSqrt2 * std::sqrt(s));
}
[[nodiscard]] inline double jkr_force(double s) {
  return (4.0 / 3.0) * s * s * s - 2.0 * kSqrt2 * s * std::sqrt(s);
}
[[nodiscard]] inline double jkr_force_slope(double s) {
  return 4.0 * s * s - 3.0 * kSqrt2 * std::sqrt(s) / 2.0;
}
// The potential energy stored along the branch since snap-in (energy unit πwA²).
[[nodiscard]] double jkr_potential(double s);
// U at the break of each rule in closed form: (3/5)2^{2/3} − (2/5)(9/8)^{2/3} (force-controlled) and
// 1/10 + (3/5)2^{2/3} (displacement-controlled).
[[nodiscard]] double jkr_break_work(double break_radius);

}  // namespace restitution::adhesion
