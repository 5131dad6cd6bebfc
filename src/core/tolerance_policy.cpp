#include "core/tolerance_policy.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "restitution/errors.hpp"

namespace restitution {

void check_solve_options(const SolveOptions& options) {
  const double tol = options.tolerance;
  if (!std::isfinite(tol) || tol < kSmallestTolerance || tol > kMaxTolerance) {
    throw InvalidInput(
        fmt::format("tolerance must lie in [{:g}, {:g}], got {}", kSmallestTolerance, kMaxTolerance, tol));
  }
  const double smallest = min_tolerance(options.method);
  if (tol < smallest) {
    throw InvalidInput(fmt::format(
        "tolerance {:g} is below what the {} engine can deliver ({:g}): double-precision round-off in its "
        "steps limits the accuracy of eps; ask for a tolerance >= {:g}",
        tol, options.method == Method::taylor ? "Taylor" : "CVODE", smallest, smallest));
  }
  if (options.max_steps_per_phase < 1) {
    throw InvalidInput(fmt::format("max_steps_per_phase must be >= 1, got {}", options.max_steps_per_phase));
  }
  if (!options.ends.contains(CollisionEnd::naive) && !options.ends.contains(CollisionEnd::delayed_recovery)) {
    throw InvalidInput("no end of the collision requested: ask for naive, delayed-recovery or both");
  }
}

}  // namespace restitution

namespace restitution::detail {
namespace {

// CVODE controls the local error per step; the global error of ε is larger. Measured over ζ in
// [1e-8, 1e4] and tolerances 1e-6 ... 1e-10 (docs/accuracy.md): with rtol = tolerance/500 the error of ε
// stays below a third of the tolerance.
constexpr double kLocalToGlobal = 0.002;

// Natural-scale magnitudes (x'(0) = 1) of the smallest compression, velocity and dissipation integral
// that decide the requested results, so that absolute tolerances follow what is measured.
struct Magnitudes {
  double x = 1.0;
  double velocity = 1.0;
  double dissipation = 1.0;
};

Magnitudes hertz_magnitudes(double zeta, const EndSet& ends) {
  Magnitudes m;
  const double z = std::max(zeta, 1.0);
  // Large ζ: x_max ~ (3/(2ζ))^{2/3}; the delayed end has ε ~ ζ^{-5/3}; the naive end is reached through
  // x ~ ζ^{-4} with ε ~ ζ^{-5} (docs/design.md §4).
  m.x = std::pow(z, -2.0 / 3.0);
  m.velocity = std::pow(z, -5.0 / 3.0);
  if (ends.contains(CollisionEnd::naive)) {
    m.x = std::pow(z, -4.0);
    m.velocity = std::pow(z, -5.0);
  }
  m.dissipation = 1.0 / z;
  return m;
}

Magnitudes dashpot_magnitudes(double r, const EndSet& ends) {
  Magnitudes m;
  if (r > 1.0) {
    // Overdamped: x_max ~ 1/(2r) and, at the delayed-recovery end, ε ~ 1/(4 r^2) for large r.
    m.x = 1.0 / (2.0 * r);
    m.velocity = 1.0 / (4.0 * r * r);
  }
  if (ends.contains(CollisionEnd::naive) && r < 1.0) {
    // The naive end is approached with x ~ ε (τ_c - τ): near critical damping (ε ~ 1e-31 at r = 0.999)
    // x must be resolved down to ε's scale, not to one.
    const double eps = std::exp(-M_PI * r / std::sqrt(1.0 - r * r));
    m.velocity = std::min(m.velocity, eps);
    m.x = std::min(m.x, eps);
  }
  m.dissipation = 1.0 / std::max(1.0, r);
  return m;
}

// Near critical damping the dash-pot's two modes e^{(-r ± iω)τ} are each 1/(2ω) times larger than x'
// at the naive end, where they cancel (ω = sqrt(1 - r²)): the local errors are amplified by about 1/ω in
// ε there (measured error ratio 10 at r = 0.999 and 20 at r = 0.9999 with the plain rtol).
double conditioning(const ContactLaw& law, const EndSet& ends) {
  const double r = law.parameter;
  if (law.kind != LawKind::linear_dashpot || !ends.contains(CollisionEnd::naive) || r >= 1.0) return 1.0;
  return std::min(1.0, 0.1 * std::sqrt(1.0 - r * r));
}

double time_limit(const ContactLaw& law, const EndSet& ends) {
  if (law.kind == LawKind::linear_dashpot) {
    const double r = law.parameter;
    return (ends.contains(CollisionEnd::naive) && r < 1.0) ? 100.0 * (10.0 + M_PI / std::sqrt(1.0 - r * r))
                                                           : 1000.0;
  }
  // Naive tail: slow relaxation over ~ζ·ln(ζ^{10/3}) (docs/design.md §4); generous margin.
  const double zeta = law.parameter;
  return law.time_scale * 1000.0 * (1.0 + zeta) * (1.0 + std::log1p(zeta));
}

}  // namespace

SolvePlan plan_solve(const ContactLaw& law, const SolveOptions& options) {
  check_solve_request(law, options);
  SolvePlan plan;
  plan.method = resolve_method(law, options.method, options.ends);
  plan.smooth_ends = options.smooth_ends && law.kind == LawKind::viscoelastic_hertz;
  const Magnitudes m = law.kind == LawKind::viscoelastic_hertz
                           ? hertz_magnitudes(law.parameter, options.ends)
                           : dashpot_magnitudes(law.parameter, options.ends);
  const double rtol = options.tolerance * kLocalToGlobal * conditioning(law, options.ends);
  plan.relative_tolerance = rtol;
  // Absolute tolerances in the law's own units: lengths scale with length_scale, velocities with v0,
  // times with time_scale, the dissipation integral ∫ w(x) x'^2 dτ with w(length) · v0^2 · time.
  const double floor = 1e-2 * rtol;
  const double x_atol = floor * m.x * law.length_scale;
  const double v_atol = floor * m.velocity * law.initial_velocity;
  const double i_atol = floor * m.dissipation * law.shape(law.length_scale) * law.initial_velocity *
                        law.initial_velocity * law.time_scale;
  plan.absolute_tolerance_time = {x_atol, v_atol, i_atol};
  plan.absolute_tolerance_compression = {floor * law.time_scale, v_atol, i_atol};
  plan.time_limit = time_limit(law, options.ends);
  // The start phase ends where x' has halved, or at x = 1/2 (natural), whichever comes first.
  plan.start_phase_x = 0.5 * law.length_scale;
  plan.max_steps = options.max_steps_per_phase;
  return plan;
}

}  // namespace restitution::detail
