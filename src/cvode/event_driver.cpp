// SPDX-License-Identifier: BSD-3-Clause
#include "cvode/event_driver.hpp"

#include <cvode/cvode_ls.h>
#include <fmt/core.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <utility>

#include "cvode/cvode_forms.hpp"
#include "restitution/errors.hpp"
#include "sundials/fixed_point.hpp"
#include "sundials/small_dense.hpp"
#include "sundials/small_vector.hpp"

namespace restitution::detail {

// At most this many events: advance() reports them as the bits of DriverStep::found.
constexpr std::size_t kMostDriverEvents = 64;

// CVODE's callbacks: each evaluates the system at the point and, under the smoothing, transforms its
// time-form rates. An exception thrown by the system is kept and rethrown after CVODE returns (a C library
// must not be unwound through).
class EventDriver::Callbacks {
 public:
  static int rates(sunrealtype t, N_Vector y, N_Vector ydot, void* user_data) noexcept {
    auto& driver = *static_cast<EventDriver*>(user_data);
    try {
      const double* s = NV_DATA_S(y);
      double* d = NV_DATA_S(ydot);
      driver.system_.rates(driver.point_at(t, s), d);
      if (driver.law_ != nullptr) to_sundman_rates(*driver.law_, s[0], d, driver.system_.size);
      return 0;
    } catch (...) {
      driver.pending_exception_ = std::current_exception();
      return -1;
    }
  }

  static int jacobian(sunrealtype t, N_Vector y, N_Vector /*fy*/, SUNMatrix J, void* user_data,
                      N_Vector /*t1*/, N_Vector /*t2*/, N_Vector /*t3*/) noexcept {
    auto& driver = *static_cast<EventDriver*>(user_data);
    try {
      SUNMatZero(J);
      driver.system_.jacobian(driver.point_at(t, NV_DATA_S(y)), {SM_DATA_D(J), driver.size_});
      return 0;
    } catch (...) {
      driver.pending_exception_ = std::current_exception();
      return -1;
    }
  }

  static int events(sunrealtype t, N_Vector y, sunrealtype* g, void* user_data) noexcept {
    auto& driver = *static_cast<EventDriver*>(user_data);
    try {
      const DriverPoint p = driver.point_at(t, NV_DATA_S(y));
      std::size_t i = 0;
      for (const EventSpec& event : driver.system_.events) g[i++] = event.active ? event.function(p) : 1.0;
      return 0;
    } catch (...) {
      driver.pending_exception_ = std::current_exception();
      return -1;
    }
  }

  static int error_weights(N_Vector y, N_Vector weights, void* user_data) noexcept {
    const auto& driver = *static_cast<const EventDriver*>(user_data);
    const std::vector<double>& atol = driver.settings_.absolute_tolerance;
    return detail::error_weights(driver.relative_tolerance_, atol.data(), NV_DATA_S(y), NV_DATA_S(weights),
                                 atol.size());
  }
};

namespace {

void require_driver_input(bool condition, const std::string& what) {
  if (!condition) throw InvalidInput("event driver: " + what);
}

}  // namespace

EventDriver::EventDriver(EventSystem system, DriverSettings settings, const sundials::Context& context,
                         Smoothing smoothing)
    : EventDriver(std::move(system), std::move(settings), nullptr, &context, smoothing) {}

EventDriver::EventDriver(EventSystem system, DriverSettings settings, Smoothing smoothing)
    : EventDriver(std::move(system), std::move(settings), std::make_unique<sundials::Context>(), nullptr,
                  smoothing) {}

EventDriver::EventDriver(EventSystem system, DriverSettings settings, std::unique_ptr<sundials::Context> own,
                         const sundials::Context* context, Smoothing smoothing)
    : own_context_(std::move(own)),
      system_(std::move(system)),
      settings_(std::move(settings)),
      law_(smoothing.law),
      size_(system_.size + (smoothing.law != nullptr ? 1 : 0)),
      memory_(settings_.method == Multistep::adams ? CV_ADAMS : CV_BDF,
              context != nullptr ? *context : *own_context_) {
  const sundials::Context& sundials_context = context != nullptr ? *context : *own_context_;
  require_driver_input(system_.size > 0 && system_.rates, "the system needs a size and a right-hand side");
  require_driver_input(
      settings_.absolute_tolerance.size() == static_cast<std::size_t>(size_),
      fmt::format("{} absolute tolerances for {} integrated components (the smoothing adds tau)",
                  settings_.absolute_tolerance.size(), size_));
  require_driver_input(system_.events.size() <= kMostDriverEvents,
                       fmt::format("at most {} events", kMostDriverEvents));
  require_driver_input(!(law_ != nullptr && system_.jacobian),
                       "no Jacobian with the smoothing (it is of the time form)");
  require_driver_input(settings_.relative_tolerance > 0.0, "the relative tolerance must be positive");
  state_ = sundials::make_small_vector(size_, sundials_context);
  N_VConst(0.0, state_.get());
  if (law_ != nullptr) time_form_.resize(static_cast<std::size_t>(system_.size));
  if (settings_.corrector == Corrector::fixed_point) {
    fixed_point_solver_ = sundials::make_small_fixed_point_solver(state_, sundials_context);
  } else {
    jacobian_ = sundials::make_small_dense_matrix(size_, sundials_context);
    linear_solver_ = sundials::make_small_dense_solver(state_, jacobian_, sundials_context);
  }
  relative_tolerance_ = cvode_relative_tolerance(settings_.relative_tolerance);
}

EventDriver::~EventDriver() = default;

DriverPoint EventDriver::point_at(double t, const double* integrated) {
  if (law_ == nullptr) return {t, t, integrated, integrated[0]};
  std::copy(integrated, integrated + system_.size, time_form_.begin());
  time_form_[0] = law_->compression_of(integrated[0]);
  return {t, integrated[system_.size], time_form_.data(), integrated[0]};
}

void EventDriver::start(double tau0, const double* y0) {
  void* mem = memory_.get();
  memory_.clear_error();
  pending_exception_ = nullptr;
  finished_ = {};
  double* s = N_VGetArrayPointer(state_.get());
  std::copy(y0, y0 + system_.size, s);
  t_ = tau0;
  if (law_ != nullptr) {
    s[0] = law_->smooth_variable(y0[0]);
    s[system_.size] = tau0;
    t_ = 0.0;
  }
  if (!initialized_) {
    sundials::check_flag(CVodeInit(mem, Callbacks::rates, t_, state_.get()), "CVodeInit");
    sundials::check_flag(CVodeSetUserData(mem, this), "CVodeSetUserData");
    sundials::check_flag(CVodeWFtolerances(mem, Callbacks::error_weights), "CVodeWFtolerances");
    if (fixed_point_solver_) {
      sundials::check_flag(CVodeSetNonlinearSolver(mem, fixed_point_solver_.get()),
                           "CVodeSetNonlinearSolver");
    } else {
      sundials::check_flag(CVodeSetLinearSolver(mem, linear_solver_.get(), jacobian_.get()),
                           "CVodeSetLinearSolver");
      if (system_.jacobian) sundials::check_flag(CVodeSetJacFn(mem, Callbacks::jacobian), "CVodeSetJacFn");
    }
    if (settings_.step_growth_threshold > 0.0) {
      sundials::check_flag(CVodeSetEtaFixedStepBounds(mem, 0.0, settings_.step_growth_threshold),
                           "CVodeSetEtaFixedStepBounds");
    }
    if (settings_.max_order > 0)
      sundials::check_flag(CVodeSetMaxOrd(mem, settings_.max_order), "CVodeSetMaxOrd");
    if (settings_.min_step > 0.0)
      sundials::check_flag(CVodeSetMinStep(mem, settings_.min_step), "CVodeSetMinStep");
    if (settings_.max_step > 0.0)
      sundials::check_flag(CVodeSetMaxStep(mem, settings_.max_step), "CVodeSetMaxStep");
    initialized_ = true;
  } else {
    sundials::check_flag(CVodeReInit(mem, t_, state_.get()), "CVodeReInit");
  }
  configure_segment();
}

void EventDriver::restart(const double* y) {
  finished_ = stats();  // CVodeReInit resets CVODE's counters
  double* s = N_VGetArrayPointer(state_.get());
  const double u = s[0];
  std::copy(y, y + system_.size, s);
  if (law_ != nullptr) s[0] = y[0] == law_->compression_of(u) ? u : law_->smooth_variable(y[0]);
  sundials::check_flag(CVodeReInit(memory_.get(), t_, state_.get()), "CVodeReInit");
  configure_segment();
}

void EventDriver::configure_segment() {
  void* mem = memory_.get();
  sundials::check_flag(CVodeSetMaxNumSteps(mem, settings_.max_steps), "CVodeSetMaxNumSteps");
  sundials::check_flag(CVodeSetStopTime(mem, settings_.stop), "CVodeSetStopTime");
  const int count = static_cast<int>(system_.events.size());
  if (count != registered_events_) {
    sundials::check_flag(CVodeRootInit(mem, count, count > 0 ? Callbacks::events : nullptr), "CVodeRootInit");
    registered_events_ = count;
  }
  if (count > 0) {
    std::vector<int> directions;
    directions.reserve(system_.events.size());
    for (const EventSpec& event : system_.events) directions.push_back(static_cast<int>(event.direction));
    sundials::check_flag(CVodeSetRootDirection(mem, directions.data()), "CVodeSetRootDirection");
  }
}

DriverStep EventDriver::step_at(double t) const {
  DriverStep step;
  step.t = t;
  const double* s = N_VGetArrayPointer(state_.get());
  step.y.assign(s, s + system_.size);
  step.tau = t;
  if (law_ != nullptr) {
    step.y[0] = law_->compression_of(s[0]);
    step.tau = s[system_.size];
  }
  return step;
}

DriverStep EventDriver::advance() {
  void* mem = memory_.get();
  // The segment's step limit: CVODE's own applies per call, so each call gets what the segment has left (in
  // CV_ONE_STEP mode CVODE never applies it); running out is reported alike in both modes.
  long steps = 0;
  CVodeGetNumSteps(mem, &steps);
  const auto where = [&](double t) {
    const DriverStep at = step_at(t);
    return law_ != nullptr ? fmt::format("tau={}", at.tau) : fmt::format("{}={}", settings_.variable_name, t);
  };
  const auto too_much_work = [&] {
    CVodeGetCurrentTime(mem, &t_);
    return NumericalFailure(
        fmt::format("CVODE failed at {} with flag {} (too much work: {} steps in one phase)", where(t_),
                    CV_TOO_MUCH_WORK, steps));
  };
  if (steps >= settings_.max_steps) throw too_much_work();
  if (!settings_.every_step) {
    sundials::check_flag(CVodeSetMaxNumSteps(mem, settings_.max_steps - steps), "CVodeSetMaxNumSteps");
  }
  const int flag =
      CVode(mem, settings_.stop, state_.get(), &t_, settings_.every_step ? CV_ONE_STEP : CV_NORMAL);
  if (pending_exception_) std::rethrow_exception(std::exchange(pending_exception_, nullptr));
  if (flag == CV_TOO_MUCH_WORK) {
    CVodeGetNumSteps(mem, &steps);
    throw too_much_work();
  }
  if (flag < 0) {
    throw NumericalFailure(fmt::format("CVODE failed at {} with flag {} ({})", where(t_), flag,
                                       memory_.last_error().empty() ? "no message" : memory_.last_error()));
  }
  DriverStep step = step_at(t_);
  if (flag == CV_ROOT_RETURN) {
    std::vector<int> found(system_.events.size());
    sundials::check_flag(CVodeGetRootInfo(mem, found.data()), "CVodeGetRootInfo");
    for (std::size_t i = 0; i < found.size(); ++i) {
      if (found[i] != 0 && system_.events[i].active) step.found |= 1UL << i;
    }
  }
  // In CV_NORMAL mode tout is the stop: reaching it may be reported as a plain success.
  step.reached_stop = flag == CV_TSTOP_RETURN || (!settings_.every_step && flag == CV_SUCCESS);
  return step;
}

DriverStep EventDriver::run(const RestartHook& hook) {
  while (true) {
    DriverStep step = advance();
    if (step.reached_stop) return step;
    if (!step.any_event()) continue;  // every_step
    bool terminal = false;
    for (std::size_t i = 0; i < system_.events.size(); ++i) {
      terminal = terminal || (step.event(static_cast<int>(i)) && system_.events[i].terminal);
    }
    if (terminal) return step;
    const AfterEvent next = hook ? hook(step) : AfterEvent::go_on;
    if (next == AfterEvent::stop) return step;
    if (next == AfterEvent::restart) restart(step.y.data());
  }
}

SolverStats EventDriver::stats() const {
  SolverStats total = finished_;
  if (!initialized_) return total;
  total += sundials::cvode_phase_stats(memory_.get());
  if (linear_solver_) {
    long value = 0;
    CVodeGetNumJacEvals(memory_.get(), &value);
    total.jacobian_evaluations += value;
  }
  return total;
}

}  // namespace restitution::detail
