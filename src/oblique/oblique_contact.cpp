// SPDX-License-Identifier: BSD-3-Clause
#include "oblique/oblique_contact.hpp"

#include <cvode/cvode.h>
#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "oblique/oblique_model.hpp"
#include "restitution/errors.hpp"
#include "sundials/fixed_point.hpp"
#include "sundials/handles.hpp"
#include "sundials/small_vector.hpp"

namespace restitution::oblique {
namespace {

using detail::NaturalModel;
using detail::State;

// The integration starts at τ0 > 0 on the leading terms x = τ0, x' = 1 (their error, O(τ0^{b+2}), is far
// below any tolerance): at x = 0 the switch function of a damped Hertz contact is infinite (w'(0) = ∞).
constexpr double kStartTime = 1e-10;
// Far beyond any end the family reaches (natural contact times are O(1); overdamped naive tails O(ζ)).
constexpr double kStopTime = 1e8;
constexpr long kMaxSteps = 1000000;
// CVODE keeps its step unless it may grow by this factor (its default 1.5), and Adams stops at order 9 (its
// default 12), as the head-on Sundman phase does (src/cvode/cvode_integrator.cpp): the 45° impact of
// bench/bench_oblique.cpp takes 243 instead of 380 steps at rtol 1e-11; 1.2 and 1.5 cost more at 20° or 45°.
constexpr double kStepGrowthThreshold = 1.05;
constexpr int kAdamsMaxOrder = 9;

void require_positive(double value, const char* name) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw InvalidInput(fmt::format("{} must be a positive finite number, got {}", name, value));
  }
}
void require_nonnegative(double value, const char* name) {
  if (!(value >= 0.0) || !std::isfinite(value)) {
    throw InvalidInput(fmt::format("{} must be a non-negative finite number, got {}", name, value));
  }
}
void require_finite(double value, const char* name) {
  if (!std::isfinite(value)) throw InvalidInput(fmt::format("{} must be finite, got {}", name, value));
}
void require_body(const Body& body, const char* which) {
  require_positive(body.radius_m, fmt::format("{} radius [m]", which).c_str());
  require_positive(body.mass_kg, fmt::format("{} mass [kg]", which).c_str());
  require_positive(body.inertia_kg_m2, fmt::format("{} moment of inertia [kg m^2]", which).c_str());
}

struct CallbackData {
  const NaturalModel* model = nullptr;
  ContactMode mode = ContactMode::stick;
  double sign = 1.0;
  CollisionEnd end = CollisionEnd::delayed_recovery;
  // The switch function's distance from 0 over its scale at the last two step ends of this phase (-1: none
  // yet), the largest so far in the phase and when it was last sampled, and the smallest interior minimum of
  // it over the contact: where it comes back close to 0 without crossing, a switch nearly happened.
  double before_previous = -1.0;
  double previous = -1.0;
  double phase_largest = 0.0;
  double last_sample = -HUGE_VAL;
  double closest = 1.0;
  // The smallest distance from 0 of the switch function at any interior minimum of its step-end samples, and
  // the smallest largest distance of a phase that ended in a switch: the margin of the mode sequence.
  double margin = 1.0;
};

// CVODE integrates the Sundman form of the engines (src/cvode/cvode_integrator.hpp): independent variable σ
// with dτ = u^{q-1} dσ, u = x^{1/q} (ContactLaw::smoothing_root), state (u, x', ξ, u_t, R1ω1, R2ω2, τ). For
// viscoelastic Hertz every right-hand side is then a polynomial in the state (w(x) = u, a = sqrt(R* δ) ∝ u),
// where in τ the start and the naive end are sqrt singularities that cost CVODE its order.
constexpr int kCvodeSize = detail::kStateSize + 1;
constexpr int kTau = detail::kStateSize;
constexpr int kRootCount = 3;

// The state in τ form (index 0 the overlap x) from the integrated one (index 0 u).
State read(const ContactLaw& law, N_Vector y) {
  State s{};
  const double* d = N_VGetArrayPointer(y);
  std::copy(d, d + detail::kStateSize, s.begin());
  s[detail::kOverlap] = law.compression_of(d[0]);
  return s;
}

int right_hand_side(sunrealtype /*t*/, N_Vector y, N_Vector ydot, void* user_data) noexcept {
  const auto& data = *static_cast<CallbackData*>(user_data);
  const ContactLaw& law = data.model->law;
  State rates{};
  data.model->rates(read(law, y), data.mode, data.sign, rates);
  const double u = N_VGetArrayPointer(y)[0];
  const double dtau = law.dcompression_du(u) / law.smoothing_root();  // u^{q-1}
  double* d = N_VGetArrayPointer(ydot);
  d[0] = rates[detail::kOverlap] / law.smoothing_root();  // du/dσ = x'/q
  for (int i = 1; i < detail::kStateSize; ++i) d[i] = rates[static_cast<std::size_t>(i)] * dtau;
  d[kTau] = dtau;
  return 0;
}

// g[0]: the end of the contact (the normal law's own end functions); g[1]: the switch out of the mode;
// g[2], for a _rescale variant only: the maximal compression (x' = 0), where its rescale turns on, a kink in
// the rates that CVODE is restarted at.
// A sample of the switch function: an interior minimum of its distance from 0 is a near miss.
// Only the step ends count (CVODE's root finding samples back inside the last step, around a root), and
// only a minimum far below what the phase reached before (a phase starts at a switch, where its function is
// 0).
void track_switch_distance(CallbackData& data, double sigma, const State& s, double value) {
  const double scale = data.model->switch_scale(s, data.mode, data.sign);
  if (!(sigma > data.last_sample) || !(scale > 0.0) || !std::isfinite(scale)) return;
  data.last_sample = sigma;
  // On the side where the mode lasts (a history slip's h below 0, the others above); across it a crossing.
  const bool lasts = data.mode == ContactMode::slip && data.model->has_history() ? value < 0.0 : value > 0.0;
  if (!lasts) {
    data.before_previous = data.previous = -1.0;
    return;
  }
  const double distance = std::abs(value) / scale;
  if (data.before_previous > data.previous && data.previous >= 0.0 && distance > data.previous) {
    data.margin = std::min(data.margin, data.previous);
    if (data.phase_largest > 1e-2 && data.previous < 1e-2 * data.phase_largest) {
      data.closest = std::min(data.closest, data.previous);
    }
  }
  data.phase_largest = std::max(data.phase_largest, distance);
  data.before_previous = data.previous;
  data.previous = distance;
}

int root_functions(sunrealtype sigma, N_Vector y, sunrealtype* g, void* user_data) noexcept {
  auto& data = *static_cast<CallbackData*>(user_data);
  const State s = read(data.model->law, y);
  // u changes sign at the naive end where x = u^q may not; without damping the force-zero end is the naive
  // one, where the force factor x^{a-b} = u^{q(a-b)} only touches 0.
  g[0] = data.end == CollisionEnd::naive || data.model->law.damping() == 0.0
             ? N_VGetArrayPointer(y)[0]
             : law_rhs::force_factor(data.model->law, s[detail::kOverlap], s[detail::kOverlapRate]);
  // Without friction the force is 0 in every mode (LAMMPS caps it at 0), and without a cap the contact
  // sticks throughout: nothing to switch.
  const bool switches = data.model->friction != 0.0 && !data.model->uncapped;
  g[1] = switches ? data.model->switch_function(s, data.mode, data.sign) : 1.0;
  if (switches) track_switch_distance(data, sigma, s, g[1]);
  if (data.model->rescales_on_unloading()) g[2] = s[detail::kOverlapRate];  // registered only then
  return 0;
}

NaturalModel natural_model(const ObliqueGeometry& geometry, const NormalForce& normal,
                           const TangentialForce& tangential, double impact_speed_m_s, CollisionEnd end,
                           bool uncapped) {
  const double mass = effective_mass_kg(geometry);
  const double time_s = physical_time_scale_s(normal.kind, normal.stiffness, mass, impact_speed_m_s);
  const double length_m = impact_speed_m_s * time_s;
  NaturalModel model;
  model.law = ContactLaw::physical(normal.kind, normal.stiffness, normal.damping, mass, impact_speed_m_s);
  const TangentialModel& row = tangential_model(tangential.kind);
  model.rule = row.rule;
  model.friction = tangential.friction;
  model.uncapped = uncapped;
  model.damping_factor = tangential.damping_factor;
  // F_t = k_t ξ: in units of m* v/T per v T of displacement, κ = k_t T²/m*; k_t sqrt(R* δ) (the mindlin
  // family, LIGGGHTS) adds sqrt(R* v T) to κ_m, YADE's ks = kso sqrt(δ) sqrt(v T).
  model.stiffness = tangential.stiffness * time_s * time_s / mass;
  if (row.rule.growth == StiffnessGrowth::contact_radius) {
    model.stiffness *= std::sqrt(effective_radius_m(geometry) * length_m);
  } else if (row.rule.growth == StiffnessGrowth::overlap) {
    model.stiffness *= std::sqrt(length_m);
  }
  if (row.rule.incident_velocity_gain) {
    // The wall's radius is the sphere's (Ig2_Wall_Sphere_ScGeom's refR1).
    const double radii =
        geometry.first.radius_m + (geometry.second ? geometry.second->radius_m : geometry.first.radius_m);
    model.velocity_gain_distance = radii / length_m;
  }
  // The arm R - f δ: f = 0, 1/2 or 1.
  const auto overlap_fraction = [](TorqueArm arm) {
    return arm == TorqueArm::radius ? 0.0 : arm == TorqueArm::radius_minus_half_overlap ? 0.5 : 1.0;
  };
  const double torque_fraction = overlap_fraction(geometry.torque_arm);
  const double contact_fraction = overlap_fraction(geometry.contact_point_arm);
  const auto rotation = [&](const Body& body, std::size_t i) {
    model.rotation_base[i] = mass * body.radius_m * body.radius_m / body.inertia_kg_m2;
    model.rotation_slope[i] = mass * body.radius_m * torque_fraction * length_m / body.inertia_kg_m2;
    model.contact_arm_slope[i] = contact_fraction * length_m / body.radius_m;
  };
  rotation(geometry.first, 0);
  if (geometry.second) rotation(*geometry.second, 1);
  model.cap_of_signed_force = end == CollisionEnd::delayed_recovery;
  if (geometry.second && !geometry.fixed_normal) {
    model.centre_distance = (geometry.first.radius_m + geometry.second->radius_m) / length_m;
  }
  return model;
}

// The largest elastic overlap in natural units, (a+1)/2 to the 1/(a+1) (the energy 1/2 all stored): no
// damped contact compresses further.
double largest_overlap(LawKind kind) {
  const double a = law_exponents(kind).elastic;
  return std::pow(0.5 * (a + 1.0), 1.0 / (a + 1.0));
}

void validate(const ObliqueGeometry& geometry, const NormalForce& normal, const TangentialForce& tangential,
              const ImpactVelocity& impact, const ObliqueOptions& options) {
  require_body(geometry.first, "first sphere's");
  if (geometry.second) require_body(*geometry.second, "second sphere's");
  require_positive(normal.stiffness, "normal stiffness");
  require_nonnegative(normal.damping, "normal damping coefficient");
  if (!options.sticking_limit) require_nonnegative(tangential.friction, "friction coefficient");
  require_nonnegative(tangential.damping_factor, "tangential damping factor");
  // Without friction the tangential force is 0 whatever the stiffness (the cap is 0), except in the sticking
  // limit, which has no cap.
  if (tangential_model(tangential.kind).has_stiffness() &&
      (tangential.friction != 0.0 || options.sticking_limit)) {
    require_positive(tangential.stiffness,
                     fmt::format("{} tangential stiffness", tangential_name(tangential.kind)).c_str());
  }
  require_positive(impact.normal_m_s, "normal impact speed [m/s]");
  require_finite(impact.tangential_m_s, "tangential impact velocity [m/s]");
  require_finite(impact.spin_first_rad_s, "first sphere's spin [rad/s]");
  require_finite(impact.spin_second_rad_s, "second sphere's spin [rad/s]");
  if (!geometry.second && impact.spin_second_rad_s != 0.0) {
    throw InvalidInput("a wall does not spin: the second spin must be 0 against a wall");
  }
  if (!(options.relative_tolerance >= 1e-14 && options.relative_tolerance <= 1e-2)) {
    throw InvalidInput(
        fmt::format("relative tolerance must be in [1e-14, 1e-2], got {}", options.relative_tolerance));
  }
  if (options.max_switches < 1) throw InvalidInput("max_switches must be at least 1");
  // Without friction (and a cap) the tangential force is 0: nothing to resolve.
  if (tangential.friction == 0.0 && !options.sticking_limit) return;
  const TangentialLimits limits = tangential_limits(geometry, normal, tangential.kind, impact.normal_m_s);
  if (tangential.stiffness > limits.stiffness) {
    throw InvalidInput(fmt::format(
        "{} tangential stiffness {} exceeds {:.3g}, the stiffest spring the solve resolves at this impact "
        "(its "
        "sticking period would be shorter than 2 pi/{:g} of the normal law's natural time)",
        tangential_name(tangential.kind), tangential.stiffness, limits.stiffness, kFastestTangentialRate));
  }
  if (tangential.damping_factor > limits.damping_factor) {
    throw InvalidInput(
        fmt::format("tangential damping factor {} exceeds {:.3g}, the strongest damping the solve resolves "
                    "at this impact "
                    "(its decay time would be shorter than 1/{:g} of the normal law's natural time)",
                    tangential.damping_factor, limits.damping_factor, kFastestTangentialDampingRate));
  }
}

// The mode at first contact: the trial force of a stick at τ0 against the cap there (the leading terms of
// both as τ -> 0 decide: a damped contact sticks where γ_t |s| <= μ, an undamped Hertz contact slides
// whenever s != 0, its cap growing as τ^{3/2} against the spring's τ).
void initial_mode(const NaturalModel& model, State& y, ContactMode& mode, double& sign) {
  const double trial = model.cap_test_force(y);
  if (model.uncapped) {
    mode = ContactMode::stick;
    return;
  }
  mode = std::abs(trial) <= model.cap(y[detail::kOverlap], y[detail::kOverlapRate]) ? ContactMode::stick
                                                                                    : ContactMode::slip;
  sign = trial < 0.0 ? -1.0 : 1.0;
  if (mode == ContactMode::slip && model.has_history()) {
    y[detail::kDisplacement] = 0.0;
    // A history slip lasts while h < 0 and ends where h rises through 0: one that starts with h > 0 would
    // never end (the capped force would drive s through 0 and beyond). LAMMPS's next step sticks there, and
    // the contact stays stuck where the trial force, from the cap, then falls below it (a first-order step
    // of the stick tells). Where it does not, LAMMPS alternates stick and slip every step, a force at the cap
    // as dt -> 0: the slip stays.
    if (model.switch_function(y, ContactMode::slip, sign) > 0.0) {
      State stuck = y;
      stuck[detail::kDisplacement] = model.displacement_at_cap(y, sign);
      State rates{};
      model.rates(stuck, ContactMode::stick, sign, rates);
      State ahead = stuck;
      const double step = 1e-3 * y[detail::kOverlap];
      for (std::size_t i = 0; i < ahead.size(); ++i) ahead[i] += step * rates[i];
      if (model.switch_function(ahead, ContactMode::stick, sign) >=
          model.switch_function(stuck, ContactMode::stick, sign)) {
        mode = ContactMode::stick;
        y = stuck;
      }
    }
  }
}

}  // namespace

TangentialLimits tangential_limits(const ObliqueGeometry& geometry, const NormalForce& normal,
                                   TangentialKind kind, double normal_speed_m_s) {
  // The model of a unit k_t and γ_t: its κ and g are then the natural values per unit of each.
  const NaturalModel unit =
      natural_model(geometry, normal, {kind, 1.0, 1.0, 0.0}, normal_speed_m_s, CollisionEnd::naive, false);
  const double x = largest_overlap(normal.kind);
  const double mobility = unit.mobility(0.0);
  const double rate2 = kFastestTangentialRate * kFastestTangentialRate;
  TangentialLimits limits{HUGE_VAL, HUGE_VAL};
  if (tangential_model(kind).has_stiffness()) {
    // λ² = mobility κ for a spring force −κξ (the force histories: H' = −κ s, the same rate).
    limits.stiffness = rate2 / (mobility * unit.tangential_stiffness(x));
  }
  if (const double g = unit.tangential_damping(x); g > 0.0)
    limits.damping_factor = kFastestTangentialDampingRate / (mobility * g);
  return limits;
}

const char* mode_name(ContactMode mode) {
  return mode == ContactMode::stick ? "stick" : "slip";
}

Body solid_sphere(double radius_m, double mass_kg) {
  return {radius_m, mass_kg, 0.4 * mass_kg * radius_m * radius_m};
}

double effective_mass_kg(const ObliqueGeometry& geometry) {
  if (!geometry.second) return geometry.first.mass_kg;
  const double m1 = geometry.first.mass_kg;
  const double m2 = geometry.second->mass_kg;
  return m1 * m2 / (m1 + m2);
}

double effective_radius_m(const ObliqueGeometry& geometry) {
  if (!geometry.second) return geometry.first.radius_m;
  const double r1 = geometry.first.radius_m;
  const double r2 = geometry.second->radius_m;
  return r1 * r2 / (r1 + r2);
}

ObliqueResult solve_oblique(const ObliqueGeometry& geometry, const NormalForce& normal,
                            const TangentialForce& tangential, const ImpactVelocity& impact,
                            const ObliqueOptions& options) {
  validate(geometry, normal, tangential, impact, options);
  const double speed = impact.normal_m_s;
  const NaturalModel model =
      natural_model(geometry, normal, tangential, speed, options.end, options.sticking_limit);
  const double time_s =
      physical_time_scale_s(normal.kind, normal.stiffness, effective_mass_kg(geometry), speed);

  State y{};
  y[detail::kOverlap] = kStartTime;
  y[detail::kOverlapRate] = 1.0;
  y[detail::kTangential] = impact.tangential_m_s / speed;
  y[detail::kSpinFirst] = geometry.first.radius_m * impact.spin_first_rad_s / speed;
  y[detail::kSpinSecond] =
      geometry.second ? geometry.second->radius_m * impact.spin_second_rad_s / speed : 0.0;
  const double slip0 = NaturalModel::slip_velocity(y);
  y[detail::kDisplacement] = model.initial_history(y, slip0);
  CallbackData data{&model, ContactMode::stick, 1.0, options.end};
  initial_mode(model, y, data.mode, data.sign);

  // Absolute tolerances on the natural scales: the overlap and its rate are O(1), the tangential state is
  // O(max(1, |s|)).
  const double tangential_scale = std::max({1.0, std::abs(slip0), std::abs(y[detail::kTangential])});
  const double rtol = options.relative_tolerance;
  sundials::Context context;
  sundials::Vector state = sundials::make_small_vector(kCvodeSize, context);
  sundials::Vector atol = sundials::make_small_vector(kCvodeSize, context);
  double* a = N_VGetArrayPointer(atol.get());
  a[detail::kOverlap] = a[detail::kOverlapRate] = a[kTau] = 1e-3 * rtol;
  for (const int i : {detail::kDisplacement, detail::kTangential, detail::kSpinFirst, detail::kSpinSecond}) {
    a[i] = 1e-3 * rtol * tangential_scale;
  }
  a[detail::kTurn] = 1e-3 * rtol;
  sundials::NonlinearSolver corrector = sundials::make_small_fixed_point_solver(state, context);
  sundials::CvodeMemory memory(CV_ADAMS, context);
  void* mem = memory.get();

  ObliqueResult result;
  result.switches.push_back({0.0, data.mode});
  double* raw = N_VGetArrayPointer(state.get());
  double sigma = 0.0;  // CVODE's independent variable
  double t = kStartTime;
  double mode_start = 0.0;
  bool initialized = false;
  bool phase_goes_on = false;  // a restart within a phase (the maximal compression), not a switch
  // Switches in a row that left no time in their mode: LIGGGHTS's and YADE's rule (the damping added only
  // below the cap, so the force jumps at a switch) can make each mode drive the contact into the other, a
  // sliding mode on the cap that their codes follow by alternating capped and uncapped steps and that the
  // two modes here do not represent.
  constexpr int kChatterSwitches = 50;
  int instant_switches = 0;
  for (int switches = 0;; ++switches) {
    if (instant_switches > kChatterSwitches && model.caps_elastic_force()) {
      throw NumericalFailure(fmt::format(
          "the contact chatters between stick and slip at t = {:.6g} s: with {}'s damping added below the "
          "cap "
          "only, each mode drives it into the other there (the code alternates capped and uncapped steps), "
          "a limit not modelled yet; less tangential damping avoids it",
          t * time_s, tangential_model(tangential.kind).code_title));
    }
    if (switches > options.max_switches) {
      throw NumericalFailure(fmt::format("the contact crossed the stick/slip boundary more than {} times",
                                         options.max_switches));
    }
    // The τ-form state back into CVODE's (only ξ changes at a switch; u stays as integrated).
    std::copy(y.begin() + 1, y.end(), raw + 1);
    if (!initialized) {
      raw[0] = model.law.smooth_variable(y[detail::kOverlap]);
      raw[kTau] = t;
      sundials::check_flag(CVodeInit(mem, right_hand_side, sigma, state.get()), "CVodeInit");
      sundials::check_flag(CVodeSetUserData(mem, &data), "CVodeSetUserData");
      sundials::check_flag(CVodeSetNonlinearSolver(mem, corrector.get()), "CVodeSetNonlinearSolver");
      sundials::check_flag(CVodeSVtolerances(mem, rtol, atol.get()), "CVodeSVtolerances");
      sundials::check_flag(CVodeSetMaxNumSteps(mem, kMaxSteps), "CVodeSetMaxNumSteps");
      sundials::check_flag(CVodeSetStopTime(mem, kStopTime), "CVodeSetStopTime");
      // The third function only where it can fire: each one costs every root evaluation.
      sundials::check_flag(
          CVodeRootInit(mem, model.rescales_on_unloading() ? kRootCount : kRootCount - 1, root_functions),
          "CVodeRootInit");
      // Not for the _rescale variants: with these settings their error fell unevenly with the rtol
      // (mindlin_rescale, wall, 12.4°, 300 rad/s of backspin: 9.6e-9 off at rtol 1e-11, 2.9e-10 at 1e-12),
      // with CVODE's own 3.6e-10 and 1.4e-11.
      if (!model.rescales_on_unloading()) {
        sundials::check_flag(CVodeSetEtaFixedStepBounds(mem, 0.0, kStepGrowthThreshold),
                             "CVodeSetEtaFixedStepBounds");
        sundials::check_flag(CVodeSetMaxOrd(mem, kAdamsMaxOrder), "CVodeSetMaxOrd");
      }
      initialized = true;
    } else {
      sundials::check_flag(CVodeReInit(mem, sigma, state.get()), "CVodeReInit");
    }
    // The end is a downward crossing; a stick ends where its function falls through 0, a slip of a history
    // model where h rises through 0, a slip of linear_nohistory where g|s| - C falls through 0.
    if (!phase_goes_on) {
      data.before_previous = data.previous = -1.0;  // a new phase
      data.phase_largest = 0.0;
      data.last_sample = -HUGE_VAL;
    }
    phase_goes_on = false;
    std::array<int, kRootCount> directions{-1, data.mode == ContactMode::slip && model.has_history() ? 1 : -1,
                                           -1};
    sundials::check_flag(CVodeSetRootDirection(mem, directions.data()), "CVodeSetRootDirection");

    const int flag = CVode(mem, kStopTime, state.get(), &sigma, CV_NORMAL);
    t = raw[kTau];
    if (flag < 0) {
      throw NumericalFailure(fmt::format("CVODE failed at tau={} with flag {} ({})", t, flag,
                                         memory.last_error().empty() ? "no message" : memory.last_error()));
    }
    if (flag != CV_ROOT_RETURN) {
      throw NumericalFailure(fmt::format("the contact did not end before sigma={}", kStopTime));
    }
    y = read(model.law, state.get());
    std::array<int, kRootCount> found{};
    sundials::check_flag(CVodeGetRootInfo(mem, found.data()), "CVodeGetRootInfo");
    if (found[0] == 0 && found[1] == 0) {
      // The maximal compression of a _rescale variant: CVODE restarts there, in the same phase.
      result.stats += sundials::cvode_phase_stats(mem);
      phase_goes_on = true;
      continue;
    }
    if (found[0] == 0 && !model.leaving_is_consistent(y, data.mode, data.sign)) {
      // Restarted in the same mode: the function, now just below 0, rises through it, which is no event.
      result.stats += sundials::cvode_phase_stats(mem);
      continue;
    }
    result.stats += sundials::cvode_phase_stats(mem);
    const double elapsed_s = (t - mode_start) * time_s;
    instant_switches = t - mode_start < 1e-9 ? instant_switches + 1 : 0;
    (data.mode == ContactMode::stick ? result.stick_time_s : result.slip_time_s) += elapsed_s;
    mode_start = t;
    if (found[0] != 0) break;
    data.margin = std::min(data.margin, data.phase_largest);

    // A switch: into slip in the direction of the trial force, or into stick from the capped force.
    if (data.mode == ContactMode::stick) {
      data.mode = ContactMode::slip;
      data.sign = model.cap_test_force(y) < 0.0 ? -1.0 : 1.0;
    } else {
      State stuck = y;
      if (model.has_history()) stuck[detail::kDisplacement] = model.displacement_at_cap(y, data.sign);
      if (model.stick_falls_back_onto_cap(stuck, data.sign)) {
        // A sliding mode on the cap: the slip goes on (at the capped force, a definite outcome where
        // switching would chatter), and the result says that it is not the code's.
        if (!result.slides_on_cap) result.cap_sliding_time_s = t * time_s;
        result.slides_on_cap = true;
        continue;
      }
      data.mode = ContactMode::stick;
      y = stuck;
    }
    result.switches.push_back({t * time_s, data.mode});
  }

  // Back in the frame of the impact (normal n0, tangent t0): the line of centres has turned by θ, so the
  // relative velocity -δ' n + u t has components -δ' cos θ - u sin θ along n0 and u cos θ - δ' sin θ along
  // t0.
  const double turn = y[detail::kTurn];
  const double separation =
      -y[detail::kOverlapRate] * std::cos(turn) - y[detail::kTangential] * std::sin(turn);
  const double tangential_after =
      y[detail::kTangential] * std::cos(turn) - y[detail::kOverlapRate] * std::sin(turn);
  result.line_of_centres_turn_rad = turn;
  result.normal_restitution = separation;
  result.normal_velocity_m_s = separation * speed;
  result.tangential_velocity_m_s = tangential_after * speed;
  result.spin_first_rad_s = y[detail::kSpinFirst] * speed / geometry.first.radius_m;
  result.spin_second_rad_s =
      geometry.second ? y[detail::kSpinSecond] * speed / geometry.second->radius_m : 0.0;
  const double slip = tangential_after + y[detail::kSpinFirst] + y[detail::kSpinSecond];
  result.slip_velocity_m_s = slip * speed;
  result.tangential_restitution = slip0 != 0.0 ? -slip / slip0 : std::nan("");
  result.impact_angle_rad = std::atan2(impact.tangential_m_s, speed);
  result.rebound_angle_rad = std::atan2(result.tangential_velocity_m_s, result.normal_velocity_m_s);
  result.impulse_ratio = (tangential_after - impact.tangential_m_s / speed) / (1.0 + separation);
  result.contact_time_s = t * time_s;
  result.closest_switch_approach = data.closest;
  result.switch_margin = data.margin;
  return result;
}

}  // namespace restitution::oblique
