// SPDX-License-Identifier: BSD-3-Clause
// Cost of fit_data (restitution/fit.hpp): a 30-point data set (speeds 0.01 ... 10 m/s, viscoelastic Hertz at
// the delayed-recovery end, β = 0.2, Gaussian noise σ = 0.01, fixed seed) fitted with every candidate law
// (Hertz at both ends on the fast table, Tsuji and the dash-pot with the solver), and with Hertz only.
// Issue 29's budget: 50 ms for all candidates. Run with --benchmark_repetitions=10 for the median.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "restitution/fast.hpp"
#include "restitution/fit.hpp"
#include "restitution/units.hpp"

namespace {

using namespace restitution;

FitData thirty_points() {
  std::mt19937_64 rng(29);
  std::normal_distribution<double> noise(0.0, 0.01);
  FitData d;
  for (int i = 0; i < 30; ++i) {
    const double v = 0.01 * std::pow(1000.0, i / 29.0);
    d.velocity_m_s.push_back(v);
    d.eps.push_back(fast::eps(zeta_from(0.2, v), CollisionEnd::delayed_recovery) + noise(rng));
    d.sigma.push_back(0.01);
  }
  return d;
}

void BM_FitAllCandidates(benchmark::State& state) {
  const FitData d = thirty_points();
  for (auto _ : state) benchmark::DoNotOptimize(fit_data(d));
  state.SetLabel("30 points, 4 laws");
}
BENCHMARK(BM_FitAllCandidates)->Unit(benchmark::kMillisecond);

void BM_FitHertzBothEnds(benchmark::State& state) {
  const FitData d = thirty_points();
  FitOptions options;
  options.candidates = {{LawKind::viscoelastic_hertz, CollisionEnd::delayed_recovery},
                        {LawKind::viscoelastic_hertz, CollisionEnd::naive}};
  for (auto _ : state) benchmark::DoNotOptimize(fit_data(d, options));
  state.SetLabel("30 points, Hertz at both ends");
}
BENCHMARK(BM_FitHertzBothEnds)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
