// SPDX-License-Identifier: BSD-3-Clause
#include "cvode/cvode_run.hpp"

#include <fmt/core.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "restitution/errors.hpp"

namespace restitution::detail {
namespace {

// The Sundman phase's last s, in units of the time limit: dτ/ds = u^{q-1} falls below its value at
// x = length_scale where x is smaller; the steps are bound by the phase's step limit anyway.
constexpr double kSundmanStopPerTau = 1e3;

// A point of the trajectory in the law's own units, whatever form produced it.
struct Point {
  double tau, x, velocity, dissipation;
};

Point point_of(const ContactLaw& law, Form form, const TauLog& tau_log, double t, const State& s) {
  if (form == Form::time) return {t, s[kFirst], s[kVelocity], s[kDissipation]};
  if (form == Form::sundman) {
    return {s[kSundmanTau], law.compression_of(s[kFirst]), s[kVelocity], s[kDissipation]};
  }
  return {s[kFirst] - tau_log.offset(t), law.compression_of(t), s[kVelocity], s[kDissipation]};
}

// The methods a failed solve may be retried with: every method of kMethods but auto, which solves with one.
std::string retry_methods() {
  std::vector<std::string> names;
  for (const Method method : kMethods) {
    if (method != Method::automatic) names.emplace_back(method_name(method));
  }
  return fmt::format("{}", fmt::join(names, ", "));
}

const char* end_names(EndSet ends) {
  if (ends == EndSet::both()) return "both ends";
  return ends.contains(CollisionEnd::naive) ? "the naive end" : "the delayed-recovery end";
}

EndResult end_result(const ContactLaw& law, const Point& p) {
  EndResult end;
  const double v0 = law.initial_velocity();
  const double x = std::max(p.x, 0.0);  // a root located a rounding error past x = 0
  const EndValues values = law.end_values(x, p.velocity, p.dissipation);
  end.eps = values.eps;
  end.one_minus_eps = values.one_minus_eps;
  end.tau = p.tau / law.time_scale();
  end.x = x / law.length_scale();
  end.velocity = p.velocity / v0;
  end.dissipated_energy = law.damping() * p.dissipation / (v0 * v0);
  return end;
}

// Runs the phases of one collision on one integrator and collects what was asked for.
class CollisionRun {
 public:
  CollisionRun(const ContactLaw& law, const SolveOptions& options, const SolvePlan& plan,
               CvodeIntegrator& integrator, CvodeIntegrator* tail, CvodeIntegrator* sundman)
      : law_(law), options_(options), plan_(plan), integrator_(&integrator), tail_(tail), sundman_(sundman) {
    result_.value.law = law.kind();
    result_.value.parameter = law.parameter();
    result_.value.speed_independent = law.speed_independent();
    result_.value.tolerance = options.tolerance;
    result_.value.method = plan.tail_method.value_or(plan.method);
  }

  CollisionResult run() {
    const State start{0.0, law_.initial_velocity(), 0.0};
    if (options_.keep_trajectory) record({0.0, 0.0, law_.initial_velocity(), 0.0});
    if (plan_.single_phase && sundman_ != nullptr && sundman_phase()) {
      // done in one phase
    } else if (!plan_.smooth_ends) {
      time_phase(Form::time, 0.0, start, /*switch_x=*/-1.0);
    } else {
      // Start: u from 0 until x' has halved (or x = start_phase_x); then τ around maximal compression
      // until x falls below 0.9 times the compression where the start phase ended; then u down to 0.
      const Point a = compression_phase(0.0, law_.smooth_variable(plan_.start_phase_x), start, true);
      Point b = a;
      if (pending()) b = time_phase(Form::time, a.tau, {a.x, a.velocity, a.dissipation}, 0.9 * a.x);
      if (pending()) end_phase(b);
    }
    if (!result_.max_compression_found) throw failure("the collision ended without a maximal compression");
    return std::move(result_.value);
  }

 private:
  struct Accumulated {
    CollisionResult value;
    bool max_compression_found = false;
  };

  [[nodiscard]] bool pending() const {
    return std::any_of(kCollisionEnds.begin(), kCollisionEnds.end(), [this](CollisionEnd end) {
      return options_.ends.contains(end) && !result_.value[end];
    });
  }

  [[nodiscard]] NumericalFailure failure(const std::string& what) const {
    // What failed, where, and what to try: a looser tolerance or the other engine usually gets through.
    return NumericalFailure{fmt::format(
        "the integration failed for law {} at {}={}, {}, tolerance {:g}, method {}: {}; try a larger "
        "tolerance or another method ({})",
        law_name(law_.kind()), law_.parameter_name(), law_.parameter(), end_names(options_.ends),
        options_.tolerance, method_name(plan_.method), what, retry_methods())};
  }

  // The naive end was requested but the state entered a region from which x never returns to 0.
  [[noreturn]] void no_naive_end(const Point& p) {
    finish_phase();
    throw InvalidInput(fmt::format(
        "the naive end does not exist for law {} at zeta={}: from tau={:.6g} (x={:.6g}, x'={:.6g}) the "
        "overlap "
        "approaches 0 only as tau -> infinity (eps = 0 in the sense of the overdamped dash-pot); ask for the "
        "delayed-recovery end",
        law_name(law_.kind()), law_.zeta(), p.tau, p.x, p.velocity));
  }

  // Whether a phase watches Event::naive_end_excluded: the naive end is pending and only the solve can tell
  // whether it exists.
  [[nodiscard]] bool watch_naive_end_exclusion() const {
    return options_.ends.contains(CollisionEnd::naive) && !result_.value[CollisionEnd::naive] &&
           law_.naive_end_existence() == NaiveEndExistence::decided_by_solve && law_.zeta() > 0.0;
  }

  void record(const Point& p) {
    result_.value.trajectory.push_back(
        {p.tau / law_.time_scale(), p.x / law_.length_scale(), p.velocity / law_.initial_velocity(),
         law_.acceleration(p.x, p.velocity) * law_.time_scale() / law_.initial_velocity()});
  }

  void begin(const PhaseSettings& settings, double t0, const State& state, const Event* events, int count) {
    try {
      integrator_->start(law_, settings, t0, state, events, count);
    } catch (const NumericalFailure& e) {
      throw failure(e.what());
    }
  }

  CvodeIntegrator::Step advance() {
    try {
      CvodeIntegrator::Step step = integrator_->advance();
      if (options_.keep_trajectory) record(point_of(law_, form_, tau_log_, step.t, step.state));
      return step;
    } catch (const NumericalFailure& e) {
      result_.value.stats += integrator_->phase_stats();
      throw failure(e.what());
    }
  }

  void finish_phase() { result_.value.stats += integrator_->phase_stats(); }

  void found_max_compression(const Point& p) {
    if (result_.max_compression_found) return;
    result_.value.max_compression = {p.tau / law_.time_scale(), p.x / law_.length_scale()};
    result_.max_compression_found = true;
  }

  // Compression form from u0 towards u_stop. Going up (the start) it stops where x' has halved; going
  // down (the end) it watches the delayed-recovery end and reaches the naive end exactly at u = 0.
  Point compression_phase(double u0, double u_stop, State state, bool is_start) {
    form_ = Form::compression;
    tau_log_ = is_start ? TauLog{} : plan_.tail;
    state[kFirst] += tau_log_.offset(u0);
    PhaseSettings settings{Form::compression, plan_.relative_tolerance, plan_.absolute_tolerance_compression,
                           u_stop};
    settings.tau_log = tau_log_;
    settings.max_steps = plan_.max_steps;
    settings.every_step = options_.keep_trajectory;
    std::array<Event, kMaxEvents> events{};
    int count = 0;
    if (is_start) {
      events[static_cast<std::size_t>(count++)] = Event::velocity_halved;
    } else if (options_.ends.contains(CollisionEnd::delayed_recovery) &&
               !result_.value[CollisionEnd::delayed_recovery]) {
      events[static_cast<std::size_t>(count++)] = Event::delayed_recovery_end;
    }
    const int excluded = !is_start && watch_naive_end_exclusion() ? count++ : -1;
    if (excluded >= 0) events[static_cast<std::size_t>(excluded)] = Event::naive_end_excluded;
    begin(settings, u0, state, events.data(), count);
    while (true) {
      const CvodeIntegrator::Step step = advance();
      const Point p = point_of(law_, Form::compression, tau_log_, step.t, step.state);
      if (excluded >= 0 && step.events_found[static_cast<std::size_t>(excluded)]) no_naive_end(p);
      if (step.reached_stop || (count > 0 && excluded != 0 && step.events_found[0])) {
        if (!is_start && step.events_found[0]) {
          result_.value[CollisionEnd::delayed_recovery] = end_result(law_, p);
          if (!pending()) {
            finish_phase();
            return p;
          }
          integrator_->ignore_event(0);
          continue;
        }
        finish_phase();
        return p;
      }
    }
  }

  // The Sundman form from the impact to the delayed-recovery end (the only end asked for). Returns false,
  // with the result reset (and its steps kept in the statistics), where u reached 0 first: the end's dip of
  // the force factor around u = 0 was passed over in one step, and the phases in u and τ take over.
  bool sundman_phase() {
    form_ = Form::sundman;
    // dτ/ds = u^{q-1}: s in units of τ per u^{q-1} at x = length_scale.
    const double ds_per_dtau =
        law_.smoothing_root() / law_.dcompression_du(law_.smooth_variable(law_.length_scale()));
    PhaseSettings settings{Form::sundman, plan_.relative_tolerance_sundman, plan_.absolute_tolerance_sundman,
                           kSundmanStopPerTau * plan_.time_limit * ds_per_dtau};
    settings.max_steps = plan_.max_steps;
    settings.every_step = options_.keep_trajectory;
    const std::array<Event, 3> events{Event::max_compression, Event::delayed_recovery_end, Event::naive_end};
    std::swap(integrator_, sundman_);
    begin(settings, 0.0, {0.0, law_.initial_velocity(), 0.0, 0.0}, events.data(), 3);
    while (true) {
      const CvodeIntegrator::Step step = advance();
      const Point p = point_of(law_, Form::sundman, TauLog{}, step.t, step.state);
      if (step.reached_stop) {
        finish_phase();
        throw failure(fmt::format("no end of the collision before tau={:g}", p.tau / law_.time_scale()));
      }
      if (step.events_found[0]) {
        found_max_compression(p);
        integrator_->ignore_event(0);
      }
      if (step.events_found[1]) {
        result_.value[CollisionEnd::delayed_recovery] = end_result(law_, p);
        finish_phase();
        std::swap(integrator_, sundman_);
        return true;
      }
      if (step.events_found[2]) {
        finish_phase();
        std::swap(integrator_, sundman_);
        result_.max_compression_found = false;
        result_.value.trajectory.clear();
        if (options_.keep_trajectory) record({0.0, 0.0, law_.initial_velocity(), 0.0});
        return false;
      }
    }
  }

  void end_phase(const Point& b) {
    const Point c =
        compression_phase(law_.smooth_variable(b.x), 0.0, {b.tau, b.velocity, b.dissipation}, false);
    if (!pending()) return;
    // Reached u = 0: the naive end, exactly.
    const Point naive{c.tau, 0.0, c.velocity, c.dissipation};
    if (options_.ends.contains(CollisionEnd::naive))
      result_.value[CollisionEnd::naive] = end_result(law_, naive);
    if (options_.ends.contains(CollisionEnd::delayed_recovery) &&
        !result_.value[CollisionEnd::delayed_recovery]) {
      // The force factor ζx' + x^{a-b} reaches zero at x = (ζ|x'|)^{1/(a-b)} (natural units), which for tiny
      // ζ (below about 1e-295 for viscoelastic Hertz) lies within rounding of u = 0 where CVODE cannot
      // separate it from the naive end. The ends then differ in 1 - ε by a relative ζ^{(b+1)/(a-b)}
      // (ζ^{3/2} for Hertz): take the naive end's ε at that x.
      if (law_.damping() > law_.indistinguishable_ends_zeta()) {
        throw failure("no delayed-recovery end before the overlap vanished");
      }
      result_.value[CollisionEnd::delayed_recovery] = end_result(law_, naive);
      result_.value[CollisionEnd::delayed_recovery]->x = law_.force_zero_compression(naive.velocity);
    }
  }

  // Time form from τ0. With switch_x > 0 it hands over to the end phase once x < switch_x on the way back;
  // otherwise it watches the naive end itself.
  Point time_phase(Form form, double tau0, const State& state, double switch_x) {
    form_ = form;
    PhaseSettings settings{form, plan_.relative_tolerance, plan_.absolute_tolerance_time, plan_.time_limit};
    settings.switch_x = switch_x;
    settings.max_steps = plan_.max_steps;
    settings.every_step = options_.keep_trajectory;
    std::array<Event, kMaxEvents> events{};
    int count = 0;
    events[static_cast<std::size_t>(count++)] = Event::max_compression;
    // The delayed-recovery end is watched also where only the tail method needs it (to take over there).
    if ((options_.ends.contains(CollisionEnd::delayed_recovery) || tail_ != nullptr) &&
        !result_.value[CollisionEnd::delayed_recovery])
      events[static_cast<std::size_t>(count++)] = Event::delayed_recovery_end;
    if (switch_x > 0.0) {
      events[static_cast<std::size_t>(count++)] = Event::below_switch;
    } else if (options_.ends.contains(CollisionEnd::naive)) {
      events[static_cast<std::size_t>(count++)] = Event::naive_end;
    }
    if (watch_naive_end_exclusion()) events[static_cast<std::size_t>(count++)] = Event::naive_end_excluded;
    begin(settings, tau0, state, events.data(), count);
    while (true) {
      const CvodeIntegrator::Step step = advance();
      const Point p = point_of(law_, form, TauLog{}, step.t, step.state);
      if (step.reached_stop) {
        finish_phase();
        throw failure(fmt::format("no end of the collision before tau={:g}", p.tau / law_.time_scale()));
      }
      for (std::size_t i = 0; i < static_cast<std::size_t>(count); ++i) {
        if (!step.events_found[i]) continue;
        switch (events[i]) {
          case Event::max_compression:
            found_max_compression(p);
            integrator_->ignore_event(static_cast<int>(i));
            break;
          case Event::delayed_recovery_end:
            if (options_.ends.contains(CollisionEnd::delayed_recovery))
              result_.value[CollisionEnd::delayed_recovery] = end_result(law_, p);
            integrator_->ignore_event(static_cast<int>(i));
            if (tail_ != nullptr && pending()) {
              finish_phase();
              integrator_ = std::exchange(tail_, nullptr);
              // x' < 0 from here on (at x' = 0 the force would push it back), so the compression form
              // of the end can start right at this end.
              if (plan_.tail.coefficient != 0.0) return p;
              return time_phase(form, p.tau, step.state, switch_x);
            }
            break;
          case Event::naive_end:
            result_.value[CollisionEnd::naive] = end_result(law_, p);
            break;
          case Event::below_switch:
            finish_phase();
            return p;
          case Event::naive_end_excluded:
            no_naive_end(p);
          case Event::velocity_halved:
            break;
        }
      }
      if (!pending()) {
        finish_phase();
        return p;
      }
    }
  }

  const ContactLaw& law_;
  const SolveOptions& options_;
  const SolvePlan& plan_;
  CvodeIntegrator* integrator_;
  CvodeIntegrator* tail_;     // takes over at the delayed-recovery end (SolvePlan::tail_method)
  CvodeIntegrator* sundman_;  // runs SolvePlan::single_phase (4 components)
  Form form_ = Form::time;
  TauLog tau_log_;  // of the compression form's current phase
  Accumulated result_;
};

}  // namespace

CollisionResult run_collision(const ContactLaw& law, const SolveOptions& options, const SolvePlan& plan,
                              CvodeIntegrator& integrator, CvodeIntegrator* tail, CvodeIntegrator* sundman) {
  return CollisionRun(law, options, plan, integrator, tail, sundman).run();
}

}  // namespace restitution::detail
