// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The tangential models, one row each (tangential_models.cpp): what each DEM code's tangential force does,
// set once, so that the solver, the study, the command line, scenes and Python ask the row instead of testing
// the kind. A new model is one row there and its value of TangentialKind here (docs/design.md, "A new
// tangential model touches").
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "restitution/contact_law.hpp"

namespace restitution::oblique {

// The tangential models of LAMMPS `pair granular ... tangential MODEL`.
//  linear_nohistory: F_t = -min(μ|F_n|, γ_t η |s|) s/|s|                 (pair_granular.cpp:534-541)
//  linear_history:   F_t = -k_t ξ - γ_t η s, ξ' = s while |F_t| <= μ|F_n|; at the cap F_t = μ|F_n| F_t/|F_t|
//                    and ξ is rescaled so that -k_t ξ - γ_t η s is the capped force
//                    (pair_granular.cpp:495-533)
//  mindlin:          linear_history with k_t multiplied by the contact radius a = sqrt(R* δ)
//                    (pair_granular.cpp:431-433)
//  mindlin_rescale:  mindlin whose ξ is scaled by a/a_old whenever a shrinks (unloading, lines 434-445, a_old
//                    the last step's a in history[3], line 489-492): ξ' = s + (a'/a) ξ while a' < 0
//  mindlin/force:    the history is the elastic force H itself, H' = -k_t a s (incremental, lines 482-487),
//                    F_t = H - γ_t η s; at the cap H = C F/|F| + γ_t η s (lines 524-527)
//  mindlin_rescale/force: mindlin/force with H scaled by a/a_old while a shrinks: H' = -k_t a s + (a'/a) H
// where η = γ δ^b is the normal damping coefficient at the current overlap (damp_normal_prefactor,
// pair_granular.cpp:368-373; `damp_tangential = tangential_coeffs[1]*damp_normal_prefactor`, line 427) and
// the cap uses |F_n| (`Fncrit = fabs(Fntot)`, line 419). fix_wall_gran.cpp repeats these at lines 1256-1280.
//
// LIGGGHTS 3.8.0 `tangential history` (Debian's liggghts 3.8.0+repack1, src/tangential_model_history.h) under
// the normal model the project prints for it, `model hertz/stiffness` (src/normal_model_hertz_stiffness.h):
//  liggghts_history: k_t = kt·sqrt(R* δ), γ_t-damping gammat·m*·sqrt(R* δ) (lines 118-122 there), so with
//                    gammat = γ_t·gamman the damping is γ_t times the normal one, as for LAMMPS; ξ' = s; the
//                    cap compares the elastic force alone, kt|ξ| > μ|F_n|
//                    (tangential_model_history.h:174-178), and at the cap F_t = μ|F_n| ξ/|ξ| without damping,
//                    ξ rescaled to the cap (191-199); below it F_t = -kt ξ - γ_t η s (214-217), which may
//                    exceed the cap. Torque arm and contact-point arm R - δ/2 for a pair and a wall
//                    (surface_model_default.h:174-188).
//
// YADE 2023.02a's ViscElPhys shear spring (pkg/dem/ViscoelasticPM.cpp, computeForceTorqueViscEl, under
// Law2_ScGeom_ViscElPhys_Basic), whose normal force is the linear dash-pot kn δ + cn δ' clamped at 0:
//  yade_viscel:      the elastic shear force grows by ks dt times the contact-point velocity (constant ks, so
//                    it is -ks ξ with ξ' = s) and is rotated with the normal; it is tested and capped alone
//                    against tan(frictionAngle)|F_n|, and below the cap the viscous cs s is added, so the
//                    rule is LIGGGHTS's with a constant stiffness: cs = γ_t cn (γ_t the damping factor on
//                    the normal coefficient, b = 0). The arms reach ScGeom's contactPoint, in the torque and
//                    the velocity: R - δ/2 for two spheres (halfway through the overlap), R - δ for a wall
//                    (the centre projected onto it); ObliqueGeometry chooses them.
//
// YADE 2023.02a's Hertz-Mindlin (pkg/dem/HertzMindlin.cpp, Law2_ScGeom_MindlinPhys_Mindlin::go, under
// Ip2_FrictMat_FrictMat_MindlinPhys with betan), whose normal force is kno δ^{3/2} + cn δ', cn = 2 betan
// sqrt(m* kn), kn = (3/2) kno sqrt(δ): the Tsuji member (LawKind::tsuji_hertz, γ = 2 betan sqrt(1.5 m* kno)),
// clamped at 0:
//  yade_mindlin:     an INCREMENTAL shear spring, `shearElastic -= ks (v_s dt)` with the tangent stiffness
//                    ks = kso sqrt(δ) (k_t = kso in N/m^{3/2}), so F_e' = -ks(δ) s (not -d(ks ξ)/dt); rotated
//                    with the normal, tested and capped alone against tan(frictionAngle) F_n (the total,
//                    clamped normal force), and below the cap the viscous cs s is added, cs = 2 betas
//                    sqrt(m* ks): cs over cn is the constant γ_t = (betas/betan) sqrt(kso/(1.5 kno)). The
//                    contact-point velocity is ScGeom::getIncidentVel's ratcheting-free form: the centres'
//                    relative velocity times (R1 + R2)/(R1 + R2 - δ) (a wall's radius counts as the
//                    sphere's) plus the spins at R (ObliqueGeometry::contact_point_arm = radius); the torque
//                    reaches ScGeom's contact point (R - δ/2 for a pair, R - δ for a wall). Debian's YADE
//                    agrees within 3.6e-6 in e_t (tests/dem/oblique_yade_mindlin.cpp).
enum class TangentialKind {
  linear_nohistory,
  linear_history,
  mindlin,
  liggghts_history,
  yade_viscel,
  mindlin_rescale,
  mindlin_force,
  mindlin_rescale_force,
  yade_mindlin
};

// Where the torque acts, and which arm the spins have in the contact-point velocity: at the contact radius R
// (fix_wall_gran.cpp:1512, `radius*tor`), or at R - δ/2 as LAMMPS's pair does (pair_granular.cpp:663,
// `dist_to_contact = radi-0.5*delta`). The slip velocity uses R in both (pair_granular.cpp:407-409). YADE's
// wall takes R - δ in both, its contact point the centre projected onto the wall
// (pkg/dem/Ig2_Facet_Sphere_ScGeom.cpp, Ig2_Wall_Sphere_ScGeom::go).
enum class TorqueArm { radius, radius_minus_half_overlap, radius_minus_overlap };

// What the model carries from step to step: nothing (the force is viscous alone), the tangential displacement
// ξ (the force -k_t ξ), or the elastic force H itself, incremented by -k_t s dt.
enum class HistoryKind { none, displacement, force };
// How k_t grows with the overlap: constant, k_t sqrt(R* δ) (the contact radius a), or k_t sqrt(δ).
enum class StiffnessGrowth { constant, contact_radius, overlap };
// What the Coulomb cap is tested against and caps: the whole trial force (elastic and damping), or the
// elastic force alone, the damping added below the cap only.
enum class CapTest { trial_force, elastic_force };

// The part of a row the equations of motion read (oblique_model.hpp).
struct TangentialRule {
  HistoryKind history = HistoryKind::none;
  StiffnessGrowth growth = StiffnessGrowth::constant;
  bool rescales_on_unloading = false;  // the history scaled by a/a_old while the contact radius a shrinks
  CapTest cap_test = CapTest::trial_force;
  // The centres' relative velocity times (R1 + R2)/(R1 + R2 - δ) in the contact-point velocity (YADE's
  // ScGeom::getIncidentVel).
  bool incident_velocity_gain = false;
};

struct ContactArms {
  TorqueArm torque = TorqueArm::radius;
  TorqueArm contact_point = TorqueArm::radius;
};

// The elastic constants a default stiffness is made of: E*, G* and R* of the contact.
struct ContactModuli {
  double effective_modulus_pa = 0.0;
  double effective_shear_modulus_pa = 0.0;
  double effective_radius_m = 0.0;
};

struct TangentialModel {
  TangentialKind kind;
  const char* name;        // the code's keyword (LAMMPS's, mindlin/force with its slash) or ours
  const char* code;        // the DEM code whose model it is: dem::code_name's "lammps", "liggghts", "yade"
  const char* code_title;  // and as its own name is written: "LAMMPS"
  const char* source;      // the code's name of the model, after code_title: "pair granular"
  TangentialRule rule;
  ContactArms pair;  // the arms the code takes for two spheres
  ContactArms wall;  // and for a sphere on a wall
  // The unit of k_t (TangentialForce::stiffness); nullptr where the model has no stiffness.
  const char* stiffness_unit;
  // k_t where none is given, from the contact's moduli (LAMMPS's `mindlin NULL`: 8 G*); nullptr where the
  // stiffness must be given (or the model has none).
  double (*default_stiffness)(const ContactModuli&);
  // The normal law the code pairs the model with (nullopt: any member of the family, as LAMMPS's pair
  // granular combines its models), and in words.
  std::optional<LawKind> normal_law;
  const char* normal_law_words;
  // Why the oblique study (restitution oblique, a scene's [[oblique]], Python) does not run it and where it
  // is run instead; nullptr where it does.
  const char* study_refusal;
  // C in |error of e_t| <= C/N at N steps per contact of the code's first-order step, measured; and how.
  double et_error_coefficient;
  const char* et_error_basis;
  // The cap as the code applies it, in words.
  const char* cap_rule;

  [[nodiscard]] bool has_stiffness() const { return rule.history != HistoryKind::none; }
  [[nodiscard]] bool runs_in_study() const { return study_refusal == nullptr; }
  [[nodiscard]] const ContactArms& arms(bool pair_of_spheres) const { return pair_of_spheres ? pair : wall; }
};

// Every row, in the order of TangentialKind.
std::span<const TangentialModel> tangential_models();
const TangentialModel& tangential_model(TangentialKind kind);
// The row of a name; nullptr for none.
const TangentialModel* find_tangential_model(std::string_view name);

const char* tangential_name(TangentialKind kind);
// The inverse; throws InvalidInput naming the value and the choices.
TangentialKind tangential_from_name(const std::string& name);
const std::vector<std::string>& tangential_names();
// The names of the rows of one code ("lammps"; every row for ""), in table order.
std::vector<std::string> tangential_names_of(std::string_view code);

// LAMMPS's Mindlin family (mindlin, mindlin_rescale, mindlin/force, mindlin_rescale/force): stiffness k_t·a,
// k_t in N/m², `NULL` for 8 G*.
bool is_lammps_mindlin(TangentialKind kind);

}  // namespace restitution::oblique
