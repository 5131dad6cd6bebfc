// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The adhesive contact of two spheres of one material (adhesion.hpp), assembled once for every front end
// (`eps --adhesion`, `dem --adhesion`, Python's restitution.adhesive_collision).
#include "restitution/adhesion.hpp"
#include "restitution/material.hpp"

namespace restitution {

// E* = Y/(2(1 − ν²)), R_eff and m_eff of the material's two spheres, γ per surface [J/m²], and the model's
// damping from the dissipative constant A [s]: A itself for `jkr`, LAMMPS's `damping viscoelastic`
// coefficient damp = 2AE*/m_eff [1/(m s)] for `jkr-lammps` and `dmt`, and LIGGGHTS's gamman for `sjkr` (whose
// k_c the caller sets; the Hertz mapping of docs/dem.md,
// whose force damp·m_eff·a·δ̇ is A·δ̇·dF_Hertz/dδ; the sphere radii its lens needs are set when they differ).
// The material's own dissipation fields are ignored.
// Throws InvalidInput naming a bad material field or a negative or non-finite A.
[[nodiscard]] AdhesiveContact adhesive_contact_of(AdhesiveModel model, const Material& material,
                                                  double surface_energy_j_per_m2,
                                                  double dissipative_constant_s);

}  // namespace restitution
