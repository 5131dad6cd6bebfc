// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The scaled form of an adhesive collision (docs/adhesion.md §4): lengths, times and energies in the model's
// own units, so that one damping number c and the impact speed V remain. Private to the library.
#include "adhesion/sjkr_branch.hpp"
#include "restitution/adhesion.hpp"

namespace restitution::adhesion {

struct ScaledAdhesion {
  AdhesiveModel model = AdhesiveModel::jkr;
  double length_m = 0.0;      // JKR: A²/R; DMT: L = (F_D/ρ)^{2/3}; sjkr: L = (2πk_cR/ρ)²
  double time_s = 0.0;        // sqrt(m* · length / force unit)
  double energy_j = 0.0;      // JKR: πwA²; DMT: F_D L; sjkr: F_s L, F_s = 2πk_cRL
  double damping = 0.0;       // c: damp·A·t0 (jkr-lammps), A_visc/t0 (jkr), damp·sqrt(R L)·t0 (dmt, sjkr)
  double break_radius = 0.0;  // JKR: s at the break; DMT: 0 (u = sqrt(δ/L) at the break)
  double break_energy = 0.0;  // U at the break (scaled): the elastic hysteresis work
  // The energy (kinetic + branch potential) below which the integration stops as certainly bound, well below
  // the break's: JKR 0 (the snap-in level), DMT −0.3 (half the well depth U(1) = −3/5), sjkr −0.05 (half
  // the small-overlap well depth U(1) = −1/10).
  double bound_level = 0.0;
  SjkrRadii sjkr_radii;  // sjkr only
  [[nodiscard]] double speed_m_per_s() const { return length_m / time_s; }
};

// Throws InvalidInput naming the first field that is not finite, not positive (E*, R, m*) or negative (γ,
// damping); γ = 0 is refused with the non-adhesive law that describes it.
void check_contact(const AdhesiveContact& contact);
[[nodiscard]] ScaledAdhesion scale_adhesion(const AdhesiveContact& contact);

// The branch potential at the scaled position (s for JKR, u = sqrt(δ/L) for DMT and sjkr).
[[nodiscard]] double branch_potential(const ScaledAdhesion& scaled, double position);
// The overlap in units of length_m at the scaled position.
[[nodiscard]] double scaled_overlap(AdhesiveModel model, double position);

}  // namespace restitution::adhesion
