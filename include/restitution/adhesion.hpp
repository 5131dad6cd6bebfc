// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Adhesive collisions of two spheres: JKR (as LAMMPS 20220106 codes it, and the textbook model) and DMT, with
// viscous dissipation. Not members of the contact-law family (contact_law.hpp): there the force vanishes at
// zero overlap and the contact lives at positive overlap, while a JKR contact snaps in with a finite
// attractive force and holds on to negative overlap, and the collision may never end (the spheres stick).
// docs/adhesion.md derives every formula used here.
//
// Conventions: γ is the surface energy of one surface [J/m²]; the work of adhesion of two like surfaces is
// w = 2γ, the JKR pull-off force F_c = (3/2)πwR = 3πγR (LAMMPS's and Johnson's). E* is the effective modulus,
// 1/E* = (1 − ν1²)/Y1 + (1 − ν2²)/Y2 (LAMMPS's `jkr E damp ν γ` takes Young's modulus Y and builds E*
// itself).
#include <string>
#include <vector>

#include "restitution/solve_types.hpp"

namespace restitution {

enum class AdhesiveModel {
  jkr_lammps,  // JKR elastic force, LAMMPS's `damping viscoelastic` (damp·m*·a·δ̇), dropped at the
               // force-controlled pull-off overlap (pair_granular.cpp 20220106, lines 266-275)
  jkr,  // JKR elastic force, viscoelastic dissipation A·δ̇·dF_el/dδ, broken where dδ/da = 0 (textbook)
  dmt,  // DMT as LAMMPS codes it: (4/3)E*sqrt(R)δ^{3/2} − 4πγR and damp·m*·sqrt(Rδ)·δ̇ while δ > 0
  // LIGGGHTS 3.8.0's `cohesion sjkr` on `model hertz/stiffness`: (4/3)E*sqrt(R)δ^{3/2} − k_c·A(δ) and
  // damp·m*·sqrt(Rδ)·δ̇ while δ > 0, A the area of the two spheres' intersection circle (2πRδ for small δ).
  sjkr,
};
// The command-line and scene names: "jkr-lammps", "jkr", "dmt", "sjkr".
[[nodiscard]] const std::vector<std::string>& adhesive_model_names();
// Throws InvalidInput naming the alternatives for an unknown name.
[[nodiscard]] AdhesiveModel adhesive_model_from_name(const std::string& name);
[[nodiscard]] const std::string& adhesive_model_name(AdhesiveModel model);

struct AdhesiveContact {
  AdhesiveModel model = AdhesiveModel::jkr;
  double effective_modulus_pa = 0.0;     // E*
  double effective_radius_m = 0.0;       // R = R1 R2/(R1 + R2)
  double effective_mass_kg = 0.0;        // m* = m1 m2/(m1 + m2)
  double surface_energy_j_per_m2 = 0.0;  // γ per surface (w = 2γ); not used by sjkr
  // jkr-lammps, dmt and sjkr: LAMMPS's `damping viscoelastic` coefficient damp (LIGGGHTS's gamman) [1/(m s)]
  // (force damp·m*·a·δ̇, a the contact radius). jkr: the dissipative constant A [s] (force A·δ̇·dF_el/dδ). 0:
  // elastic.
  double damping = 0.0;
  // sjkr only: LIGGGHTS's cohesionEnergyDensity k_c [J/m³] and the two sphere radii [m], which the exact
  // intersection area needs (0, 0: two equal spheres of radius 2R).
  double cohesion_energy_density_j_per_m3 = 0.0;
  double sphere_radius_1_m = 0.0;
  double sphere_radius_2_m = 0.0;
};

enum class AdhesiveOutcome { bounced, stuck };
[[nodiscard]] const char* adhesive_outcome_name(AdhesiveOutcome outcome);  // "bounced", "stuck"

struct AdhesiveCollision {
  AdhesiveOutcome outcome = AdhesiveOutcome::bounced;
  double eps = 0.0;            // 0 when stuck
  double one_minus_eps = 1.0;  // from the energy balance, without cancellation near ε = 1
  // From first touch to the break (bounced), or to the turning point after which the spheres are bound
  // (stuck).
  double contact_time_s = 0.0;
  double max_compression_m = 0.0;
  // Bounced: the work the neck takes until it breaks (the elastic hysteresis: U at the break overlap). Stuck:
  // the kinetic energy not lost to viscosity by the turning point, which the neck keeps bound.
  double hysteresis_work_j = 0.0;
  double viscous_work_j = 0.0;  // work of the damping force from first touch to the end above
  // The model's extra dimensionless group: the impact's kinetic energy over the adhesion energy unit,
  // ½m*v²/(πwA²) with A³ = πwR²/E* (JKR), ½m*v²/(F_D L) with F_D = 4πγR, L = (F_D/ρ)^{2/3} (DMT),
  // ½m*v²/(F_s L) with L = (2πk_cR/ρ)², F_s = 2πk_cRL (sjkr); ρ = (4/3)E*sqrt(R).
  double kinetic_to_adhesion_energy = 0.0;
  SolverStats stats;
};

// One collision at impact speed v [m/s], to relative tolerance T in [1e-12, 1e-2] (ε to T·min(ε, 1 − ε) is
// the aim; tests/test_adhesion.cpp checks it against closed forms and an independent integration).
// Throws InvalidInput for a contact or speed that is not finite and positive (γ ≥ 0 and damping ≥ 0 allowed:
// γ = 0 is refused with the non-adhesive law to use instead), NumericalFailure when CVODE fails.
[[nodiscard]] AdhesiveCollision solve_adhesive(const AdhesiveContact& contact, double impact_speed_m_per_s,
                                               double tolerance = kDefaultTolerance);

struct StickingSpeed {
  double speed_m_per_s = 0.0;  // 0: the spheres never stick (undamped DMT or sjkr)
  int solves = 0;
};
// The impact speed below which the spheres stick, to relative tolerance T: the root of the energy left at the
// break overlap (bracketed, then Brent's method); the elastic JKR value is the closed form sqrt(2W/m*).
[[nodiscard]] StickingSpeed sticking_speed(const AdhesiveContact& contact,
                                           double tolerance = kDefaultTolerance);

// Closed forms of the elastic model (docs/adhesion.md): the hysteresis work W of the model's break rule [J]
// (0 for DMT and sjkr), the overlap at which the contact breaks [m] (negative for JKR, 0 for DMT and sjkr),
// the JKR pull-off force F_c = 3πγR [N] and the adhesion energy unit πwA² [J].
[[nodiscard]] double elastic_hysteresis_work_j(const AdhesiveContact& contact);
[[nodiscard]] double break_overlap_m(const AdhesiveContact& contact);
[[nodiscard]] double jkr_pull_off_force_n(const AdhesiveContact& contact);

}  // namespace restitution
