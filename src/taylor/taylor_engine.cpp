// SPDX-License-Identifier: BSD-3-Clause
#include "taylor/taylor_engine.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "law/law_rhs.hpp"
#include "restitution/errors.hpp"
#include "taylor/taylor_collision.hpp"

namespace restitution {
namespace {

// The local truncation error per step is the requested tolerance times this factor. The order is 8 above
// Jorba & Zou's p = -ln(tol)/2 + 1: steps here are limited by singularities just outside the phases
// (x' = 0, u = 0) and, for large ζ, by the fast relaxation, so the larger step of a higher order pays for
// its O(p²) cost (measured: 2x fewer steps, 30% less time at T = 1e-12). Both measured against the reference
// solutions over ζ in [1e-8, 1e4] (docs/accuracy.md, tests/test_taylor_engine.cpp).
constexpr double kLocalFactor = 0.03;
constexpr int kExtraOrder = 8;
constexpr double kSmallestLocalTolerance = 1e-17;

taylor::TaylorSettings settings_for(const ContactLaw& law, const SolveOptions& options) {
  taylor::TaylorSettings s;
  s.tolerance = std::max(options.tolerance * kLocalFactor, kSmallestLocalTolerance);
  if (law.kind() == LawKind::viscoelastic_hertz && law.parameter() > 1.0) {
    // Large ζ: after the delayed-recovery end the force factor ζx' + x stays within ~ζ^{-5/3} x of zero
    // (x' relaxes onto -x/ζ), so a looser local error could keep it positive and miss the end.
    s.tolerance = std::min(s.tolerance, 1e-3 * std::pow(law.parameter(), -5.0 / 3.0));
  }
  s.order = std::clamp(static_cast<int>(std::ceil(-0.5 * std::log(s.tolerance))) + 1 + kExtraOrder, 6,
                       taylor::kMaxOrder);
  s.ends = options.ends;
  s.max_steps = options.max_steps_per_phase;  // bounds the whole solve, more strictly than per phase
  const double p = law.parameter();
  const double z = std::max(p, 1.0);
  if (law.kind() == LawKind::viscoelastic_hertz) {
    // Scales of what decides the result (the law's, as in the CVODE tolerance policy): for large ζ the
    // delayed end has ε ~ ζ^{-5/3} at x ~ ζ^{-2/3}, the naive end ε ~ ζ^{-5} reached through x ~ ζ^{-4}.
    const ResolutionScales m = resolution_scales(law, options.ends);
    s.compression_floor = {1e-2, 1e-2 * m.velocity, 1e-2 / z};
    s.time_floor = {1e-2 * std::sqrt(m.x), 1e-2 * m.velocity, 1e-2 / z};
    // Below u ~ 1/ζ² the damping no longer dominates and the compression form is not stiff; above it,
    // for large ζ, the slow tail stays in the time form.
    s.end_switch_u_max = 1.0 / (z * z);
    s.time_limit = 1000.0 * (1.0 + p) * (1.0 + std::log1p(p));
  } else {
    double velocity = p > 1.0 ? 1.0 / (4.0 * p * p) : 1.0;
    double x = p > 1.0 ? 0.5 / p : 1.0;
    if (options.ends.contains(CollisionEnd::naive) && p < 1.0) {
      // The naive end is approached with x ~ ε (τ_c - τ), ε = exp(-πr/ω) (3e-31 at r = 0.999), and the two
      // modes cancel there to 1/ω: resolve x and x' on ε's scale and tighten the step error by ω/10 (as the
      // CVODE tolerance policy does).
      const double omega = std::sqrt(1.0 - p * p);
      const double eps = std::exp(-M_PI * p / omega);
      velocity = std::min(velocity, eps);
      x = std::min(x, eps);
      s.tolerance = std::max(s.tolerance * std::min(1.0, 0.1 * omega), kSmallestLocalTolerance);
    }
    s.time_floor = {1e-2 * x, 1e-2 * velocity, 1e-2 / z};
    s.time_limit = 1000.0 * (1.0 + p);
  }
  return s;
}

EndResult end_result(const ContactLaw& law, const taylor::TaylorPoint<double>& p) {
  const double damping = law.damping();
  const double x = std::max(p.x, 0.0);
  const EndValues values = law.end_values(x, p.y, p.dissipation);
  EndResult end;
  end.eps = values.eps;
  end.one_minus_eps = values.one_minus_eps;
  end.tau = p.tau;
  end.x = x;
  end.velocity = p.y;
  end.dissipated_energy = damping * p.dissipation;
  return end;
}

}  // namespace

void TaylorEngine::check(const ContactLaw& law, const SolveOptions& options) const {
  check_solve_request(law, options, {method_name(Method::taylor), kTaylorRoundingGain, 0.0, ""});
  if (options.keep_trajectory) {
    throw InvalidInput("method taylor does not record trajectories: use --method bdf or adams");
  }
  if (law.kind() != LawKind::viscoelastic_hertz && law.kind() != LawKind::linear_dashpot) {
    throw InvalidInput(fmt::format(
        "method taylor does not support law {}: its recurrences cover viscoelastic-hertz and linear-dashpot; "
        "use the default method (auto) or bdf/adams",
        law_name(law.kind())));
  }
  const bool hertz = law.kind() == LawKind::viscoelastic_hertz;
  if (hertz && options.ends.contains(CollisionEnd::naive) && law.parameter() > kTaylorNaiveZetaMax) {
    throw InvalidInput(
        fmt::format("method taylor computes the naive end only for zeta <= {:g} (the overdamped naive tail "
                    "is stiff), got "
                    "zeta={}: use --method bdf",
                    kTaylorNaiveZetaMax, law.parameter()));
  }
}

CollisionResult TaylorEngine::solve(const ContactLaw& law, const SolveOptions& options) {
  check(law, options);
  const bool hertz = law.kind() == LawKind::viscoelastic_hertz;
  taylor::TaylorCollision<double> run(settings_for(law, options), law.parameter());
  taylor::TaylorOutcome<double> out;
  try {
    out = hertz ? run.hertz(law.zeta()) : run.dashpot(law.damping(), law.stiffness());
  } catch (const NumericalFailure& e) {
    throw NumericalFailure(fmt::format(
        "the integration failed for law {} at {}={}, tolerance {:g}, method taylor: {}; try a larger "
        "tolerance or the default method (auto)",
        law_name(law.kind()), law.parameter_name(), law.parameter(), options.tolerance, e.what()));
  }
  CollisionResult result;
  result.law = law.kind();
  result.parameter = law.parameter();
  result.speed_independent = law.speed_independent();
  result.tolerance = options.tolerance;
  result.method = Method::taylor;
  result.max_compression = {out.tau_max, out.x_max};
  for (const CollisionEnd end : kCollisionEnds) {
    if (out.ends[end]) result[end] = end_result(law, *out.ends[end]);
  }
  // One Taylor expansion per step: counted as the engine's right-hand-side evaluations (each costs O(p²)).
  result.stats.steps = out.steps;
  result.stats.rhs_evaluations = out.steps;
  return result;
}

}  // namespace restitution
