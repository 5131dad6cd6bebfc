// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The oblique contact of two spheres, or of a sphere and a flat wall, as an initial-value problem: the normal
// law of the family (F_n = k δ^a + γ δ^b δ', include/restitution/contact_law.hpp) together with a tangential
// force as Debian's LAMMPS 20220106 writes it in `pair granular` (src/GRANULAR/pair_granular.cpp) and `fix
// wall/gran granular` (src/GRANULAR/fix_wall_gran.cpp), in the limit of a vanishing time step. The switches
// between sticking (the tangential force below the Coulomb cap μ|F_n|) and sliding (at the cap) are located
// as CVODE root-function events; the contact ends at the normal law's end event. docs/oblique.md derives the
// model from the source, line by line.
//
// The impact is planar: n is the line of centres (fixed for a wall; for a pair it turns during the contact
// unless ObliqueGeometry::fixed_normal), t the tangent in the impact plane, spins are about n × t. Results
// are given in the frame of the impact (the normal at first contact). The contact-point slip velocity of the
// first body relative to the second is
//     s = u + R1 ω1 + R2 ω2
// with u the tangential velocity of the first centre relative to the second; a positive spin adds to s.
#include <optional>
#include <string>
#include <vector>

#include "restitution/contact_law.hpp"
#include "restitution/solve_types.hpp"

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

// LAMMPS's Mindlin family (mindlin, mindlin_rescale, mindlin/force, mindlin_rescale/force): stiffness k_t·a,
// k_t in N/m², `NULL` for 8 G*.
bool is_lammps_mindlin(TangentialKind kind);

// "linear_nohistory" | "linear_history" | "mindlin" | "mindlin_rescale" | "mindlin/force" |
// "mindlin_rescale/force" (LAMMPS's keywords) | "liggghts_history" | "yade_viscel" | "yade_mindlin"
const char* tangential_name(TangentialKind kind);
// The inverse; throws InvalidInput naming the value and the choices.
TangentialKind tangential_from_name(const std::string& name);
const std::vector<std::string>& tangential_names();

struct Body {
  double radius_m = 0.0;
  double mass_kg = 0.0;
  double inertia_kg_m2 = 0.0;  // about a diameter
};
// A homogeneous solid sphere: I = 2/5 m R².
Body solid_sphere(double radius_m, double mass_kg);

// Where the torque acts: at the contact radius R (fix_wall_gran.cpp:1512, `radius*tor`), or at R - δ/2 as
// LAMMPS's pair does (pair_granular.cpp:663, `dist_to_contact = radi-0.5*delta`). The slip velocity uses R in
// both (pair_granular.cpp:407-409). YADE's wall takes R - δ in both, its contact point the centre projected
// onto the wall (pkg/dem/Ig2_Facet_Sphere_ScGeom.cpp, Ig2_Wall_Sphere_ScGeom::go).
enum class TorqueArm { radius, radius_minus_half_overlap, radius_minus_overlap };

struct ObliqueGeometry {
  Body first;
  std::optional<Body> second;  // none: a flat immovable wall (effective radius R1, effective mass m1)
  TorqueArm torque_arm = TorqueArm::radius;
  // A pair's line of centres turns during the contact as the centres pass each other (LAMMPS's pair: n from
  // the positions every step, the history projected onto the new tangent plane with its magnitude kept,
  // pair_granular.cpp:450-471); true keeps the normal of the impact throughout (the textbook model, the
  // closed forms). A wall's normal is fixed either way.
  bool fixed_normal = false;
  // The arm of the spins in the contact-point velocity: R (LAMMPS, pair_granular.cpp:407-409) or R - δ/2
  // (LIGGGHTS, surface_model_default.h:176-186, also for a wall).
  TorqueArm contact_point_arm = TorqueArm::radius;
};

// The normal force F_n = k δ^a + γ δ^b δ' of a member of the family (SI: k in N/m^a, γ in N s/m^{1+b}).
struct NormalForce {
  LawKind kind = LawKind::viscoelastic_hertz;
  double stiffness = 0.0;
  double damping = 0.0;
};

struct TangentialForce {
  TangentialKind kind = TangentialKind::linear_history;
  // k_t: N/m for linear_history and yade_viscel (its ks); N/m² for the mindlin family and liggghts_history
  // (their stiffness is k_t·sqrt(R* δ)); N/m^{3/2} for yade_mindlin (its kso: ks = kso sqrt(δ)); unused by
  // linear_nohistory.
  double stiffness = 0.0;
  // γ_t (LAMMPS's `damping` of the tangential model, dimensionless): the tangential damping coefficient is
  // γ_t times the normal one, γ δ^b.
  double damping_factor = 0.0;
  double friction = 0.0;  // μ
};

// The velocities just before contact. normal_m_s > 0 is the approach speed.
struct ImpactVelocity {
  double normal_m_s = 0.0;
  double tangential_m_s = 0.0;    // u: of the first centre relative to the second, along t
  double spin_first_rad_s = 0.0;  // ω1 (sign: R1 ω1 adds to the slip velocity)
  double spin_second_rad_s = 0.0;
};

struct ObliqueOptions {
  // naive: the contact ends where δ returns to 0 (LAMMPS without limit_damping; the Coulomb cap is then
  // μ|F_n|, pair_granular.cpp:419); delayed_recovery: where F_n first reaches 0 (limit_damping).
  CollisionEnd end = CollisionEnd::delayed_recovery;
  double relative_tolerance = kDefaultTolerance;  // CVODE's, on the natural-unit state
  int max_switches = 1000;  // more stick/slip switches in one contact is reported as a failure
  // The sticking limit μ → ∞: the Coulomb cap removed, the contact sticks from first contact to the end and
  // the friction is not read. No switch function is integrated, so nothing near a huge cap can fail (a finite
  // μ = 1e12 drove CVODE into error-test failures).
  bool sticking_limit = false;
};

enum class ContactMode { stick, slip };
const char* mode_name(ContactMode mode);  // "stick" | "slip"

// A switch of the contact's mode at time_s after first contact (the first entry, at 0, is the initial mode).
struct ModeSwitch {
  double time_s = 0.0;
  ContactMode mode = ContactMode::stick;
};

struct ObliqueResult {
  double normal_restitution = 0.0;        // ε = -v_n'/v_n
  double tangential_restitution = 0.0;    // e_t = -s'/s (NaN when s = 0 at impact)
  double slip_velocity_m_s = 0.0;         // s' after contact
  double tangential_velocity_m_s = 0.0;   // u' after contact
  double normal_velocity_m_s = 0.0;       // separation speed ε v_n
  double spin_first_rad_s = 0.0;          // ω1' after contact
  double spin_second_rad_s = 0.0;         // ω2' (0 for a wall)
  double impact_angle_rad = 0.0;          // atan2(u, v_n) before contact
  double rebound_angle_rad = 0.0;         // atan2(u', ε v_n) after contact
  double impulse_ratio = 0.0;             // J_t/J_n, tangential over normal impulse on the first body
  double line_of_centres_turn_rad = 0.0;  // θ: how far a pair's line of centres turned during the contact
  double contact_time_s = 0.0;
  double stick_time_s = 0.0;  // time below the Coulomb cap
  double slip_time_s = 0.0;   // time at the cap
  std::vector<ModeSwitch> switches;
  // The smallest interior minimum of a switch function's distance from 0, relative to the size of its terms,
  // over the contact (1: none): near 0 the contact nearly switched, and the outcome is ill-conditioned
  // (oblique_accuracy.hpp).
  double closest_switch_approach = 1.0;
  // How far the mode sequence is from changing: the smallest of the switch function's interior minima of
  // distance (seen at step ends, as above, without the near-miss criterion) and of the largest distance each
  // phase that ended in a switch reached (a short phase nearly did not happen). Relative, 1 at most.
  double switch_margin = 1.0;
  // LIGGGHTS's and YADE's rule (the damping added below the cap only): a slip ended where the sticking force
  // drives the contact straight back onto the cap, first at cap_sliding_time_s. The codes then alternate
  // capped and uncapped steps, a sliding mode the stick and slip here do not model, and the outputs can be
  // off the codes' by 1e-2 or more (docs/oblique.md): the slip goes on there instead, and the accuracy
  // contract reports such an impact.
  bool slides_on_cap = false;
  double cap_sliding_time_s = 0.0;
  SolverStats stats;
};

// The stiffest tangential spring and the strongest tangential damping the solve resolves at one impact:
// CVODE's Adams method (non-stiff) needs steps of about 1/λ for a sticking contact whose tangential motion
// has the rate λ (sqrt(mobility κ) for the spring, mobility g for the damper, in the normal law's natural
// time, taken at the largest elastic overlap and the largest mobility, that of first contact).
// kFastestTangentialRate bounds the spring's λ, kFastestTangentialDampingRate the damper's; the limits are
// k_t and γ_t at those bounds, in the units of TangentialForce (infinite where the model has no such term, or
// the normal law no damping). Measured on 1 mm steel at 10°: springs solved up to λ ≈ 1100 (mindlin) and 2400
// (linear_history), chattering between stick and slip above about 3500; the damper solved at 2.7e4, its
// bound.
inline constexpr double kFastestTangentialRate = 1e3;
inline constexpr double kFastestTangentialDampingRate = 2.7e4;
struct TangentialLimits {
  double stiffness = 0.0;       // largest k_t [N/m, N/m², N/m^{3/2} as TangentialForce::stiffness]
  double damping_factor = 0.0;  // largest γ_t
};
TangentialLimits tangential_limits(const ObliqueGeometry& geometry, const NormalForce& normal,
                                   TangentialKind kind, double normal_speed_m_s);

// Solves one oblique impact. Throws InvalidInput naming a bad argument (non-positive radius, mass, inertia,
// normal speed or stiffness; negative damping or friction; a history model without stiffness; a stiffness
// or damping beyond tangential_limits),
// NumericalFailure if CVODE fails or the mode switches more than max_switches times.
ObliqueResult solve_oblique(const ObliqueGeometry& geometry, const NormalForce& normal,
                            const TangentialForce& tangential, const ImpactVelocity& impact,
                            const ObliqueOptions& options = {});

// m* = m1 m2/(m1 + m2), or m1 against a wall.
double effective_mass_kg(const ObliqueGeometry& geometry);
// R* = R1 R2/(R1 + R2), or R1 against a wall.
double effective_radius_m(const ObliqueGeometry& geometry);

}  // namespace restitution::oblique
