// SPDX-License-Identifier: BSD-3-Clause
// The default configuration (`restitution eps --zeta Z`: both ends, tolerance 1e-10, method auto) on the
// ζ values of the core issue's closing table. Counters: ε of each end and its error against the reference
// (data/reference_solutions.csv); for the naive end at ζ = 1e4, which the reference does not hold, against
// the derived law ε = κ ζ^{-5} (docs/asymptotics.md: corrections below 3e-12 from ζ = 7 on).
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "analysis/asymptotics.hpp"
#include "reference/reference_solution.hpp"
#include "reference/work_precision.hpp"
#include "restitution/collision_solver.hpp"

namespace {

using namespace restitution;

const std::vector<ReferenceRow>& rows() {
  static const std::vector<ReferenceRow> r = read_reference_file(reference_file_in(RESTITUTION_SOURCE_DIR));
  return r;
}

double law_error(const EndResult& end, double zeta) {
  const double law = asymptotics::naive_eps(zeta, asymptotics::naive_prefactor().value);
  return std::abs(end.eps - law) / law;
}

void default_solve(benchmark::State& state, double zeta) {
  CollisionSolver solver;
  const ContactLaw law = ContactLaw::hertz_natural(zeta);
  const SolveOptions options;  // the defaults of `restitution eps`
  CollisionResult result = solver.solve(law, options);
  for (auto _ : state) {  // NOLINT(clang-analyzer-deadcode.DeadStores): the benchmark loop idiom
    result = solver.solve(law, options);
    benchmark::DoNotOptimize(result);
  }
  state.counters["eps_naive"] = result[CollisionEnd::naive]->eps;
  state.counters["eps_delayed"] = result[CollisionEnd::delayed_recovery]->eps;
  const ReferenceRow* row = reference_row_for(rows(), zeta);
  if (row != nullptr && row->ends[CollisionEnd::naive]) {
    state.counters["err_naive"] =
        contract_error(*result[CollisionEnd::naive], *row->ends[CollisionEnd::naive]);
  } else {
    state.counters["err_naive_vs_law"] = law_error(*result[CollisionEnd::naive], zeta);
  }
  if (row != nullptr && row->ends[CollisionEnd::delayed_recovery]) {
    state.counters["err_delayed"] =
        contract_error(*result[CollisionEnd::delayed_recovery], *row->ends[CollisionEnd::delayed_recovery]);
  }
  state.counters["steps"] = static_cast<double>(result.stats.steps);
}

}  // namespace

int main(int argc, char** argv) {
  for (const double zeta : {1e-6, 1e-3, 0.1, 1.0, 10.0, 100.0, 1e4}) {
    benchmark::RegisterBenchmark(("default/zeta=" + std::to_string(zeta)).c_str(), default_solve, zeta)
        ->Unit(benchmark::kMicrosecond);
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
