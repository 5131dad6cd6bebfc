// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// One integrate-until-event service on CVODE: a system (a right-hand side and its events as data) is
// integrated until an event the caller stops at, with restarts (CVodeReInit) where the caller changes the
// mode or the state. Private to the library.
//
// The vocabulary is SciPy's solve_ivp (an event is a function whose zero is the event, a direction and
// whether it is terminal) and deal.II's SUNDIALS wrappers (a restart hook, solver_should_restart; an
// exception thrown inside a callback is carried across CVODE and rethrown, pending_exception).
//
// What a consumer writes (docs/design.md, "The event driver"):
//   1. an EventSystem: the state's size, dy/dτ in time form, its events (and a Jacobian for Newton, or none);
//   2. DriverSettings: method, corrector, tolerances, stop, step limits;
//   3. optionally the smoothing of a contact law (Smoothing): the driver then integrates u = x^{1/q} in
//      place of the overlap x = y[0], with dτ = u^{q-1} dσ, while the system still sees x, τ and dy/dτ;
//   4. a loop: driver.start(τ0, y0), then driver.run(hook) until a terminal event or the stop (or
//      driver.advance() step by step), reading driver.stats() at the end.
// The hook is called at every step where a non-terminal event was found; it may change the state and the
// events (directions, active) and return AfterEvent::restart, go on, or stop.
// The smoothing holds while x >= 0 (u = x^{1/q}): a contact whose overlap goes negative (an adhesive neck)
// ends the smoothed run at a terminal event (u falling through 0) and goes on in the time form with a second
// driver started from that step's τ and state. An event function that is 0 at the start (x = 0 at first
// touch) is no event there: CVODE looks just past the start and reports a root only where the function then
// crosses 0 (the head-on phases and tests/test_event_driver.cpp start at u = 0 with the naive end watched).
#include <exception>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "restitution/contact_law.hpp"
#include "restitution/solve_types.hpp"
#include "sundials/handles.hpp"

namespace restitution::detail {

// Where the system is, as its right-hand side and events see it.
struct DriverPoint {
  double t = 0.0;             // the independent variable CVODE integrates: τ, or σ under the smoothing
  double tau = 0.0;           // the time τ (= t without the smoothing)
  const double* y = nullptr;  // the state in time form, EventSystem::size entries (y[0] = x when smoothed)
  double u = 0.0;  // under the smoothing the smooth variable u = x^{1/q}, which changes sign at x = 0 where
                   // x = u^q may not (the naive end); without it y[0]
};

// Which crossings of 0 count (SciPy's `direction`): falling (+ to -), rising (- to +) or either.
enum class Crossing { falling = -1, either = 0, rising = 1 };

// One event: its function of the point, whose zero is the event. An event that is not active is not
// watched (its function is then a positive constant: CVODE's number of functions stays).
struct EventSpec {
  std::string name;  // for messages and tests
  std::function<double(const DriverPoint&)> function;
  Crossing direction = Crossing::either;
  bool terminal = true;  // run() returns at it; a non-terminal event goes to the restart hook
  bool active = true;
};

// Column-major dense n×n matrix (SUNDIALS' layout) the Jacobian fills; zero on entry.
struct JacobianView {
  double* data;
  int n;
  double& operator()(int row, int column) const { return data[column * n + row]; }
};

struct EventSystem {
  int size = 0;  // components of the time-form state
  // dy/dτ at the point (`size` entries written to the second argument).
  std::function<void(const DriverPoint&, double*)> rates;
  // ∂(dy/dτ)/∂y for the Newton corrector; empty: CVODE's difference quotients. Not with the smoothing.
  std::function<void(const DriverPoint&, JacobianView)> jacobian;
  std::vector<EventSpec> events;
};

// The smoothing of a contact's start and naive end (docs/design.md §4): with a law, the overlap y[0] = x is
// integrated as u = x^{1/q} (ContactLaw::smoothing_root, smooth_variable) and the independent variable is σ
// with dτ = u^{q-1} dσ, τ carried as the last component (du/dσ = x'/q where x' = dx/dτ is the system's rate
// of y[0]). Analytic in u and σ for viscoelastic Hertz where the time form has sqrt singularities at x = 0.
struct Smoothing {
  const ContactLaw* law = nullptr;  // null: the time form, τ itself
};

enum class Multistep { adams, bdf };
enum class Corrector { fixed_point, newton };

struct DriverSettings {
  Multistep method = Multistep::adams;
  Corrector corrector = Corrector::fixed_point;  // newton: a dense direct solver (EventSystem::jacobian)
  double relative_tolerance = 1e-10;  // taken as at least 2 DBL_EPSILON (below, CVODE stops with flag -2)
  // One per integrated component: size, or size + 1 under the smoothing (u first, τ last).
  std::vector<double> absolute_tolerance;
  double stop = 1e8;         // the independent variable's last value (CVodeSetStopTime)
  long max_steps = 1000000;  // per segment: from a start or restart to the next
  double min_step = 0.0;     // 0: CVODE's default
  double max_step = 0.0;     // 0: unbounded
  // CVODE keeps its step unless it may grow by this factor (CVodeSetEtaFixedStepBounds); 0: CVODE's 1.5.
  double step_growth_threshold = 0.0;
  int max_order = 0;  // 0: CVODE's (12 Adams, 5 BDF)
  // advance() returns after every internal step (to record a trajectory) instead of only at events and the
  // stop, which saves CVODE's per-call overhead.
  bool every_step = false;
  std::string variable_name = "t";  // the independent variable in messages (τ is named tau when smoothed)
};

// What advance() and run() return.
struct DriverStep {
  double t = 0.0;           // the independent variable
  double tau = 0.0;         // the time
  std::vector<double> y;    // the time-form state (a restart hook may change it before a restart)
  unsigned long found = 0;  // bit i: event i (active) was found at this step
  bool reached_stop = false;
  [[nodiscard]] bool event(int index) const { return ((found >> index) & 1UL) != 0; }
  [[nodiscard]] bool any_event() const { return found != 0; }
};

enum class AfterEvent { go_on, restart, stop };
// Called at a step where only non-terminal events were found. It may change step.y (the state the restart
// starts from) and driver.events(); go_on continues without a restart (CVODE keeps its history), restart
// calls restart(step.y), stop makes run() return the step.
using RestartHook = std::function<AfterEvent(DriverStep& step)>;

class EventDriver {
 public:
  // Throws InvalidInput naming what does not fit: a system without a size or rates, absolute tolerances
  // not one per integrated component, more than 64 events, a Jacobian with the smoothing.
  EventDriver(EventSystem system, DriverSettings settings, const sundials::Context& context,
              Smoothing smoothing = {});
  // The same with a SUNDIALS context of its own (a consumer that runs one driver needs no sundials/ header).
  EventDriver(EventSystem system, DriverSettings settings, Smoothing smoothing = {});
  EventDriver(const EventDriver&) = delete;  // CVODE holds a pointer to it
  EventDriver& operator=(const EventDriver&) = delete;
  ~EventDriver();

  // Starts at time τ0 with the time-form state y0 (size entries); under the smoothing σ starts at 0. Starting
  // again forgets the previous run (and its statistics).
  void start(double tau0, const double* y0);
  // Restarts at the current point from the time-form state y (CVodeReInit): the events and their
  // directions are read again. Under the smoothing u and τ stay as integrated where y[0] is the current x
  // (no round trip through x^{1/q}).
  void restart(const double* y);
  // One internal step (every_step) or up to the next event or the stop. Throws NumericalFailure on a CVODE
  // failure or once the segment has taken max_steps steps, and rethrows what a callback threw.
  DriverStep advance();
  // Advances until a terminal event (or the hook's stop) or the stop; the hook (may be empty: go on) at every
  // other event. Returns the last step: step.reached_stop, or the events found.
  DriverStep run(const RestartHook& hook = {});

  // The events, to change between steps (active, direction: read at the next start or restart; active
  // also at once).
  [[nodiscard]] std::vector<EventSpec>& events() { return system_.events; }
  // Statistics of every segment since start() (restarts reset CVODE's counters: they are added up here).
  [[nodiscard]] SolverStats stats() const;

 private:
  class Callbacks;
  friend class Callbacks;
  [[nodiscard]] DriverPoint point_at(double t, const double* integrated);
  void configure_segment();
  [[nodiscard]] DriverStep step_at(double t) const;

  EventDriver(EventSystem system, DriverSettings settings, std::unique_ptr<sundials::Context> own,
              const sundials::Context* context, Smoothing smoothing);

  std::unique_ptr<sundials::Context> own_context_;  // null where the caller's context is used
  EventSystem system_;
  DriverSettings settings_;
  const ContactLaw* law_ = nullptr;
  int size_ = 0;  // integrated components (system size, + 1 under the smoothing)
  sundials::Vector state_;
  sundials::Matrix jacobian_;
  sundials::LinearSolver linear_solver_;
  sundials::NonlinearSolver fixed_point_solver_;
  sundials::CvodeMemory memory_;
  std::vector<double> time_form_;  // the time-form state the callbacks see under the smoothing
  double relative_tolerance_ = 0.0;
  double t_ = 0.0;          // where CVODE is
  SolverStats finished_{};  // of the segments before the current one
  int registered_events_ = -1;
  bool initialized_ = false;
  std::exception_ptr pending_exception_;
};

}  // namespace restitution::detail
