// SPDX-License-Identifier: BSD-3-Clause
// The sweep target of issue 5: 10^4 values of ζ, log-spaced over [1e-4, 1e4], delayed-recovery end,
// tolerance 1e-10 (the accuracy contract: error <= 1e-10 relative to min(ε, 1-ε)), on 1 and 2 threads.
// Target: <= 60 ms wall on 2 cores and >= 1.8x the single-thread rate. Wall-clock medians over repeats:
//   build/release/bench/bench_sweep --benchmark_repetitions=3
// The counter points_per_second is the rate; divide the two rows' medians for the parallel speed-up.
// process_cpu_ms is the CPU time of all threads together: equal on 1 and 2 threads when the parallel sweep
// adds no work of its own (a check that still means something on a loaded machine, where the wall-clock
// speed-up does not).
#include <benchmark/benchmark.h>

#include <ctime>

#include "restitution/sweep.hpp"

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
  const std::clock_t cpu_start = std::clock();  // the process's CPU time, every thread
  for (auto _ : state) {
    const SweepSummary summary = run_sweep(zetas, options, control);
    failed += summary.failed;
    benchmark::DoNotOptimize(summary);
  }
  const double cpu_ms = 1e3 * static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  if (failed > 0) state.SkipWithError("points failed");
  state.counters["process_cpu_ms"] = cpu_ms / static_cast<double>(state.iterations());
  state.counters["points_per_second"] =
      benchmark::Counter(static_cast<double>(kPoints), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_Sweep)->Arg(1)->Arg(2)->ArgName("threads")->Iterations(1)->UseRealTime()->Unit(
    benchmark::kMillisecond);

}  // namespace
}  // namespace restitution

BENCHMARK_MAIN();
