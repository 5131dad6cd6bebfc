// SPDX-License-Identifier: BSD-3-Clause
// The default engine's targets (issue 17): `--method auto` at T = 1e-10,
//  * delayed-recovery end, the mean over the reference grid's ζ in [1e-3, 1e3] (25 points, log-spaced):
//    one iteration solves every point once, the time per solve is the iteration's time / 25;
//  * naive end at ζ = 100.
// Uses no library internals, so that scripts/bench_against writes the same program against an earlier
// commit and runs both in one session (the ratio is what to compare on a shared machine). Each case checks
// the contract against data/reference_solutions.csv (counter worst_error_over_T must stay <= 1).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <vector>

#include "restitution/collision_solver.hpp"
// The reference and work-precision headers moved from include/restitution to src/reference; both places
// are tried so that scripts/bench_against can build this program at commits before the move.
#if __has_include("reference/work_precision.hpp")
#include "reference/reference_solution.hpp"
#include "reference/work_precision.hpp"
#else
#include "restitution/reference_solution.hpp"
#include "restitution/work_precision.hpp"
#endif

namespace {

using namespace restitution;

constexpr double kTolerance = 1e-10;

std::vector<ReferenceRow> rows_between(double zeta_min, double zeta_max) {
  std::vector<ReferenceRow> rows;
  for (const ReferenceRow& row : read_reference_file(reference_file_in(RESTITUTION_SOURCE_DIR))) {
    if (row.zeta >= zeta_min && row.zeta <= zeta_max) rows.push_back(row);
  }
  return rows;
}

void solve_rows(benchmark::State& state, const std::vector<ReferenceRow>& rows, CollisionEnd end) {
  CollisionSolver solver;
  SolveOptions options;
  options.tolerance = kTolerance;
  options.ends = EndSet{end};
  std::vector<ContactLaw> laws;
  laws.reserve(rows.size());
  for (const ReferenceRow& row : rows) laws.push_back(ContactLaw::hertz_natural(row.zeta));
  double worst = 0.0;
  long steps = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const CollisionResult r = solver.solve(laws[i], options);
    worst = std::max(worst, contract_error(*r[end], *rows[i].ends[end]));
    steps += r.stats.steps;
  }
  for (auto _ : state) {  // NOLINT(clang-analyzer-deadcode.DeadStores): the benchmark loop idiom
    for (const ContactLaw& law : laws) benchmark::DoNotOptimize(solver.solve(law, options));
  }
  const auto solves = static_cast<double>(rows.size());
  // CPU time per solve in µs (rate inverted: time / (solves · 1e-6)).
  state.counters["us_per_solve"] = benchmark::Counter(
      solves * 1e-6, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["worst_error_over_T"] = worst / kTolerance;
  state.counters["steps_per_solve"] = static_cast<double>(steps) / solves;
}

}  // namespace

int main(int argc, char** argv) {
  static const std::vector<ReferenceRow> delayed = rows_between(1e-3, 1e3);
  static const std::vector<ReferenceRow> naive = rows_between(100.0, 100.0);
  benchmark::RegisterBenchmark("default/delayed/mean_zeta_1e-3_1e3/T=1e-10", [](benchmark::State& s) {
    solve_rows(s, delayed, CollisionEnd::delayed_recovery);
  })->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("default/naive/zeta=100/T=1e-10", [](benchmark::State& s) {
    solve_rows(s, naive, CollisionEnd::naive);
  })->Unit(benchmark::kMicrosecond);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
