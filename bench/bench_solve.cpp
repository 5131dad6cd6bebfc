// SPDX-License-Identifier: BSD-3-Clause
// Per-solve micro-benchmarks: one collision per iteration, reusing one solver (as a sweep does).
// Arguments: engine, end, ζ, tolerance. Each case also reports the error against the reference solution
// (data/reference_solutions.csv) as the counter "error" and the right-hand-side evaluations as "rhs".
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "reference/reference_solution.hpp"
#include "reference/work_precision.hpp"
#include "restitution/collision_solver.hpp"

namespace {

using namespace restitution;

const std::vector<ReferenceRow>& rows() {
  static const std::vector<ReferenceRow> r = read_reference_file(reference_file_in(RESTITUTION_SOURCE_DIR));
  return r;
}

void solve_case(benchmark::State& state, const WorkPrecisionEngine& engine, CollisionEnd which, double zeta,
                double tolerance) {
  CollisionSolver solver;
  const SolveOptions options = work_precision_options(engine, which, tolerance);
  const ContactLaw law = ContactLaw::hertz_natural(zeta);
  CollisionResult result = solver.solve(law, options);
  for (auto _ : state) {  // NOLINT(clang-analyzer-deadcode.DeadStores): the benchmark loop idiom
    result = solver.solve(law, options);
    benchmark::DoNotOptimize(result);
  }
  const EndResult& end = *result[which];
  if (const ReferenceRow* row = reference_row_for(rows(), zeta)) {
    const auto& ref = row->ends[which];
    if (ref) state.counters["error"] = contract_error(end, *ref);
  }
  state.counters["rhs"] = static_cast<double>(result.stats.rhs_evaluations);
  state.counters["steps"] = static_cast<double>(result.stats.steps);
}

// The cases of the targets: Taylor at 1e-12 on every decade of ζ (delayed recovery) and ζ <= 10
// (naive); CVODE at 1e-10 for ζ <= 100 (delayed recovery).
void register_cases() {
  const double decades[] = {1e-4, 1e-3, 1e-2, 1e-1, 1.0, 10.0, 100.0, 1e3, 1e4};
  for (const WorkPrecisionEngine& engine : work_precision_engines()) {
    const bool taylor = engine.method == Method::taylor;
    const double tolerance = taylor ? 1e-12 : 1e-10;
    for (const CollisionEnd end : {CollisionEnd::delayed_recovery, CollisionEnd::naive}) {
      const bool naive = end == CollisionEnd::naive;
      for (const double zeta : decades) {
        if (naive && zeta > (taylor ? 10.0 : 100.0)) continue;
        if (!taylor && zeta > 100.0) continue;
        const std::string name = "solve/" + engine.name + (naive ? "/naive" : "/delayed") +
                                 "/zeta=" + std::to_string(zeta).substr(0, 8) +
                                 "/T=" + (taylor ? "1e-12" : "1e-10");
        benchmark::RegisterBenchmark(name.c_str(), solve_case, engine, end, zeta, tolerance)
            ->Unit(benchmark::kMicrosecond);
      }
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  register_cases();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
