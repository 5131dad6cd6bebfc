// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The compliances of one body of a Hertz-Mindlin contact, summed over the two bodies: 1/E* = Σ (1 - ν²)/Y
// and 1/G* = Σ (2 - ν)/G = Σ 2 (2 - ν)(1 + ν)/Y (G = Y/(2 (1 + ν))); a rigid body adds 0. Mindlin's
// tangential stiffness is 8 G* a, the normal one 2 E* a (a the contact radius). Shared by the DEM wall lines
// (dem/wall_lines.cpp) and the oblique impacts on a wall (oblique/oblique_study.cpp), so that both mean the
// same wall.
namespace restitution {

// (1 - ν²)/Y [1/Pa] of one body.
double normal_compliance_per_pa(double young_modulus_pa, double poisson_ratio);
// 2 (2 - ν)(1 + ν)/Y [1/Pa] of one body.
double shear_compliance_per_pa(double young_modulus_pa, double poisson_ratio);

}  // namespace restitution
