// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The naive ends of the scale-invariant members near critical damping (the dash-pot as r -> 1, Tsuji as
// ζ -> sqrt(5)) over a grid of parameters × tolerances × every engine: each request is either refused with
// InvalidInput or answered within T of the closed form ε = exp(-πζ/sqrt(4(b+1) - ζ²)), evaluated in
// __float128 at the double the solver received (near critical the condition number is ~1e6, so the decimal
// string and the double differ by more than T). The refusal boundary is checked on both sides against the
// condition number κ = πρ/(1-ρ²)^{3/2} computed independently here, also in __float128. A numerical failure
// (exit 1) counts as wrong: inside the accepted domain there must be none.
#include <gtest/gtest.h>
#include <quadmath.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <vector>

#include "cvode/tolerance_policy.hpp"
#include "restitution/collision_solver.hpp"
#include "restitution/errors.hpp"
#include "taylor/taylor_engine.hpp"

namespace restitution::conditioning_grid {

struct Counts {
  int answered = 0;
  int refused = 0;
  int outside_tolerance = 0;  // answered with |Δε| > T·min(ε, 1-ε)
  int failed = 0;             // NumericalFailure
  int wrong_side = 0;         // refused where the independent floor says deliverable, or the reverse
  double worst_ratio = 0.0;   // worst |Δε| / (T·min(ε, 1-ε)) among the answers
};

struct Exact {
  __float128 eps;
  __float128 condition;  // |d ln ε / d ln ζ|
};

// Closed form at the exact natural ζ of the law (ζ = 2r for the dash-pot: exact in double).
inline Exact exact_naive(const ContactLaw& law) {
  const __float128 zeta = law.zeta();
  const __float128 four_b1 = 4 * (static_cast<__float128>(law.damping_exponent()) + 1);
  const __float128 d = four_b1 - zeta * zeta;
  return {expq(-M_PIq * zeta / sqrtq(d)), M_PIq * four_b1 * zeta / (d * sqrtq(d))};
}

// The floors of check_solve_request, restated from the engines' measured constants.
// BDF's gain for bdf, Adams' for adams and auto (which resolves to Adams below ζ = 5, where these naive ends
// lie), the Taylor engine's for taylor.
inline double gain_of(Method method) {
  if (method == Method::taylor) return kTaylorRoundingGain;
  return method == Method::bdf ? detail::kBdfRoundingGain : detail::kAdamsRoundingGain;
}

inline bool deliverable(const Exact& exact, Method method, double tolerance) {
  const bool taylor = method == Method::taylor;
  const double gain = gain_of(method);
  const double smallest = taylor ? DBL_MIN : detail::kCvodeSmallestEps;
  if (tolerance < min_tolerance(method)) return false;
  if (exact.eps < static_cast<__float128>(smallest)) return false;
  return static_cast<__float128>(tolerance) >= gain * exact.condition * DBL_EPSILON;
}

// Within this relative distance of the floor the double and __float128 floors may decide differently.
inline bool near_boundary(const Exact& exact, Method method, double tolerance) {
  const bool taylor = method == Method::taylor;
  const double gain = gain_of(method);
  const double floor = gain * static_cast<double>(exact.condition) * DBL_EPSILON;
  const double smallest = taylor ? DBL_MIN : detail::kCvodeSmallestEps;
  return std::abs(tolerance / floor - 1.0) < 1e-6 ||
         std::abs(static_cast<double>(exact.eps / static_cast<__float128>(smallest)) - 1.0) < 1e-6;
}

// Parameters (r or ζ) approaching critical: critical · (1 - 10^{-k/(4 density)}), k over [2, 26] · density.
inline std::vector<double> approach(double critical, int density) {
  std::vector<double> out;
  for (int k = 2 * density; k <= 26 * density; ++k) {
    out.push_back(critical * (1.0 - std::pow(10.0, -static_cast<double>(k) / (4.0 * density))));
  }
  return out;
}

// Half decades from 1e-2 to 1e-13.
inline std::vector<double> tolerances() {
  std::vector<double> out;
  for (int k = 4; k <= 26; ++k) {
    const double t = std::pow(10.0, -static_cast<double>(k) / 2.0);
    if (t >= kSmallestTolerance * 0.999) out.push_back(t);
  }
  return out;
}

inline void check_one(CollisionSolver& solver, const ContactLaw& law, Method method, double tolerance,
                      Counts& counts) {
  const Exact exact = exact_naive(law);
  SolveOptions options;
  options.method = method;
  options.tolerance = tolerance;
  options.ends = EndSet{CollisionEnd::naive};
  const bool expected = deliverable(exact, method, tolerance);
  const bool ambiguous = near_boundary(exact, method, tolerance);
  try {
    const CollisionResult result = solver.solve(law, options);
    ++counts.answered;
    const EndResult& end = end_of(result, CollisionEnd::naive);
    const __float128 e = exact.eps;
    const __float128 scale = e < 1 - e ? e : 1 - e;
    const double ratio =
        static_cast<double>(fabsq(static_cast<__float128>(end.eps) - e) / (tolerance * scale));
    if (ratio > counts.worst_ratio) counts.worst_ratio = ratio;
    if (!(ratio <= 1.0)) {
      ++counts.outside_tolerance;
      ADD_FAILURE() << law_name(law.kind()) << " " << law.parameter_name() << "=" << law.parameter()
                    << " method " << method_name(method) << " T=" << tolerance << ": error " << ratio << " T";
    }
    if (!expected && !ambiguous) {
      ++counts.wrong_side;
      ADD_FAILURE() << "answered below the floor: " << law.parameter() << " " << method_name(method)
                    << " T=" << tolerance;
    }
  } catch (const InvalidInput& e) {
    ++counts.refused;
    if (expected && !ambiguous) {
      ++counts.wrong_side;
      ADD_FAILURE() << "refused above the floor: " << law.parameter() << " " << method_name(method)
                    << " T=" << tolerance << ": " << e.what();
    }
  } catch (const NumericalFailure& e) {
    ++counts.failed;
    ADD_FAILURE() << "numerical failure: " << law.parameter() << " " << method_name(method)
                  << " T=" << tolerance << ": " << e.what();
  }
}

// The whole grid: both members × their engines; `density` multiplies the points per decade of the distance
// to critical. Prints the counts (docs/accuracy.md quotes them).
inline Counts run_grid(int density) {
  Counts counts;
  CollisionSolver solver;
  const std::vector<double> tols = tolerances();
  for (const Method method : {Method::bdf, Method::adams, Method::automatic, Method::taylor}) {
    for (const double r : approach(1.0, density)) {
      const ContactLaw law = ContactLaw::linear_dashpot(r);
      for (const double t : tols) check_one(solver, law, method, t, counts);
    }
    if (method == Method::taylor) continue;  // Tsuji is not among the Taylor engine's members
    for (const double zeta : approach(std::sqrt(5.0), density)) {
      const ContactLaw law = ContactLaw::natural(LawKind::tsuji_hertz, zeta);
      for (const double t : tols) check_one(solver, law, method, t, counts);
    }
  }
  std::printf(
      "density %d: %d answered (worst %.3g T), %d refused, %d outside T, %d numerical failures, "
      "%d on the wrong side of the floor\n",
      density, counts.answered, counts.worst_ratio, counts.refused, counts.outside_tolerance, counts.failed,
      counts.wrong_side);
  return counts;
}

// The test of both programs: nothing outside T, no failure, every refusal on its side of the floor, and a
// grid that reaches both sides.
inline void expect_refused_or_within_tolerance(int density) {
  const Counts counts = run_grid(density);
  EXPECT_EQ(counts.outside_tolerance, 0);
  EXPECT_EQ(counts.failed, 0);
  EXPECT_EQ(counts.wrong_side, 0);
  EXPECT_GT(counts.answered, 100);
  EXPECT_GT(counts.refused, 100);
}

}  // namespace restitution::conditioning_grid
