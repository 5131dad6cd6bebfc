// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The oblique impact as a front end gives it (the command `restitution oblique`, a scene's [[oblique]]
// section, Python's restitution.oblique): a material, a tangential model, impact angles and initial spins,
// turned into the solver's geometry and forces by one set of rules whose errors name the argument in the
// caller's spelling
// (--friction on the command line, friction in Python and scenes); the sweep over every (angle, spin) pair;
// and Maw, Barber & Fawcett's normalized variables ψ (Wear 38, 101 (1976)), docs/oblique.md "Maw's diagram".
#include <optional>
#include <string>
#include <vector>

#include "restitution/material.hpp"
#include "restitution/solve_types.hpp"
// The solver's interface (src/oblique/oblique_contact.hpp) stays where the other studies include it from;
// this folder is the part of the module the Python module may include, and it re-exports that header by its
// path.
#include "../../oblique_accuracy.hpp"
#include "../../oblique_contact.hpp"

namespace restitution::oblique {

struct ObliqueInputs {
  // Elastic data, radii, density or masses (material_from_fields); its dissipation fields are not read.
  Material material;
  // The damping of viscoelastic Hertz, one of the two required (never a silent elastic default): A [s] (0 for
  // an elastic contact), or ε measured head-on at eps_velocity_m_s [m/s] on this contact (A calibrated, as
  // `calibrate`, `eps` and `dem` do it).
  std::optional<double> dissipative_constant_s;
  std::optional<double> eps;
  std::optional<double> eps_velocity_m_s;
  // The normal law: viscoelastic-hertz, tsuji-hertz or hertz-constant-damping (the material's Hertz
  // stiffness; the last two damped by eps and velocity only, or elastic with A = 0).
  std::string law = "viscoelastic-hertz";
  // A sphere on a flat wall: rigid (as `dem --wall`), or of its own Young's modulus [Pa] and Poisson ratio
  // (both or neither); 1/E* and 1/G* sum the sphere's and the wall's compliances.
  bool wall = false;
  std::optional<double> wall_young_modulus_pa;
  std::optional<double> wall_poisson_ratio;
  bool fixed_normal = false;                   // two spheres: keep the normal of the impact
  std::string tangential = "mindlin";          // as `dem`: its default stiffness needs no option
  std::optional<double> tangential_stiffness;  // N/m (linear_history), N/m² (mindlin; default 8 G*)
  double tangential_damping = 0.0;             // LAMMPS's factor on the normal damping coefficient
  std::optional<double> friction;              // μ, required
  std::string end = "delayed-recovery";
  std::string torque_arm = "lammps";        // lammps | radius | radius-minus-half-overlap
  double tolerance = kDefaultTolerance;     // the accuracy contract's T (oblique_accuracy.hpp)
  double speed_m_s = 1.0;                   // impact speed: v cos θ normal, v sin θ tangential
  std::vector<double> angles_deg;           // from the normal, in [0, 90)
  std::vector<double> spins_rad_s = {0.0};  // initial spins of the first sphere
};

// The tangential models oblique_setup runs (the command's --tangential, Python's and a scene's choices): the
// library's less yade_viscel and yade_mindlin, whose normal laws are not viscoelastic Hertz.
const std::vector<std::string>& oblique_tangential_names();

// How errors spell an argument: "--tangential-stiffness" (option) or "tangential_stiffness" (keyword).
enum class ArgumentStyle { option, keyword };

struct ObliqueSetup {
  ObliqueGeometry geometry;
  NormalForce normal;
  TangentialForce tangential;
  ObliqueOptions options;
  double tolerance =
      kDefaultTolerance;              // the contract's T; options.relative_tolerance is CVODE's rtol for it
  double effective_modulus_pa = 0.0;  // E*
  double effective_shear_modulus_pa = 0.0;  // G* (Mindlin's k_t = 8 G* a)
  double dissipative_constant_s = 0.0;      // A of viscoelastic Hertz, given or calibrated (0: other laws)
  bool rigid_wall = false;                  // a wall without a material of its own
  double speed_m_s = 1.0;
  std::vector<double> angles_deg;
  std::vector<double> spins_rad_s;
};

// The setup the inputs describe; throws InvalidInput naming the argument that is missing or bad.
ObliqueSetup oblique_setup(const ObliqueInputs& inputs, ArgumentStyle style);

// The velocities before contact at angle_deg from the normal, the first sphere spinning at spin_rad_s.
ImpactVelocity impact_at(const ObliqueSetup& setup, double angle_deg, double spin_rad_s);

// Maw, Barber & Fawcett's normalized contact-point velocity, ψ = κ s/(μ v_n) with κ = 4G*/E*: the Mindlin
// stiffness over the normal one (8G*·a over 2E*·a; 2(1 − ν)/(2 − ν) for spheres of one material and for a
// sphere on a rigid wall), so that the sticking
// condition |F_t| <= μ F_n and the stick and slip equations of the elastic Mindlin contact, written in ψ and
// the normal law's natural time, depend on χ alone (docs/oblique.md derives it). NaN for μ = 0.
double maw_psi(const ObliqueSetup& setup, double slip_m_s, double normal_speed_m_s);
// χ = (κ/2) · (1 + m* Σ R_i²/I_i): 7(1 − ν)/(2(2 − ν)) for a homogeneous sphere on a rigid wall or a pair of
// equal ones. A contact that slides throughout moves ψ by −2(1 + ε)χ (−4χ elastic).
double maw_chi(const ObliqueSetup& setup);

struct ObliqueImpact {
  double angle_deg = 0.0;
  double initial_spin_rad_s = 0.0;
  ObliqueResult result;
  double psi_in = 0.0;   // ψ₁ of the incoming slip velocity
  double psi_out = 0.0;  // ψ₂ of the outgoing one, over the same incoming normal speed
  // The accuracy contract (oblique_accuracy.hpp): CVODE's rtol of `result`, and whether the outputs could not
  // be shown within the tolerance (near the stick/slip boundary), said in words in `conditioning`.
  double relative_tolerance = 0.0;
  bool ill_conditioned = false;
  std::string conditioning;
  // Empty where the impact was solved; otherwise why the solve failed (a NumericalFailure's words), and every
  // output of `result` and psi_out is NaN (its switches empty), so that one impact never loses the others.
  std::string failure;
  [[nodiscard]] bool solved() const { return failure.empty(); }
};

// One impact of the setup at angle_deg from the normal, the first sphere spinning at spin_rad_s, solved
// within the setup's tolerance (solve_oblique_within). A numerical failure is returned in `failure`, not
// thrown; bad input still throws InvalidInput.
ObliqueImpact solve_impact(const ObliqueSetup& setup, double angle_deg, double spin_rad_s);

// Every (angle, spin) pair, angles outermost, in the order given.
std::vector<ObliqueImpact> oblique_sweep(const ObliqueSetup& setup);
// How many of the impacts failed (ObliqueImpact::failure).
std::size_t failed_count(const std::vector<ObliqueImpact>& impacts);

// The tangential restitution of the sticking limit μ → ∞ (the slope −ψ₂/ψ₁ of Maw's diagram at ψ₁ → 0):
// one impact at 1° without spin with the Coulomb cap removed (ObliqueOptions::sticking_limit), whose
// equations are linear in the slip, so that no switch function can fail near a huge cap. Should the solve
// fail all the same, `tangential_restitution` is NaN and `failure` says why (the plot and the report leave
// the limit out with that note).
struct StickingLimit {
  double tangential_restitution = 0.0;
  std::string failure;
};
StickingLimit sticking_limit_restitution(const ObliqueSetup& setup);

}  // namespace restitution::oblique
