// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// One CVODE integrator (BDF or Adams) for the equation of motion of a ContactLaw, with the dissipated
// energy integrated alongside. Reused across solves and across the phases of a solve (CVodeReInit).
// Private to the library.
//
// Two forms of the same system, chosen per phase of the collision:
//  * time form, independent variable τ, state (x, x', I);
//  * compression form, independent variable u = x^{1/q} (ContactLaw::smoothing_root; q = 2 for Hertz
//    spheres), state (τ, x', I), valid while x' != 0:
//        dτ/du = q u^{q-1}/x',  dx'/du = q u^{q-1}·a(u^q, x')/x',  dI/du = q u^{q-1}·w(u^q)·x'
//    This is analytic in u, where the time form has τ^{b+2}-type singularities at x = 0 that cost CVODE its
//    order (docs/design.md §4).
//    For the overdamped tail of the naive end the compression form may carry σ = τ + c·ln(u + u*) instead
//    of τ (TauLog): there τ ≈ -c ln(u + u*) with c = qζ and u* the u at which inertia takes over from the
//    slow decay x' ≈ -x^{a-b}/ζ (a - b = 1), a logarithm that costs BDF a step per fraction of u, while σ
//    stays smooth (docs/performance.md).
//  * Sundman form, independent variable s with dτ = u^{q-1} ds, state (u, x', I, τ), valid throughout:
//        du/ds = x'/q,  dx'/ds = u^{q-1}·a(u^q, x'),  dI/ds = u^{q-1}·w(u^q)·x'^2,  dτ/ds = u^{q-1}
//    polynomial for viscoelastic Hertz, with no singularity at x = 0 or at x' = 0: one phase from the
//    impact to the delayed-recovery end, so CVODE ramps its order up once instead of three times
//    (docs/performance.md, sixth round).
// I = ∫ w(x) x'^2 dτ is the dissipation integral (the dissipated energy is D = c_d · I).
#include <array>
#include <cmath>
#include <string>

#include "restitution/contact_law.hpp"
#include "restitution/solve_types.hpp"
#include "sundials/handles.hpp"
#include "sundials/small_vector.hpp"

namespace restitution::detail {

// The largest state (the Sundman form's); the time and compression forms use the first three entries.
inline constexpr int kStateSize = 4;
using State = std::array<double, kStateSize>;
// Index of x' and I in every form; index 0 is x in the time form, τ in the compression form and u in the
// Sundman form, which carries τ last.
enum StateIndex { kFirst = 0, kVelocity = 1, kDissipation = 2, kSundmanTau = 3 };

enum class Form { time, compression, sundman };
[[nodiscard]] constexpr int state_size(Form form) {
  return form == Form::sundman ? 4 : 3;
}

// The events a phase can watch.
enum class Event {
  max_compression,       // x' = 0
  naive_end,             // x = 0 (time form) or u = 0 (Sundman form)
  delayed_recovery_end,  // c_d x' + c_s x = 0
  velocity_halved,       // x' = x'(0)/2: leave the compression form of the start
  below_switch,          // x = switch_x while decompressing: enter the compression form of the end
  naive_end_excluded,    // the state enters a region from which x never returns to 0 (ContactLaw)
};
inline constexpr int kMaxEvents = 4;

// The logarithm taken out of τ in the compression form: σ = τ + coefficient·ln(u + shift).
struct TauLog {
  double shift = 0.0;        // u*
  double coefficient = 0.0;  // c; 0: the state holds τ itself
  [[nodiscard]] double offset(double u) const {
    return coefficient == 0.0 ? 0.0 : coefficient * std::log(u + shift);
  }
};

struct PhaseSettings {
  Form form = Form::time;
  double relative_tolerance = 0.0;  // the tolerance plan's (tolerance_policy.hpp)
  State absolute_tolerance{};
  double stop = 1e6;  // the independent variable's last value: time limit, or u at the phase's end
  long max_steps = 1000000;
  double switch_x = 0.0;  // for Event::below_switch
  TauLog tau_log{};       // compression form only
  // Return after every internal step (to record a trajectory); otherwise only at events and the stop,
  // which saves CVODE's per-call overhead (~12 % of a solve).
  bool every_step = false;
};

class CvodeIntegrator {
 public:
  // For the phases of `form`'s state size (state_size): 3 (time and compression forms) or 4 (Sundman).
  CvodeIntegrator(Method method, const sundials::Context& context, int size = 3);

  // Starts a phase at independent variable t0 with the given state, watching the given events.
  void start(const ContactLaw& law, const PhaseSettings& settings, double t0, const State& state,
             const Event* events, int event_count);

  struct Step {
    double t = 0.0;  // τ (time form) or u (compression form)
    State state{};
    std::array<bool, kMaxEvents> events_found{};  // indexed like the events passed to start()
    bool reached_stop = false;
  };
  // Advances one internal step (PhaseSettings::every_step) or up to the next event or the stop. Throws
  // NumericalFailure on a CVODE error or once the phase has taken max_steps steps.
  Step advance();
  // Stops watching an event that has been handled (its function becomes a positive constant).
  void ignore_event(int index) { data_.ignored[static_cast<std::size_t>(index)] = true; }

  // Statistics of the phase so far (CVodeReInit resets them: callers add up phases).
  [[nodiscard]] SolverStats phase_stats() const;

  struct CallbackData {
    const ContactLaw* law = nullptr;
    Form form = Form::time;
    double switch_x = 0.0;
    TauLog tau_log{};
    std::array<Event, kMaxEvents> events{};
    std::array<bool, kMaxEvents> ignored{};
    int event_count = 0;
    double relative_tolerance = 0.0;  // of the phase, as CVODE is given it (at least 2 DBL_EPSILON)
    State absolute_tolerance{};
  };

 private:
  sundials::Vector state_;
  sundials::Matrix jacobian_;
  sundials::LinearSolver linear_solver_;
  sundials::NonlinearSolver fixed_point_solver_;
  sundials::CvodeMemory memory_;
  CallbackData data_;
  int watched_events_ = -1;
  bool initialized_ = false;
  double stop_ = 0.0;
  long max_steps_ = 0;  // per phase
  bool every_step_ = false;
  int size_ = 3;
};

}  // namespace restitution::detail
