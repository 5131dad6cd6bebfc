// The sweep target of issue 5: 10^4 values of ζ, log-spaced over [1e-4, 1e4], delayed-recovery end,
// tolerance 1e-10 (the accuracy contract: error <= 1e-10 relative to min(ε, 1-ε)), on 1 and 2 threads.
// Target: <= 60 ms wall on 2 cores and >= 1.8x the single-thread rate. Wall-clock medians over repeats:
//   build/release/bench/bench_sweep --benchmark_repetitions=3
// The counter points_per_second is the rate; divide the two rows' medians for the parallel speed-up.
#include <benchmark/benchmark.h>

#include "sweep/sweep.hpp"

namespace restitution {
namespace {

constexpr std::size_t kPoints = 10'000;

void BM_Sweep(benchmark::State& state) {
  const std::vector<double> zetas = zeta_values({1e-4, 1e4, kPoints, true});
  SolveOptions options;
  options.tolerance = 1e-10;
  options.ends = EndSet{CollisionEnd::delayed_recovery};
  SweepControl control;
  control.threads = static_cast<unsigned>(state.range(0));
  std::size_t failed = 0;
  for (auto _ : state) {
    const SweepSummary summary = run_sweep(zetas, options, control);
    failed += summary.failed;
    benchmark::DoNotOptimize(summary);
  }
  if (failed > 0) state.SkipWithError("points failed");
  state.counters["points_per_second"] =
      benchmark::Counter(static_cast<double>(kPoints), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_Sweep)->Arg(1)->Arg(2)->ArgName("threads")->Iterations(1)->UseRealTime()->Unit(
    benchmark::kMillisecond);

}  // namespace
}  // namespace restitution

BENCHMARK_MAIN();
