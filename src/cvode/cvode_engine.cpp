// SPDX-License-Identifier: BSD-3-Clause
#include "cvode/cvode_engine.hpp"

#include <fmt/core.h>

#include "cvode/cvode_run.hpp"
#include "cvode/tolerance_policy.hpp"
#include "restitution/errors.hpp"

namespace restitution {

MethodChoice choose_methods(const ContactLaw& law, Method requested, EndSet ends) {
  if (requested != Method::automatic) return {requested, std::nullopt};
  // Measured (docs/accuracy.md): Adams is cheaper while the damping is weak, BDF once it makes the
  // problem stiff. Only the naive tail is stiff: up to the delayed-recovery end Adams takes 2-4x fewer
  // steps than BDF at every ζ up to 1e4, and resolves the fast decay of x' at orders up to 12 where BDF
  // stops at 5 (ζ = 100, naive end, T = 1e-10: 2131 instead of 3648 steps, the same error;
  // docs/performance.md). So BDF takes over at the delayed-recovery end while the naive end is pending.
  if (!ends.contains(CollisionEnd::naive) || law.parameter() < 5.0) return {Method::adams, std::nullopt};
  return {Method::adams, Method::bdf};
}

Method resolve_method(const ContactLaw& law, Method requested, EndSet ends) {
  const MethodChoice choice = choose_methods(law, requested, ends);
  return choice.tail.value_or(choice.method);
}

void CvodeEngine::check(const ContactLaw& law, const SolveOptions& options) const {
  check_solve_request(law, options, detail::cvode_rounding(law, options));
  if (options.method == Method::adams && options.ends.contains(CollisionEnd::naive) &&
      law.naive_end_existence() == NaiveEndExistence::always && law.zeta() > kAdamsNaiveZetaMax) {
    throw InvalidInput(fmt::format(
        "method adams computes the naive end only for zeta <= {:g}, got zeta={}: the overdamped tail after "
        "the delayed-recovery end is stiff (Adams needs ~ zeta^(5/3) steps, more than a million from zeta ~ "
        "2500); use --method auto (Adams up to the delayed-recovery end, then BDF) or bdf",
        kAdamsNaiveZetaMax, law.zeta()));
  }
}

detail::CvodeIntegrator& CvodeEngine::integrator(Method method) {
  if (!context_) context_.emplace();
  auto& slot = method == Method::adams ? adams_ : bdf_;
  if (!slot) slot.emplace(method, *context_);
  return *slot;
}

CollisionResult CvodeEngine::solve(const ContactLaw& law, const SolveOptions& options) {
  const auto run = [&](const detail::SolvePlan& plan) {
    detail::CvodeIntegrator& main = integrator(plan.method);  // makes the context
    detail::CvodeIntegrator* tail = plan.tail_method ? &integrator(*plan.tail_method) : nullptr;
    detail::CvodeIntegrator* sundman = nullptr;
    if (plan.single_phase) {
      if (!sundman_) sundman_.emplace(Method::adams, *context_, detail::state_size(detail::Form::sundman));
      sundman = &*sundman_;
    }
    return detail::run_collision(law, options, plan, main, tail, sundman);
  };
  check(law, options);  // the one check of the request: the plans below trust it
  const detail::SolvePlan plan = detail::plan_solve(law, options);
  CollisionResult result = run(plan);
  // A naive end whose conditioning only the solve reveals (constant damping close to the largest ζ with a
  // naive end): solve again with CVODE's local tolerances tightened accordingly.
  const auto& naive = result[CollisionEnd::naive];
  const double conditioning = naive ? law.naive_end_conditioning(naive->eps) : 1.0;
  if (conditioning >= 1.0) return result;
  const detail::SolvePlan refined = detail::plan_solve(law, options, conditioning);
  if (refined.relative_tolerance < detail::kSmallestRelativeTolerance) {
    throw InvalidInput(fmt::format(
        "the naive end of natural {} at zeta={} (eps ~ {:.2g}: close to the largest zeta with a naive end, "
        "docs/contact_laws.md) is delivered only to tolerance >= {:.2g}, got {:g}",
        law_name(law.kind()), law.zeta(), naive->eps,
        options.tolerance * detail::kSmallestRelativeTolerance / refined.relative_tolerance,
        options.tolerance));
  }
  CollisionResult second = run(refined);
  second.stats += result.stats;
  return second;
}

}  // namespace restitution
