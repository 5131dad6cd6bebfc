#include "restitution/collision_solver.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "core/cvode_integrator.hpp"
#include "core/tolerance_policy.hpp"
#include "restitution/errors.hpp"
#include "taylor/taylor_engine.hpp"

namespace restitution {

using detail::CvodeIntegrator;
using detail::Event;
using detail::Form;
using detail::State;

const char* method_name(Method method) {
  switch (method) {
    case Method::bdf:
      return "bdf";
    case Method::adams:
      return "adams";
    case Method::automatic:
      return "auto";
    case Method::taylor:
      return "taylor";
  }
  return "?";
}

Method method_from_name(const std::string& name) {
  for (const Method method : {Method::bdf, Method::adams, Method::automatic, Method::taylor}) {
    if (name == method_name(method)) return method;
  }
  throw InvalidInput(fmt::format("method must be bdf, adams, auto or taylor, got '{}'", name));
}

const char* end_name(CollisionEnd end) {
  return end == CollisionEnd::naive ? "naive" : "delayed-recovery";
}

const char* end_key(CollisionEnd end) {
  return end == CollisionEnd::naive ? "naive" : "delayed_recovery";
}

CollisionEnd end_from_name(const std::string& name) {
  if (name == "naive") return CollisionEnd::naive;
  if (name == "delayed-recovery") return CollisionEnd::delayed_recovery;
  throw InvalidInput(fmt::format("end must be naive or delayed-recovery, got '{}'", name));
}

const EndResult& end_of(const CollisionResult& result, CollisionEnd end) {
  const auto& value = result[end];
  if (!value) throw NumericalFailure(fmt::format("no {} end at zeta={}", end_name(end), result.parameter));
  return *value;
}

SolverStats& operator+=(SolverStats& total, const SolverStats& more) {
  total.steps += more.steps;
  total.rhs_evaluations += more.rhs_evaluations;
  total.jacobian_evaluations += more.jacobian_evaluations;
  total.root_evaluations += more.root_evaluations;
  total.error_test_failures += more.error_test_failures;
  total.convergence_failures += more.convergence_failures;
  return total;
}

double min_tolerance(Method method) {
  return method == Method::taylor ? kMinTaylorTolerance : kMinTolerance;
}

Method resolve_method(const ContactLaw& law, Method requested, EndSet ends) {
  if (requested != Method::automatic) return requested;
  // Measured (docs/accuracy.md): Adams is cheaper while the damping is weak, BDF once it makes the
  // problem stiff. Only the naive tail is stiff: up to the delayed-recovery end Adams takes 2-4x fewer
  // steps than BDF at every ζ up to 1e4.
  if (!ends.contains(CollisionEnd::naive)) return Method::adams;
  return law.parameter < 5.0 ? Method::adams : Method::bdf;
}

struct CollisionSolver::Impl {
  sundials::Context context;
  std::optional<CvodeIntegrator> bdf;
  std::optional<CvodeIntegrator> adams;

  CvodeIntegrator& integrator(Method method) {
    auto& slot = method == Method::adams ? adams : bdf;
    if (!slot) slot.emplace(method, context);
    return *slot;
  }
};

CollisionSolver::CollisionSolver() : impl_(std::make_unique<Impl>()) {}
CollisionSolver::~CollisionSolver() = default;
CollisionSolver::CollisionSolver(CollisionSolver&&) noexcept = default;
CollisionSolver& CollisionSolver::operator=(CollisionSolver&&) noexcept = default;

namespace {

// Below this ζ the two ends differ in 1 - ε by less than 1e-30 relative (see end_phase).
constexpr double kIndistinguishableEndsZeta = 1e-20;

// A point of the trajectory in the law's own units, whatever form produced it.
struct Point {
  double tau, x, velocity, dissipation;
};

Point point_of(Form form, double t, const State& s) {
  if (form == Form::time) return {t, s[detail::kFirst], s[detail::kVelocity], s[detail::kDissipation]};
  return {s[detail::kFirst], t * t, s[detail::kVelocity], s[detail::kDissipation]};
}

const char* end_names(EndSet ends) {
  if (ends == EndSet::both()) return "both ends";
  return ends.contains(CollisionEnd::naive) ? "the naive end" : "the delayed-recovery end";
}

// ε from the velocity at the end, 1-ε from the energy balance 1-ε^2 = 2(D + U(x_end))/v0^2, which keeps
// full relative accuracy as ε -> 1; each is reported from the form that is accurate in its regime.
EndResult end_result(const ContactLaw& law, const Point& p) {
  EndResult end;
  const double v0 = law.initial_velocity;
  const double eps_from_velocity = -p.velocity / v0;
  const double x = std::max(p.x, 0.0);  // a root located a rounding error past x = 0
  const double one_minus_eps_squared =
      2.0 * (law.damping * p.dissipation + law.elastic_energy(x)) / (v0 * v0);
  if (eps_from_velocity > 0.5) {
    end.one_minus_eps = one_minus_eps_squared / (1.0 + eps_from_velocity);
    end.eps = 1.0 - end.one_minus_eps;
  } else {
    end.eps = eps_from_velocity;
    end.one_minus_eps = 1.0 - eps_from_velocity;
  }
  end.tau = p.tau / law.time_scale;
  end.x = x / law.length_scale;
  end.velocity = p.velocity / v0;
  end.dissipated_energy = law.damping * p.dissipation / (v0 * v0);
  return end;
}

// Runs the phases of one collision on one integrator and collects what was asked for.
class CollisionRun {
 public:
  CollisionRun(const ContactLaw& law, const SolveOptions& options, const detail::SolvePlan& plan,
               CvodeIntegrator& integrator)
      : law_(law), options_(options), plan_(plan), integrator_(integrator) {
    result_.value.law = law.kind;
    result_.value.parameter = law.parameter;
    result_.value.tolerance = options.tolerance;
    result_.value.method = plan.method;
  }

  CollisionResult run() {
    const State start{0.0, law_.initial_velocity, 0.0};
    if (options_.keep_trajectory) record({0.0, 0.0, law_.initial_velocity, 0.0});
    if (!plan_.smooth_ends) {
      time_phase(Form::time, 0.0, start, /*switch_x=*/-1.0);
    } else {
      // Start: u from 0 until x' has halved (or x = start_phase_x); then τ around maximal compression
      // until x falls below 0.9 times the compression where the start phase ended; then u down to 0.
      const Point a = compression_phase(0.0, std::sqrt(plan_.start_phase_x), start, true);
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
    const char* parameter = law_.kind == LawKind::viscoelastic_hertz ? "zeta" : "damping-ratio";
    return NumericalFailure{
        fmt::format("{} (law {}, {}={}, {}, tolerance {:g}, method {})", what, law_name(law_.kind), parameter,
                    law_.parameter, end_names(options_.ends), options_.tolerance, method_name(plan_.method))};
  }

  void record(const Point& p) {
    result_.value.trajectory.push_back(
        {p.tau / law_.time_scale, p.x / law_.length_scale, p.velocity / law_.initial_velocity,
         law_.acceleration(p.x, p.velocity) * law_.time_scale / law_.initial_velocity});
  }

  void begin(const detail::PhaseSettings& settings, double t0, const State& state, const Event* events,
             int count) {
    try {
      integrator_.start(law_, settings, t0, state, events, count);
    } catch (const NumericalFailure& e) {
      throw failure(e.what());
    }
  }

  CvodeIntegrator::Step advance() {
    try {
      CvodeIntegrator::Step step = integrator_.advance();
      if (options_.keep_trajectory) record(point_of(form_, step.t, step.state));
      return step;
    } catch (const NumericalFailure& e) {
      result_.value.stats += integrator_.phase_stats();
      throw failure(e.what());
    }
  }

  void finish_phase() { result_.value.stats += integrator_.phase_stats(); }

  void found_max_compression(const Point& p) {
    if (result_.max_compression_found) return;
    result_.value.max_compression = {p.tau / law_.time_scale, p.x / law_.length_scale};
    result_.max_compression_found = true;
  }

  // Compression form from u0 towards u_stop. Going up (the start) it stops where x' has halved; going
  // down (the end) it watches the delayed-recovery end and reaches the naive end exactly at u = 0.
  Point compression_phase(double u0, double u_stop, const State& state, bool is_start) {
    form_ = Form::compression;
    detail::PhaseSettings settings{Form::compression, plan_.relative_tolerance,
                                   plan_.absolute_tolerance_compression, u_stop};
    settings.max_steps = plan_.max_steps;
    settings.every_step = options_.keep_trajectory;
    std::array<Event, detail::kMaxEvents> events{};
    int count = 0;
    if (is_start) {
      events[static_cast<std::size_t>(count++)] = Event::velocity_halved;
    } else if (options_.ends.contains(CollisionEnd::delayed_recovery) &&
               !result_.value[CollisionEnd::delayed_recovery]) {
      events[static_cast<std::size_t>(count++)] = Event::delayed_recovery_end;
    }
    begin(settings, u0, state, events.data(), count);
    while (true) {
      const CvodeIntegrator::Step step = advance();
      const Point p = point_of(Form::compression, step.t, step.state);
      if (step.reached_stop || step.events_found[0]) {
        if (!is_start && step.events_found[0]) {
          result_.value[CollisionEnd::delayed_recovery] = end_result(law_, p);
          if (!pending()) {
            finish_phase();
            return p;
          }
          integrator_.ignore_event(0);
          continue;
        }
        finish_phase();
        return p;
      }
    }
  }

  void end_phase(const Point& b) {
    const Point c = compression_phase(std::sqrt(b.x), 0.0, {b.tau, b.velocity, b.dissipation}, false);
    if (!pending()) return;
    // Reached u = 0: the naive end, exactly.
    const Point naive{c.tau, 0.0, c.velocity, c.dissipation};
    if (options_.ends.contains(CollisionEnd::naive))
      result_.value[CollisionEnd::naive] = end_result(law_, naive);
    if (options_.ends.contains(CollisionEnd::delayed_recovery) &&
        !result_.value[CollisionEnd::delayed_recovery]) {
      // The force factor ζx' + x reaches zero at x ≈ ζ|x'| (natural units), which for ζ below about 1e-295
      // lies within rounding of u = 0 where CVODE cannot separate it from the naive end. The ends then
      // differ in 1 - ε by a relative O(ζ^{3/2}): take the naive end's ε at x = ζ|x'|.
      if (law_.damping > kIndistinguishableEndsZeta || law_.kind != LawKind::viscoelastic_hertz) {
        throw failure("no delayed-recovery end before the overlap vanished");
      }
      result_.value[CollisionEnd::delayed_recovery] = end_result(law_, naive);
      result_.value[CollisionEnd::delayed_recovery]->x = law_.damping * -naive.velocity;
    }
  }

  // Time form from τ0. With switch_x > 0 it hands over to the end phase once x < switch_x on the way back;
  // otherwise it watches the naive end itself.
  Point time_phase(Form form, double tau0, const State& state, double switch_x) {
    form_ = form;
    detail::PhaseSettings settings{form, plan_.relative_tolerance, plan_.absolute_tolerance_time,
                                   plan_.time_limit};
    settings.switch_x = switch_x;
    settings.max_steps = plan_.max_steps;
    settings.every_step = options_.keep_trajectory;
    std::array<Event, detail::kMaxEvents> events{};
    int count = 0;
    events[static_cast<std::size_t>(count++)] = Event::max_compression;
    if (options_.ends.contains(CollisionEnd::delayed_recovery))
      events[static_cast<std::size_t>(count++)] = Event::delayed_recovery_end;
    if (switch_x > 0.0) {
      events[static_cast<std::size_t>(count++)] = Event::below_switch;
    } else if (options_.ends.contains(CollisionEnd::naive)) {
      events[static_cast<std::size_t>(count++)] = Event::naive_end;
    }
    begin(settings, tau0, state, events.data(), count);
    while (true) {
      const CvodeIntegrator::Step step = advance();
      const Point p = point_of(form, step.t, step.state);
      if (step.reached_stop) {
        finish_phase();
        throw failure(fmt::format("no end of the collision before tau={:g}", p.tau / law_.time_scale));
      }
      for (std::size_t i = 0; i < static_cast<std::size_t>(count); ++i) {
        if (!step.events_found[i]) continue;
        switch (events[i]) {
          case Event::max_compression:
            found_max_compression(p);
            integrator_.ignore_event(static_cast<int>(i));
            break;
          case Event::delayed_recovery_end:
            result_.value[CollisionEnd::delayed_recovery] = end_result(law_, p);
            integrator_.ignore_event(static_cast<int>(i));
            break;
          case Event::naive_end:
            result_.value[CollisionEnd::naive] = end_result(law_, p);
            break;
          case Event::below_switch:
            finish_phase();
            return p;
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
  const detail::SolvePlan& plan_;
  CvodeIntegrator& integrator_;
  Form form_ = Form::time;
  Accumulated result_;
};

}  // namespace

void check_solvable(const ContactLaw& law, const SolveOptions& options) {
  if (options.method == Method::taylor) {
    check_taylor_request(law, options);
  } else {
    check_solve_request(law, options);
  }
}

CollisionResult CollisionSolver::solve(const ContactLaw& given, const SolveOptions& options) {
  // Every result is reported in natural units, and a Hertz law depends only on ζ: integrate the natural
  // form, whose magnitudes are of order one, rather than the (β, v) form, whose lengths and velocities
  // (v^{4/5}) under- or overflow the absolute tolerances at extreme speeds (v = 1e-150 m/s).
  // Only a well-formed (β, v) law is converted; a hand-made one (tests of failures) is integrated as given.
  const bool scaled = given.kind == LawKind::viscoelastic_hertz && given.initial_velocity != 1.0 &&
                      given.time_scale == 1.0 && std::isfinite(given.damping) &&
                      std::isfinite(given.stiffness) && std::isfinite(given.initial_velocity) &&
                      std::isfinite(given.parameter);
  const ContactLaw law = scaled ? ContactLaw::hertz_natural(given.parameter) : given;
  if (options.method == Method::taylor) return solve_with_taylor(law, options);
  const detail::SolvePlan plan = detail::plan_solve(law, options);
  return CollisionRun(law, options, plan, impl_->integrator(plan.method)).run();
}

}  // namespace restitution
