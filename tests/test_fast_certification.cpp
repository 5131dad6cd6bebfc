// Certification of the committed fast tables (src/fast/fast_table.h) against an independent engine: the
// double-precision Taylor engine at its tightest tolerance (1e-13) on 10^5 random ζ, log-uniform and
// stratified so that every interval of both tables, the series below them and the asymptotic laws above them
// are hit, plus every interval boundary. Both ends (the naive end where the Taylor engine computes it,
// ζ <= 100; above, docs/fast.md and the reference rows of test_fast certify κ ζ^-5).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "restitution/fast.hpp"
#include "taylor/taylor_engine.hpp"

namespace {

using namespace restitution;

// The table's contract itself: the two agree to 1.3e-14 on these points, so the engine's own error (bounded
// by its tolerance, 1e-13) leaves room for none of the table's beyond it.
constexpr double kAllowed = 1e-13;

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
  for (double s = -19.0; s <= 12.0; s += 0.125)
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
  Worst worst_naive, worst_delayed;
  long naive_points = 0, delayed_points = 0;
  for (const double zeta : certification_points()) {
    options.ends = zeta <= kTaylorNaiveZetaMax ? EndSet::both() : EndSet{CollisionEnd::delayed_recovery};
    const CollisionResult r = solve_with_taylor(ContactLaw::hertz_natural(zeta), options);
    const auto check = [&](const EndResult& end, CollisionEnd which, Worst& worst) {
      const double e = std::max(relative(fast::eps(zeta, which), end.eps),
                                relative(fast::one_minus_eps(zeta, which), end.one_minus_eps));
      worst.update(e, zeta);
      ASSERT_LE(e, kAllowed) << end_name(which) << " at zeta " << zeta;
    };
    check(*r[CollisionEnd::delayed_recovery], CollisionEnd::delayed_recovery, worst_delayed);
    ++delayed_points;
    if (r[CollisionEnd::naive]) {
      check(*r[CollisionEnd::naive], CollisionEnd::naive, worst_naive);
      ++naive_points;
    }
  }
  RecordProperty("naive_points", std::to_string(naive_points));
  RecordProperty("delayed_points", std::to_string(delayed_points));
  std::printf(
      "naive: %ld points, worst %.3g at zeta %.6g; delayed recovery: %ld points, worst %.3g at zeta %.6g\n",
      naive_points, worst_naive.error, worst_naive.zeta, delayed_points, worst_delayed.error,
      worst_delayed.zeta);
}

}  // namespace
