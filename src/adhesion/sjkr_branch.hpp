// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// LIGGGHTS's sjkr cohesion on Hertz in scaled form (docs/adhesion.md §10): u = sqrt(δ/L), L = (2πk_cR/ρ)²,
// force in F_s = 2πk_cRL, energy in F_s·L. The cohesive area is the intersection circle of the two spheres,
//   A(δ) = (π/4)·δ(2S − δ)(2r1 − δ)(2r2 − δ)/(S − δ)²,   S = r1 + r2,
// = 2πRδ·g(δ) with g(0) = 1; its work ∫0^δ A = (π/4)δ²[S(4R − δ)/(S − δ) − δ/3] in closed form. Private to
// the library.

namespace restitution::adhesion {

struct SjkrRadii {  // the sphere radii and R in units of L
  double first = 0.0;
  double second = 0.0;
  double effective = 0.0;
};

// The scaled elastic force (repulsive positive) u³ − u²·g(u²) at u ≥ 0.
[[nodiscard]] double sjkr_force(const SjkrRadii& radii, double u);
// The potential since first touch: (2/5)u⁵ − ∫0^{u²} x g(x) dx.
[[nodiscard]] double sjkr_potential(const SjkrRadii& radii, double u);

}  // namespace restitution::adhesion
