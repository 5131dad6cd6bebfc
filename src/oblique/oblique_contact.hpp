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
// Beside this header: the Python module reaches both through restitution_oblique/, without src/ on its path.
#include "tangential_models.hpp"

namespace restitution::oblique {

struct Body {
  double radius_m = 0.0;
  double mass_kg = 0.0;
  double inertia_kg_m2 = 0.0;  // about a diameter
};
// A homogeneous solid sphere: I = 2/5 m R².
Body solid_sphere(double radius_m, double mass_kg);

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
