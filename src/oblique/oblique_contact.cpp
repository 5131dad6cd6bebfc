// SPDX-License-Identifier: BSD-3-Clause
#include "oblique/oblique_contact.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "cvode/event_driver.hpp"
#include "oblique/oblique_model.hpp"
#include "restitution/errors.hpp"

namespace restitution::oblique {
namespace {

using detail::NaturalModel;
using detail::State;
namespace driver = restitution::detail;  // the event driver (src/cvode)
using driver::Crossing;

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

// The stick/slip automaton's mode and its watch on the switch function.
struct Automaton {
  ContactMode mode = ContactMode::stick;
  double sign = 1.0;
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

  void new_phase() {
    before_previous = previous = -1.0;
    phase_largest = 0.0;
    last_sample = -HUGE_VAL;
  }
};

// The events of the contact, in this order: its end (the normal law's own end functions), the switch out
// of the mode, and for a _rescale variant only the maximal compression (x' = 0), where its rescale turns on,
// a kink in the rates that CVODE is restarted at.
enum ContactEvent { kEnd = 0, kSwitch = 1, kMaxCompression = 2 };

// A sample of the switch function: an interior minimum of its distance from 0 is a near miss.
// Only the step ends count (CVODE's root finding samples back inside the last step, around a root), and
// only a minimum far below what the phase reached before (a phase starts at a switch, where its function is
// 0).
void track_switch_distance(const NaturalModel& model, Automaton& data, double sigma, const State& s,
                           double value) {
  const double scale = model.switch_scale(s, data.mode, data.sign);
  if (!(sigma > data.last_sample) || !(scale > 0.0) || !std::isfinite(scale)) return;
  data.last_sample = sigma;
  // On the side where the mode lasts (a history slip's h below 0, the others above); across it a crossing.
  const bool lasts = data.mode == ContactMode::slip && model.has_history() ? value < 0.0 : value > 0.0;
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

State state_at(const driver::DriverPoint& p) {
  State s{};
  std::copy(p.y, p.y + detail::kStateSize, s.begin());
  return s;
}

// A switch ends a stick where its function falls through 0, a slip of a history model where h rises
// through 0, a slip of linear_nohistory where g|s| - C falls through 0.
Crossing switch_direction(const NaturalModel& model, ContactMode mode) {
  return mode == ContactMode::slip && model.has_history() ? Crossing::rising : Crossing::falling;
}

// The contact for the event driver in the smoothing of its normal law (independent variable σ with
// dτ = u^{q-1} dσ, u = x^{1/q}): for viscoelastic Hertz every right-hand side is then a polynomial in the
// state (w(x) = u, a = sqrt(R* δ) ∝ u), where in τ the start and the naive end are sqrt singularities that
// cost CVODE its order.
driver::EventSystem contact_system(const NaturalModel& model, Automaton& automaton, CollisionEnd end) {
  driver::EventSystem system;
  system.size = detail::kStateSize;
  system.rates = [&model, &automaton](const driver::DriverPoint& p, double* d) {
    State rates{};
    model.rates(state_at(p), automaton.mode, automaton.sign, rates);
    std::copy(rates.begin(), rates.end(), d);
  };
  // u changes sign at the naive end where x = u^q may not; without damping the force-zero end is the naive
  // one, where the force factor x^{a-b} = u^{q(a-b)} only touches 0.
  const bool naive = end == CollisionEnd::naive || model.law.damping() == 0.0;
  system.events.push_back({"end",
                           [&model, naive](const driver::DriverPoint& p) {
                             return naive ? p.u
                                          : law_rhs::force_factor(model.law, p.y[detail::kOverlap],
                                                                  p.y[detail::kOverlapRate]);
                           },
                           Crossing::falling, true});
  // Without friction the force is 0 in every mode (LAMMPS caps it at 0), and without a cap the contact
  // sticks throughout: nothing to switch.
  const bool switches = model.friction != 0.0 && !model.uncapped;
  system.events.push_back({"switch",
                           [&model, &automaton, switches](const driver::DriverPoint& p) {
                             if (!switches) return 1.0;
                             const State s = state_at(p);
                             const double g = model.switch_function(s, automaton.mode, automaton.sign);
                             track_switch_distance(model, automaton, p.t, s, g);
                             return g;
                           },
                           switch_direction(model, automaton.mode), false});
  // Only where it can fire: each event costs every root evaluation.
  if (model.rescales_on_unloading()) {
    system.events.push_back({"max_compression",
                             [](const driver::DriverPoint& p) { return p.y[detail::kOverlapRate]; },
                             Crossing::falling, false});
  }
  return system;
}

// Adams with the fixed-point corrector, absolute tolerances on the natural scales: the overlap and its rate
// are O(1), the tangential state is O(max(1, |s|)); the integrated state is (u, x', ξ, u_t, R1ω1, R2ω2, θ,
// τ).
driver::DriverSettings contact_settings(const NaturalModel& model, double rtol, double tangential_scale) {
  driver::DriverSettings settings;
  settings.relative_tolerance = rtol;
  settings.absolute_tolerance.assign(detail::kStateSize + 1, 1e-3 * rtol);
  for (const int i : {detail::kDisplacement, detail::kTangential, detail::kSpinFirst, detail::kSpinSecond}) {
    settings.absolute_tolerance[static_cast<std::size_t>(i)] = 1e-3 * rtol * tangential_scale;
  }
  settings.stop = kStopTime;
  settings.max_steps = kMaxSteps;
  settings.variable_name = "sigma";
  // Not for the _rescale variants: with these settings their error fell unevenly with the rtol
  // (mindlin_rescale, wall, 12.4°, 300 rad/s of backspin: 9.6e-9 off at rtol 1e-11, 2.9e-10 at 1e-12),
  // with CVODE's own 3.6e-10 and 1.4e-11.
  if (!model.rescales_on_unloading()) {
    settings.step_growth_threshold = kStepGrowthThreshold;
    settings.max_order = kAdamsMaxOrder;
  }
  return settings;
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

namespace {

// Switches in a row that left no time in their mode: LIGGGHTS's and YADE's rule (the damping added only below
// the cap, so the force jumps at a switch) can make each mode drive the contact into the other, a sliding
// mode on the cap that their codes follow by alternating capped and uncapped steps and that the two modes
// here do not represent.
constexpr int kChatterSwitches = 50;

// The stick/slip automaton: at each switch event it changes the mode (or finds the event no switch) and
// restarts the integration; it adds up the time in each mode and the switches into the result.
class StickSlip {
 public:
  StickSlip(const NaturalModel& model, Automaton& automaton, const ObliqueOptions& options,
            const TangentialForce& tangential, double time_s, ObliqueResult& result)
      : model_(model),
        automaton_(automaton),
        options_(options),
        tangential_(tangential),
        time_s_(time_s),
        result_(result) {
    result_.switches.push_back({0.0, automaton_.mode});
  }

  // The restart hook of the event driver.
  driver::AfterEvent operator()(driver::DriverStep& step, std::vector<driver::EventSpec>& events) {
    if (!step.event(kSwitch)) return restart(step, true);  // the maximal compression of a _rescale variant
    State y = state_of(step);
    // Restarted in the same mode: the function, now just below 0, rises through it, which is no event.
    if (!model_.leaving_is_consistent(y, automaton_.mode, automaton_.sign)) return restart(step, false);
    end_mode(step.tau);
    automaton_.margin = std::min(automaton_.margin, automaton_.phase_largest);
    // A switch: into slip in the direction of the trial force, or into stick from the capped force.
    if (automaton_.mode == ContactMode::stick) {
      automaton_.mode = ContactMode::slip;
      automaton_.sign = model_.cap_test_force(y) < 0.0 ? -1.0 : 1.0;
    } else {
      State stuck = y;
      if (model_.has_history()) stuck[detail::kDisplacement] = model_.displacement_at_cap(y, automaton_.sign);
      if (model_.stick_falls_back_onto_cap(stuck, automaton_.sign)) {
        // A sliding mode on the cap: the slip goes on (at the capped force, a definite outcome where
        // switching would chatter), and the result says that it is not the code's.
        if (!result_.slides_on_cap) result_.cap_sliding_time_s = step.tau * time_s_;
        result_.slides_on_cap = true;
        return restart(step, false);
      }
      automaton_.mode = ContactMode::stick;
      std::copy(stuck.begin(), stuck.end(), step.y.begin());
    }
    events[kSwitch].direction = switch_direction(model_, automaton_.mode);
    result_.switches.push_back({step.tau * time_s_, automaton_.mode});
    return restart(step, false);
  }

  // The time in the mode that ends at τ (a switch or the end of the contact).
  void end_mode(double tau) {
    instant_switches_ = tau - mode_start_ < 1e-9 ? instant_switches_ + 1 : 0;
    (automaton_.mode == ContactMode::stick ? result_.stick_time_s : result_.slip_time_s) +=
        (tau - mode_start_) * time_s_;
    mode_start_ = tau;
  }

 private:
  static State state_of(const driver::DriverStep& step) {
    State y{};
    std::copy(step.y.begin(), step.y.end(), y.begin());
    return y;
  }

  // Every restart counts against max_switches; a phase that goes on keeps its watch on the switch function.
  driver::AfterEvent restart(const driver::DriverStep& step, bool phase_goes_on) {
    ++restarts_;
    if (instant_switches_ > kChatterSwitches && model_.caps_elastic_force()) {
      throw NumericalFailure(fmt::format(
          "the contact chatters between stick and slip at t = {:.6g} s: with {}'s damping added below the "
          "cap "
          "only, each mode drives it into the other there (the code alternates capped and uncapped steps), "
          "a limit not modelled yet; less tangential damping avoids it",
          step.tau * time_s_, tangential_model(tangential_.kind).code_title));
    }
    if (restarts_ > options_.max_switches) {
      throw NumericalFailure(fmt::format("the contact crossed the stick/slip boundary more than {} times",
                                         options_.max_switches));
    }
    if (!phase_goes_on) automaton_.new_phase();
    return driver::AfterEvent::restart;
  }

  const NaturalModel& model_;
  Automaton& automaton_;
  const ObliqueOptions& options_;
  const TangentialForce& tangential_;
  double time_s_;
  ObliqueResult& result_;
  double mode_start_ = 0.0;
  int restarts_ = 0;
  int instant_switches_ = 0;
};

// The state at first contact in natural units: τ0 on the leading terms, the history of the model.
State first_contact(const ObliqueGeometry& geometry, const ImpactVelocity& impact,
                    const NaturalModel& model) {
  const double speed = impact.normal_m_s;
  State y{};
  y[detail::kOverlap] = kStartTime;
  y[detail::kOverlapRate] = 1.0;
  y[detail::kTangential] = impact.tangential_m_s / speed;
  y[detail::kSpinFirst] = geometry.first.radius_m * impact.spin_first_rad_s / speed;
  y[detail::kSpinSecond] =
      geometry.second ? geometry.second->radius_m * impact.spin_second_rad_s / speed : 0.0;
  y[detail::kDisplacement] = model.initial_history(y, NaturalModel::slip_velocity(y));
  return y;
}

// The result from the state at the end of the contact.
void write_outcome(const ObliqueGeometry& geometry, const ImpactVelocity& impact, const State& y,
                   double slip0, ObliqueResult& result) {
  const double speed = impact.normal_m_s;
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
}

}  // namespace

ObliqueResult solve_oblique(const ObliqueGeometry& geometry, const NormalForce& normal,
                            const TangentialForce& tangential, const ImpactVelocity& impact,
                            const ObliqueOptions& options) {
  validate(geometry, normal, tangential, impact, options);
  const double speed = impact.normal_m_s;
  const NaturalModel model =
      natural_model(geometry, normal, tangential, speed, options.end, options.sticking_limit);
  const double time_s =
      physical_time_scale_s(normal.kind, normal.stiffness, effective_mass_kg(geometry), speed);

  State y = first_contact(geometry, impact, model);
  const double slip0 = NaturalModel::slip_velocity(y);
  Automaton automaton;
  initial_mode(model, y, automaton.mode, automaton.sign);
  const double tangential_scale = std::max({1.0, std::abs(slip0), std::abs(y[detail::kTangential])});

  driver::EventDriver driver(contact_system(model, automaton, options.end),
                             contact_settings(model, options.relative_tolerance, tangential_scale),
                             driver::Smoothing{&model.law});
  ObliqueResult result;
  StickSlip stick_slip(model, automaton, options, tangential, time_s, result);
  driver.start(kStartTime, y.data());
  const driver::DriverStep end =
      driver.run([&](driver::DriverStep& step) { return stick_slip(step, driver.events()); });
  if (end.reached_stop)
    throw NumericalFailure(fmt::format("the contact did not end before sigma={}", kStopTime));
  stick_slip.end_mode(end.tau);
  result.stats = driver.stats();
  std::copy(end.y.begin(), end.y.end(), y.begin());
  write_outcome(geometry, impact, y, slip0, result);
  result.contact_time_s = end.tau * time_s;
  result.closest_switch_approach = automaton.closest;
  result.switch_margin = automaton.margin;
  return result;
}

}  // namespace restitution::oblique
