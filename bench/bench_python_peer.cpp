// SPDX-License-Identifier: BSD-3-Clause
// The C++ side of bench/python_bench.py (issue 14): the same work the Python module is timed on, through
// the library directly, so that the script can report the module's overhead as a ratio in one run.
//   BM_SweepPeer: 10^5 ζ log-spaced over [1e-3, 1e3], delayed-recovery end, method taylor, tolerance 1e-10,
//                 all hardware threads (run_sweep, as restitution.eps(array) uses).
//   BM_ScalarPeer: one solve per iteration with a reused solver, cycling through 100 log-spaced ζ in the
//                 same range (as the scalar restitution.eps does with its per-thread solver).
// Wall and CPU time (all threads of the process, which on a shared machine is the steadier of the two).
// Run: build/release/bench/bench_python_peer --benchmark_repetitions=5 (the script runs one case at a time).
#include <benchmark/benchmark.h>

#include "restitution/sweep.hpp"

namespace restitution {
namespace {

SolveOptions peer_options() {
  SolveOptions options;
  options.tolerance = 1e-10;
  options.method = Method::taylor;
  options.ends = EndSet{CollisionEnd::delayed_recovery};
  return options;
}

void BM_SweepPeer(benchmark::State& state) {
  const std::vector<double> zetas = zeta_values({1e-3, 1e3, 100'000, true});
  const SolveOptions options = peer_options();
  std::vector<double> eps(zetas.size());
  SweepControl control;  // all hardware threads, results stored as the module stores them
  control.point_finished = [&eps](const SweepPoint& p) {
    eps[p.index] = (*p.result)[CollisionEnd::delayed_recovery]->eps;
  };
  for (auto _ : state) {
    const SweepSummary summary = run_sweep(zetas, options, control);
    if (summary.failed > 0) state.SkipWithError("points failed");
    benchmark::DoNotOptimize(eps.data());
  }
}
BENCHMARK(BM_SweepPeer)->Iterations(1)->UseRealTime()->MeasureProcessCPUTime()->Unit(benchmark::kMillisecond);

void BM_ScalarPeer(benchmark::State& state) {
  const std::vector<double> zetas = zeta_values({1e-3, 1e3, 100, true});
  const SolveOptions options = peer_options();
  CollisionSolver solver;
  std::size_t i = 0;
  for (auto _ : state) {
    const CollisionResult r = solver.solve(ContactLaw::hertz_natural(zetas[i]), options);
    benchmark::DoNotOptimize(r[CollisionEnd::delayed_recovery]->eps);
    i = (i + 1) % zetas.size();
  }
}
BENCHMARK(BM_ScalarPeer)->Iterations(2'000)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace restitution

BENCHMARK_MAIN();
