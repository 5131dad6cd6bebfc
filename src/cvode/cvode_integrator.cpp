// SPDX-License-Identifier: BSD-3-Clause
#include "cvode/cvode_integrator.hpp"

#include <cvode/cvode_ls.h>
#include <fmt/core.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <cfloat>

#include "law/law_rhs.hpp"
#include "restitution/errors.hpp"
#include "sundials/fixed_point.hpp"
#include "sundials/small_dense.hpp"

namespace restitution::detail {
namespace {

using Data = CvodeIntegrator::CallbackData;

const char* form_variable(Form form) {
  if (form == Form::time) return "tau";
  return form == Form::sundman ? "s" : "u";
}

// The smallest growth of the step size CVODE acts on with Adams (its default: 1.5).
constexpr double kStepGrowthThreshold = 1.2;
// The same for the Sundman form (4 components): from 1.05x on, 4 % fewer steps than from 1.2x and less CPU
// (delayed end, 25 ζ in [1e-3, 1e3], T = 1e-10; docs/performance.md, eighth round).
constexpr double kSundmanStepGrowthThreshold = 1.05;
// Adams' highest order (CVODE's default: 12). Each step's predictor costs q(q+1)/2 vector sums; above 9 the
// order gains no steps here (delayed end, 25 ζ in [1e-3, 1e3], T = 1e-10: 299 steps at 9, 324 at 12, 315 at
// 8, 398 at 7) and CPU per solve is 11 % lower at 9 than at 12 (docs/performance.md).
constexpr int kAdamsMaxOrder = 9;

// The callbacks are plain arithmetic on doubles: nothing in them can throw, so nothing crosses CVODE.
int right_hand_side(sunrealtype t, N_Vector y, N_Vector ydot, void* user_data) noexcept {
  const Data& data = *static_cast<Data*>(user_data);
  const ContactLaw& law = *data.law;
  const double* s = NV_DATA_S(y);
  double* d = NV_DATA_S(ydot);
  const double v = s[kVelocity];
  if (data.form == Form::time) {
    d[kFirst] = v;
    d[kVelocity] = law_rhs::acceleration(law, s[kFirst], v);
    d[kDissipation] = law_rhs::dissipation_integrand(law, s[kFirst], v);
  } else if (data.form == Form::sundman) {
    const double u = s[kFirst];
    const double x = law.compression_of(u);
    const double dtau_ds = law.dcompression_du(u) / law.smoothing_root();  // u^{q-1}
    d[kFirst] = v / law.smoothing_root();
    d[kVelocity] = law_rhs::acceleration(law, x, v) * dtau_ds;
    d[kDissipation] = law_rhs::dissipation_integrand(law, x, v) * dtau_ds;
    d[kSundmanTau] = dtau_ds;
  } else {
    const double x = law.compression_of(t);
    const double dtau_du = law.dcompression_du(t) / v;
    const TauLog& tau_log = data.tau_log;
    d[kFirst] = tau_log.coefficient == 0.0 ? dtau_du : dtau_du + tau_log.coefficient / (t + tau_log.shift);
    d[kVelocity] = law_rhs::acceleration(law, x, v) * dtau_du;
    d[kDissipation] = law_rhs::dissipation_integrand(law, x, v) * dtau_du;
  }
  return 0;
}

int jacobian(sunrealtype t, N_Vector y, N_Vector /*fy*/, SUNMatrix J, void* user_data, N_Vector /*t1*/,
             N_Vector /*t2*/, N_Vector /*t3*/) noexcept {
  const Data& data = *static_cast<Data*>(user_data);
  const ContactLaw& law = *data.law;
  const double* s = NV_DATA_S(y);
  const double v = s[kVelocity];
  SUNMatZero(J);
  if (data.form == Form::time) {
    const double x = s[kFirst];
    SM_ELEMENT_D(J, kFirst, kVelocity) = 1.0;
    SM_ELEMENT_D(J, kVelocity, kFirst) = law_rhs::dacceleration_dx(law, x, v);
    SM_ELEMENT_D(J, kVelocity, kVelocity) = law_rhs::dacceleration_dv(law, x);
    SM_ELEMENT_D(J, kDissipation, kFirst) = law_rhs::ddissipation_integrand_dx(law, x, v);
    SM_ELEMENT_D(J, kDissipation, kVelocity) = law_rhs::ddissipation_integrand_dv(law, x, v);
  } else {
    // Only x' appears on the right-hand side: d/dx' of g(x')·q u^{q-1}/x' is q u^{q-1} (g'·x' - g)/x'^2.
    const double x = law.compression_of(t);
    const double scale = law.dcompression_du(t) / (v * v);
    SM_ELEMENT_D(J, kFirst, kVelocity) = -scale;
    SM_ELEMENT_D(J, kVelocity, kVelocity) =
        scale * (law_rhs::dacceleration_dv(law, x) * v - law_rhs::acceleration(law, x, v));
    SM_ELEMENT_D(J, kDissipation, kVelocity) = scale * (law_rhs::ddissipation_integrand_dv(law, x, v) * v -
                                                        law_rhs::dissipation_integrand(law, x, v));
  }
  return 0;
}

int event_functions(sunrealtype t, N_Vector y, sunrealtype* g, void* user_data) noexcept {
  const Data& data = *static_cast<Data*>(user_data);
  const double* s = NV_DATA_S(y);
  const double x = data.form == Form::time      ? s[kFirst]
                   : data.form == Form::sundman ? data.law->compression_of(s[kFirst])
                                                : data.law->compression_of(t);
  const double v = s[kVelocity];
  for (std::size_t i = 0; i < static_cast<std::size_t>(data.event_count); ++i) {
    if (data.ignored[i]) {
      g[i] = 1.0;
      continue;
    }
    switch (data.events[i]) {
      case Event::max_compression:
        g[i] = v;
        break;
      case Event::naive_end:
        // u changes sign at x = 0 where x = u^q may not.
        g[i] = data.form == Form::sundman ? s[kFirst] : x;
        break;
      case Event::delayed_recovery_end:
        g[i] = law_rhs::force_factor(*data.law, x, v);
        break;
      case Event::velocity_halved:
        g[i] = v - 0.5 * data.law->initial_velocity();
        break;
      case Event::below_switch:
        g[i] = x - data.switch_x;
        break;
      case Event::naive_end_excluded:
        g[i] = naive_end_excluded(*data.law, x, v);
        break;
    }
  }
  return 0;
}

// CVODE's error weights for a relative tolerance and a vector of absolute ones, 1/(rtol |y_i| + atol_i), in
// one loop: the same arithmetic as CVODE's own (CVodeSVtolerances: N_VAbs, N_VLinearSum, N_VInv), without its
// four vector calls per step (~2 % of a solve's instructions).
int error_weights(N_Vector y, N_Vector weights, void* user_data) noexcept {
  const Data& data = *static_cast<Data*>(user_data);
  const double* s = NV_DATA_S(y);
  double* w = NV_DATA_S(weights);
  const auto size = static_cast<std::size_t>(NV_LENGTH_S(y));
  for (std::size_t i = 0; i < size; ++i) {
    const double scale = data.relative_tolerance * std::abs(s[i]) + data.absolute_tolerance[i];
    if (scale <= 0.0) return -1;  // as CVODE: a zero weight scale is an error
    w[i] = 1.0 / scale;
  }
  return 0;
}

}  // namespace

CvodeIntegrator::CvodeIntegrator(Method method, const sundials::Context& context, int size)
    : state_(sundials::make_small_vector(size, context)),
      memory_(method == Method::adams ? CV_ADAMS : CV_BDF, context),
      size_(size) {
  N_VConst(0.0, state_.get());
  if (method == Method::adams) {
    // Adams is chosen where the problem is not stiff: a fixed-point corrector needs no Jacobian.
    fixed_point_solver_ = sundials::make_small_fixed_point_solver(state_, context);
  } else {
    jacobian_ = sundials::make_small_dense_matrix(size, context);
    linear_solver_ = sundials::make_small_dense_solver(state_, jacobian_, context);
  }
}

void CvodeIntegrator::start(const ContactLaw& law, const PhaseSettings& settings, double t0,
                            const State& state, const Event* events, int event_count) {
  void* mem = memory_.get();
  memory_.clear_error();
  data_.law = &law;
  data_.form = settings.form;
  data_.switch_x = settings.switch_x;
  data_.tau_log = settings.tau_log;
  data_.event_count = event_count;
  data_.ignored.fill(false);
  for (std::size_t i = 0; i < static_cast<std::size_t>(event_count); ++i) data_.events[i] = events[i];

  // The Sundman form has no Jacobian here: it runs with Adams (fixed point) only.
  if (state_size(settings.form) != size_ || (settings.form == Form::sundman && linear_solver_)) {
    throw NumericalFailure(fmt::format("this {}-component integrator cannot run a {}-component form", size_,
                                       state_size(settings.form)));
  }
  double* s = N_VGetArrayPointer(state_.get());
  for (std::size_t i = 0; i < static_cast<std::size_t>(size_); ++i) s[i] = state[i];

  if (!initialized_) {
    sundials::check_flag(CVodeInit(mem, right_hand_side, t0, state_.get()), "CVodeInit");
    sundials::check_flag(CVodeSetUserData(mem, &data_), "CVodeSetUserData");
    sundials::check_flag(CVodeWFtolerances(mem, error_weights), "CVodeWFtolerances");
    if (fixed_point_solver_) {
      sundials::check_flag(CVodeSetNonlinearSolver(mem, fixed_point_solver_.get()),
                           "CVodeSetNonlinearSolver");
      // CVODE keeps h unless it may grow by 1.5x; for Adams, changing it from 1.2x on takes ~20 % fewer
      // steps on ζ in [1e-3, 1e3] at T = 1e-10, with a smaller error (docs/performance.md). Not for BDF:
      // there it cost accuracy near the dash-pot's critical damping.
      const bool sundman = size_ == state_size(Form::sundman);
      sundials::check_flag(
          CVodeSetEtaFixedStepBounds(mem, 0.0, sundman ? kSundmanStepGrowthThreshold : kStepGrowthThreshold),
          "CVodeSetEtaFixedStepBounds");
      sundials::check_flag(CVodeSetMaxOrd(mem, kAdamsMaxOrder), "CVodeSetMaxOrd");
    } else {
      sundials::check_flag(CVodeSetLinearSolver(mem, linear_solver_.get(), jacobian_.get()),
                           "CVodeSetLinearSolver");
      sundials::check_flag(CVodeSetJacFn(mem, jacobian), "CVodeSetJacFn");
    }
    initialized_ = true;
  } else {
    sundials::check_flag(CVodeReInit(mem, t0, state_.get()), "CVodeReInit");
  }

  // CVODE stops with "too much accuracy requested" (flag -2) where DBL_EPSILON/rtol > 1; below 2 DBL_EPSILON
  // its steps are bound by rounding anyway (near critical damping, where the tolerance policy asks for less),
  // and check_solve_request refuses the tolerances that rounding cannot deliver.
  data_.relative_tolerance = std::max(settings.relative_tolerance, 2.0 * DBL_EPSILON);
  data_.absolute_tolerance = settings.absolute_tolerance;
  sundials::check_flag(CVodeSetMaxNumSteps(mem, settings.max_steps), "CVodeSetMaxNumSteps");
  max_steps_ = settings.max_steps;
  every_step_ = settings.every_step;
  sundials::check_flag(CVodeSetStopTime(mem, settings.stop), "CVodeSetStopTime");
  stop_ = settings.stop;

  if (event_count != watched_events_) {
    sundials::check_flag(CVodeRootInit(mem, event_count, event_functions), "CVodeRootInit");
    watched_events_ = event_count;
  }
  // Events are crossings in the direction of integration; the compression form of the end runs towards
  // u = 0, so there either direction is accepted (each of its events crosses once).
  std::array<int, kMaxEvents> directions{};
  directions.fill(settings.stop >= t0 ? -1 : 0);
  if (event_count > 0) {
    sundials::check_flag(CVodeSetRootDirection(mem, directions.data()), "CVodeSetRootDirection");
  }
}

CvodeIntegrator::Step CvodeIntegrator::advance() {
  Step step;
  // The phase's step limit: CVODE's own applies per call, so each call gets what the phase has left (in
  // CV_ONE_STEP mode CVODE never applies it); running out is reported alike in both modes.
  long steps = 0;
  CVodeGetNumSteps(memory_.get(), &steps);
  const auto too_much_work = [&] {
    CVodeGetCurrentTime(memory_.get(), &step.t);
    return NumericalFailure(
        fmt::format("CVODE failed at {}={} with flag {} (too much work: {} steps in one phase)",
                    form_variable(data_.form), step.t, CV_TOO_MUCH_WORK, steps));
  };
  if (steps >= max_steps_) throw too_much_work();
  if (!every_step_) {
    sundials::check_flag(CVodeSetMaxNumSteps(memory_.get(), max_steps_ - steps), "CVodeSetMaxNumSteps");
  }
  const int flag = CVode(memory_.get(), stop_, state_.get(), &step.t, every_step_ ? CV_ONE_STEP : CV_NORMAL);
  if (flag == CV_TOO_MUCH_WORK) {
    CVodeGetNumSteps(memory_.get(), &steps);
    throw too_much_work();
  }
  if (flag < 0) {
    throw NumericalFailure(fmt::format("CVODE failed at {}={} with flag {} ({})", form_variable(data_.form),
                                       step.t, flag,
                                       memory_.last_error().empty() ? "no message" : memory_.last_error()));
  }
  const double* s = N_VGetArrayPointer(state_.get());
  for (std::size_t i = 0; i < static_cast<std::size_t>(size_); ++i) step.state[i] = s[i];
  if (flag == CV_ROOT_RETURN) {
    std::array<int, kMaxEvents> found{};
    sundials::check_flag(CVodeGetRootInfo(memory_.get(), found.data()), "CVodeGetRootInfo");
    for (std::size_t i = 0; i < static_cast<std::size_t>(data_.event_count); ++i) {
      step.events_found[i] = found[i] != 0 && !data_.ignored[i];
    }
  }
  // In CV_NORMAL mode tout is the stop: reaching it may be reported as a plain success.
  step.reached_stop = flag == CV_TSTOP_RETURN || (!every_step_ && flag == CV_SUCCESS);
  return step;
}

SolverStats CvodeIntegrator::phase_stats() const {
  void* mem = memory_.get();
  SolverStats stats = sundials::cvode_phase_stats(mem);
  if (linear_solver_) {
    long value = 0;
    CVodeGetNumJacEvals(mem, &value);
    stats.jacobian_evaluations = value;
  }
  return stats;
}

}  // namespace restitution::detail
