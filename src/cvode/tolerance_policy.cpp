// SPDX-License-Identifier: BSD-3-Clause
#include "cvode/tolerance_policy.hpp"

#include <algorithm>
#include <cmath>

#include "cvode/cvode_engine.hpp"
#include "law/law_rhs.hpp"

namespace restitution::detail {
namespace {

// CVODE controls the local error per step; the global error of ε is larger. Measured over ζ in
// [1e-8, 1e4] and tolerances 1e-6 ... 1e-10 (docs/accuracy.md): with rtol = tolerance/500 the error of ε
// stays below a third of the tolerance.
constexpr double kLocalToGlobal = 0.002;

// BDF stops at order 5, where the global error grows like rtol^{5/6}: at a fixed local-to-global factor the
// error relative to T grows ~1.5x per decade of T (dense grid ζ in [0.09, 0.16], both ends: worst 0.47 T at
// T = 1e-9, 0.65 T at 1e-10, 0.9989 T at 1e-11, ζ = 0.0922, delayed-recovery end). Below
// kBdfCalibratedTolerance its factor shrinks as (T / kBdfCalibratedTolerance)^kBdfTightening, which brings
// the worst at T = 1e-11 to 0.55 T (tests/test_bdf_margin_slow.cpp); T >= 1e-10, the default, is unchanged.
// Adams (orders up to 9, error ~ rtol^{9/10}) keeps a factor of 2 without it.
constexpr double kBdfCalibratedTolerance = 1e-10;
constexpr double kBdfTightening = 0.3;

double local_to_global(Method method, double tolerance) {
  if (method != Method::bdf || tolerance >= kBdfCalibratedTolerance) return kLocalToGlobal;
  return kLocalToGlobal * std::pow(tolerance / kBdfCalibratedTolerance, kBdfTightening);
}

// Below this ζ the overdamped tail spans too few e-folds of u for its logarithm to pay (measured, naive end,
// T = 1e-10: 1449 instead of 1333 steps at ζ = 5.6, the same at 8.5, 1435 instead of 1499 at 10).
constexpr double kLogTailZeta = 9.0;

// The single Sundman phase watches the delayed-recovery end as a sign change of c_d x' + c_s x^{a-b} with
// x = u^q, which for an end at a small x is a narrow dip around u = 0 that one step can pass over; below
// this compression at the end (natural units, from the impact speed) the phases in u and τ are taken.
constexpr double kSinglePhaseEndCompression = 1e-4;

// The single Sundman phase loses less of ε's accuracy to its local errors than the phases in u and τ: with
// their tolerances its worst error on the reference grid (ζ in [1e-8, 1e4], T = 1e-4 ... 1e-11) was 0.089 T.
// It takes 4x their local tolerances: worst 0.22 T (with kSundmanStepGrowthThreshold), 9 % fewer steps on
// the 25 ζ in [1e-3, 1e3] at T = 1e-10 (docs/performance.md, eighth round).
constexpr double kSundmanToleranceGain = 4.0;

}  // namespace

SolvePlan plan_solve(const ContactLaw& law, const SolveOptions& options, double conditioning) {
  SolvePlan plan;
  const MethodChoice choice = choose_methods(law, options.method, options.ends);
  plan.method = choice.method;
  plan.tail_method = choice.tail;
  // The smooth variable u = x^{1/q} pays where the solution is not analytic in τ at x = 0 (q > 1).
  plan.smooth_ends = options.smooth_ends && law.smoothing_root() > 1;
  const ResolutionScales m = resolution_scales(law, options.ends);
  const double rtol = options.tolerance * local_to_global(plan.method, options.tolerance) *
                      law.conditioning(options.ends) * conditioning;
  plan.relative_tolerance = rtol;
  // Absolute tolerances in the law's own units: lengths scale with length_scale, velocities with v0,
  // times with time_scale, the dissipation integral ∫ w(x) x'^2 dτ with w(length) · v0^2 · time.
  const double floor = 1e-2 * rtol;
  const double x_atol = floor * m.x * law.length_scale();
  const double v_atol = floor * m.velocity * law.initial_velocity();
  const double i_atol = floor * m.dissipation * law.shape(law.length_scale()) * law.initial_velocity() *
                        law.initial_velocity() * law.time_scale();
  plan.absolute_tolerance_time = {x_atol, v_atol, i_atol};
  plan.absolute_tolerance_compression = {floor * law.time_scale(), v_atol, i_atol};
  plan.relative_tolerance_sundman = kSundmanToleranceGain * rtol;
  plan.absolute_tolerance_sundman = {floor * law.smooth_variable(m.x * law.length_scale()), v_atol, i_atol,
                                     floor * law.time_scale()};
  for (double& atol : plan.absolute_tolerance_sundman) atol *= kSundmanToleranceGain;
  // The delayed-recovery end alone, with Adams: one Sundman phase instead of three (u, τ, u) takes 253
  // instead of 299 steps per solve on the 25 reference ζ in [1e-3, 1e3] at T = 1e-10, with a smaller error
  // (docs/performance.md, sixth round). Not for BDF (no Jacobian for it), nor for an end so close to x = 0
  // that a step may pass over it (kSinglePhaseEndCompression; should u reach 0 all the same, the run starts
  // again in phases).
  plan.single_phase =
      plan.smooth_ends && plan.method == Method::adams && !plan.tail_method &&
      options.ends == EndSet{CollisionEnd::delayed_recovery} &&
      law.force_zero_compression(-law.initial_velocity()) >= kSinglePhaseEndCompression * law.length_scale();
  plan.time_limit = law.time_limit(options.ends);
  const double a = law.elastic_exponent();
  const double b = law.damping_exponent();
  if (plan.tail_method && plan.smooth_ends && a - b == 1.0 && law.naive_balance() > 0.0 &&
      law.zeta() >= kLogTailZeta) {
    // The overdamped tail of the naive end: x' ≈ -(c_s/c_d) x until x'', c_d x^b x' and c_s x^a balance at
    // the naive end's scale m.x (viscoelastic Hertz: x = ζ^{-4}), below which the overlap closes at a nearly
    // constant speed; so dτ/du = q u^{q-1}/x' ≈ -q (c_d/c_s)/(u + u*). With that logarithm taken out of τ
    // the tail after the delayed-recovery end takes 1139 steps at ζ = 100, T = 1e-10, against ~1570 in the
    // time form and then u (docs/performance.md).
    plan.tail.shift = law.smooth_variable(m.x * law.length_scale());
    plan.tail.coefficient = law.smoothing_root() * law.damping() / law.stiffness();
  }
  // The start phase ends where x' has halved, or at x = 1/2 (natural), whichever comes first.
  plan.start_phase_x = 0.5 * law.length_scale();
  plan.max_steps = options.max_steps_per_phase;
  return plan;
}

}  // namespace restitution::detail
