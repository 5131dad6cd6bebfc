// SPDX-License-Identifier: BSD-3-Clause
// Certification of the committed fast tables (src/fast/fast_table.h) against an independent engine: the
// double-precision Taylor engine at its tightest tolerance (1e-13) on 10^5 random ζ, log-uniform and
// stratified so that every interval of both tables, the series below them and the asymptotic laws above them
// are hit, plus every interval boundary. Both ends (the naive end where the Taylor engine computes it,
// ζ <= 100); the durations and the maximal compression on the same points. The naive end above ζ = 100:
// fresh __float128 reference solves at random ζ ∈ (100, 500] and CVODE at its tightest tolerance on random
// ζ ∈ (100, 1e5].
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "reference/reference_solution.hpp"
#include "restitution/fast.hpp"
#include "taylor/taylor_engine.hpp"

namespace {

using namespace restitution;

// The table's contract itself: the two agree to 1.3e-14 on these points, so the engine's own error (bounded
// by its tolerance, 1e-13) leaves room for none of the table's beyond it.
constexpr double kAllowed = 1e-13;
// τ_c, x_max, τ_max against the same engine: its tolerance controls ε, not these, and its τ_c is off by up
// to 1.3e-7 (ζ ≈ 1e6; the table agrees with the reference there to 3e-16): a sanity check only, the
// certification of these is DurationsAgainstTheReference.
constexpr double kDurationAllowed = 1e-6;

double relative(double value, double exact) {
  return std::abs(value - exact) / exact;
}

std::vector<double> certification_points() {
  const double s_lo = std::log(1e-12), s_hi = std::log(1e6);
  const int count = 100000;
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> zeta;
  for (int k = 0; k < count; ++k) zeta.push_back(std::exp(s_lo + (k + unit(rng)) * (s_hi - s_lo) / count));
  // Every interval boundary of the tables (and the switch points), approached from both sides.
  for (double s = -19.0; s <= 12.0; s += 0.125)  // also the naive duration table's end, e^6
    for (const double side : {-1.0, 1.0}) zeta.push_back(std::nextafter(std::exp(s), side * 1e300));
  return zeta;
}

struct Worst {
  double error = 0, zeta = 0;
  void update(double e, double z) {
    if (e > error) error = e, zeta = z;
  }
};

TEST(FastCertification, AgreesWithTheTaylorEngineOnRandomZeta) {
  SolveOptions options;
  options.tolerance = kMinTaylorTolerance;
  options.method = Method::taylor;
  Worst worst_naive, worst_delayed, worst_duration;
  long naive_points = 0, delayed_points = 0;
  TaylorEngine taylor;
  for (const double zeta : certification_points()) {
    options.ends = zeta <= kTaylorNaiveZetaMax ? EndSet::both() : EndSet{CollisionEnd::delayed_recovery};
    const CollisionResult r = taylor.solve(ContactLaw::hertz_natural(zeta), options);
    const auto check = [&](const EndResult& end, CollisionEnd which, Worst& worst) {
      const double e = std::max(relative(fast::eps(zeta, which), end.eps),
                                relative(fast::one_minus_eps(zeta, which), end.one_minus_eps));
      worst.update(e, zeta);
      ASSERT_LE(e, kAllowed) << end_name(which) << " at zeta " << zeta;
    };
    const auto& delayed = *r[CollisionEnd::delayed_recovery];
    check(delayed, CollisionEnd::delayed_recovery, worst_delayed);
    const MaxCompression m = fast::max_compression(zeta);
    for (const double e :
         {relative(fast::collision_duration(zeta, CollisionEnd::delayed_recovery), delayed.tau),
          relative(m.x, r.max_compression.x), relative(m.tau, r.max_compression.tau)}) {
      worst_duration.update(e, zeta);
      ASSERT_LE(e, kDurationAllowed) << "tau_c, x_max or tau_max at zeta " << zeta;
    }
    ++delayed_points;
    if (r[CollisionEnd::naive]) {
      check(*r[CollisionEnd::naive], CollisionEnd::naive, worst_naive);
      const double e =
          relative(fast::collision_duration(zeta, CollisionEnd::naive), r[CollisionEnd::naive]->tau);
      worst_duration.update(e, zeta);
      ASSERT_LE(e, kDurationAllowed) << "naive tau_c at zeta " << zeta;
      ++naive_points;
    }
  }
  RecordProperty("naive_points", std::to_string(naive_points));
  RecordProperty("delayed_points", std::to_string(delayed_points));
  std::printf(
      "naive: %ld points, worst %.3g at zeta %.6g; delayed recovery: %ld points, worst %.3g at zeta %.6g; "
      "tau_c, x_max, tau_max: worst %.3g at zeta %.6g\n",
      naive_points, worst_naive.error, worst_naive.zeta, delayed_points, worst_delayed.error,
      worst_delayed.zeta, worst_duration.error, worst_duration.zeta);
}

std::vector<double> log_uniform(double lo, double hi, int count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> s(std::log(lo), std::log(hi));
  std::vector<double> zeta(static_cast<std::size_t>(count));
  for (double& z : zeta) z = std::exp(s(rng));
  return zeta;
}

// The naive end above the Taylor engine's range, against fresh __float128 reference solves (agreeing with
// themselves to 1e-25); the reference's cost grows like ζ^{5/3} at this end, so a few points below 700.
TEST(FastCertification, NaiveEndAgainstTheReferenceAbove100) {
  Worst worst_eps;
  Worst worst_tau;
  for (const double zeta : log_uniform(100, 700, 4, 31)) {
    const ReferenceSolution r = hertz_reference(zeta);
    const auto eps = static_cast<double>(r.ends[CollisionEnd::naive]->eps);
    const double e = relative(fast::eps(zeta, CollisionEnd::naive), eps);
    const double t = relative(fast::collision_duration(zeta, CollisionEnd::naive),
                              static_cast<double>(r.ends[CollisionEnd::naive]->tau));
    worst_eps.update(e, zeta);
    worst_tau.update(t, zeta);
    EXPECT_LE(e, kAllowed) << zeta;
    EXPECT_EQ(fast::one_minus_eps(zeta, CollisionEnd::naive), 1.0 - eps) << zeta;  // 1 − ε rounds to it
    EXPECT_LE(t, kAllowed) << zeta;
  }
  std::printf(
      "naive end against the reference on (100, 700]: eps worst %.3g at zeta %.6g, tau_c worst %.3g at "
      "zeta %.6g\n",
      worst_eps.error, worst_eps.zeta, worst_tau.error, worst_tau.zeta);
}

// τ_c (both ends), x_max and τ_max against fresh reference solves at random ζ over the tables and the laws
// above them (the naive end where the reference is cheap, ζ <= 100; above, the test before).
TEST(FastCertification, DurationsAgainstTheReference) {
  std::vector<double> points = log_uniform(1e-12, 1e6, 40, 41);
  for (const double zeta : log_uniform(std::exp(12.0), 1e6, 8, 43)) points.push_back(zeta);
  Worst worst;
  for (const double zeta : points) {
    const bool naive = zeta <= 100;
    const ReferenceSolution r =
        hertz_reference(zeta, naive ? EndSet::both() : EndSet{CollisionEnd::delayed_recovery});
    const MaxCompression m = fast::max_compression(zeta);
    std::vector<double> errors{relative(fast::collision_duration(zeta, CollisionEnd::delayed_recovery),
                                        static_cast<double>(r.ends[CollisionEnd::delayed_recovery]->tau)),
                               relative(m.x, static_cast<double>(r.x_max)),
                               relative(m.tau, static_cast<double>(r.tau_max))};
    if (naive)
      errors.push_back(relative(fast::collision_duration(zeta, CollisionEnd::naive),
                                static_cast<double>(r.ends[CollisionEnd::naive]->tau)));
    for (const double e : errors) {
      worst.update(e, zeta);
      EXPECT_LE(e, kAllowed) << zeta;
    }
  }
  std::printf("tau_c, x_max, tau_max against the reference: worst %.3g at zeta %.6g\n", worst.error,
              worst.zeta);
}

// The naive end on (100, 1e5] against CVODE at its tightest tolerance, 1e-11 in ε: the two may differ by
// that tolerance plus the table's 1e-13, and no more. The measured difference (printed) is CVODE's error.
TEST(FastCertification, NaiveEndAgainstCvodeTo1e5) {
  SolveOptions options;
  options.tolerance = kMinTolerance;
  options.ends = EndSet{CollisionEnd::naive};
  CollisionSolver solver;
  Worst worst_eps;
  Worst worst_tau;
  for (const double zeta : log_uniform(100, 1e5, 40, 37)) {
    const CollisionResult r = solver.solve(ContactLaw::hertz_natural(zeta), options);
    const double e = relative(fast::eps(zeta, CollisionEnd::naive), r[CollisionEnd::naive]->eps);
    worst_eps.update(e, zeta);
    EXPECT_LE(e, kMinTolerance + kAllowed) << zeta;
    const double t =
        relative(fast::collision_duration(zeta, CollisionEnd::naive), r[CollisionEnd::naive]->tau);
    worst_tau.update(t, zeta);
    EXPECT_LE(t, 1e-9) << zeta;  // CVODE's τ_c is not bound by its tolerance in ε
  }
  std::printf(
      "naive end against CVODE at 1e-11: eps worst %.3g at zeta %.6g, tau_c worst %.3g at zeta %.6g\n",
      worst_eps.error, worst_eps.zeta, worst_tau.error, worst_tau.zeta);
}

}  // namespace
