// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The damping of an adhesive contact from one measured ε at one impact speed, the surface energy known
// (docs/adhesion.md §7a): `calibrate --adhesion`.
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
                                                                    double tolerance = 1e-10);

}  // namespace restitution
