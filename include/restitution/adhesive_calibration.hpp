// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The damping of an adhesive contact from one measured ε at one impact speed, the surface energy known, or
// the surface energy and the damping together from ε at one speed plus the sticking speed (docs/adhesion.md
// §7a): `calibrate --adhesion`.
#include "restitution/adhesion.hpp"
#include "restitution/material.hpp"

namespace restitution {

struct AdhesiveDampingCalibration {
  double dissipative_constant_s = 0.0;  // A [s]; LAMMPS's damp = 2AE*/m_eff for jkr-lammps and dmt
  AdhesiveContact contact;              // with the damping found
  double eps_at_velocity = 0.0;         // ε re-solved with that damping
  double elastic_eps = 0.0;             // ε of the undamped model at the speed: the largest ε reachable
  int solves = 0;
};

// A such that the model gives ε = eps at impact speed v [m/s] for two spheres of the material with surface
// energy γ [J/m², per surface], to relative tolerance T on A (each solve to T): bracketed upwards from 0 by
// factors of 4 from a thousandth of the elastic contact time, then bisected. Throws InvalidInput for eps
// outside (0, 1), for an eps the undamped model does not exceed at that speed (damping only lowers ε), or a
// bad material, γ or speed.
[[nodiscard]] AdhesiveDampingCalibration calibrate_adhesive_damping(AdhesiveModel model,
                                                                    const Material& material,
                                                                    double surface_energy_j_per_m2,
                                                                    double eps, double impact_speed_m_per_s,
                                                                    double tolerance = kDefaultTolerance);

struct AdhesiveStickingCalibration {
  double surface_energy_j_per_m2 = 0.0;  // γ per surface
  double dissipative_constant_s = 0.0;   // A [s]; LAMMPS's damp = 2AE*/m_eff for jkr-lammps and dmt
  AdhesiveContact contact;               // with γ and the damping found
  double eps_at_velocity = 0.0;          // ε re-solved with (γ, A)
  double sticking_speed_m_per_s = 0.0;   // v_s re-solved with (γ, A)
  // sqrt(1 − (v_s/v)²): ε of the undamped JKR models at the γ that gives v_s, and the limit of every model
  // (DMT too) as the damping vanishes; the largest ε reachable.
  double undamped_eps = 0.0;
  int solves = 0;  // collisions integrated, the sticking speeds' included
};

// γ and A such that the model (jkr-lammps, jkr or dmt) sticks below v_s [m/s] and gives ε = eps at the impact
// speed v [m/s] > v_s, for two spheres of the material, each to relative tolerance T (docs/adhesion.md §7a).
// In the scaled variables ε(v/v_s) depends on the dimensionless damping alone, so one 1-D root in A at a
// reference γ (each trial: a sticking speed and one collision), then γ and A follow from the scaling
// v_s ∝ γ^{5/6}, A ∝ γ^{−1/6} at fixed dimensionless damping. Throws InvalidInput for eps outside (0, 1), v_s
// not in (0, v), an eps at or above the undamped sqrt(1 − (v_s/v)²), sjkr, or a bad material;
// NumericalFailure when the damping needed lies where the solver fails.
[[nodiscard]] AdhesiveStickingCalibration calibrate_adhesive_sticking(AdhesiveModel model,
                                                                      const Material& material, double eps,
                                                                      double impact_speed_m_per_s,
                                                                      double sticking_speed_m_per_s,
                                                                      double tolerance = kDefaultTolerance);

}  // namespace restitution
