// SPDX-License-Identifier: BSD-3-Clause
// An adhesive collision (JKR as LAMMPS codes it, textbook JKR with viscoelastic dissipation, DMT) at T = 1e-8
// against the viscoelastic Hertz solve at the same tolerance (default method, both ends as `eps` asks, and
// the naive end alone, which is what the adhesive solve computes), and the sticking speed at T = 1e-8
// (counter "solves"). Issue 48's target: an adhesive solve costs at most 3× the Hertz one; v_s in at most 30
// solves. µm ice (docs/adhesion.md §7) at 3 v_s, with a damping that gives ε ≈ 0.5-0.7 there. And γ with the
// damping from ε at 3 v_s plus v_s (calibrate_adhesive_sticking, T = 1e-8; counter "solves").
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "restitution/adhesion.hpp"
#include "restitution/adhesive_calibration.hpp"
#include "restitution/adhesive_contact.hpp"
#include "restitution/collision_solver.hpp"
#include "restitution/contact_law.hpp"

namespace {

using namespace restitution;

AdhesiveContact ice(AdhesiveModel model) {
  const double radius = 1.5e-6, mass = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius * 920.0;
  const double damping = model == AdhesiveModel::jkr ? 2e-9 : 1e15;
  return {model, 7e9 / (2.0 * (1.0 - 0.0625)), radius / 2.0, mass / 2.0, 0.19, damping};
}

void adhesive_solve(benchmark::State& state, AdhesiveModel model) {
  const auto contact = ice(model);
  const double speed = 3.0 * sticking_speed(contact, 1e-8).speed_m_per_s;
  AdhesiveCollision result = solve_adhesive(contact, speed, 1e-8);
  for (auto _ : state) {  // NOLINT(clang-analyzer-deadcode.DeadStores): the benchmark loop idiom
    result = solve_adhesive(contact, speed, 1e-8);
    benchmark::DoNotOptimize(result);
  }
  state.counters["eps"] = result.eps;
  state.counters["steps"] = static_cast<double>(result.stats.steps);
  state.counters["rhs"] = static_cast<double>(result.stats.rhs_evaluations);
}

void hertz_solve(benchmark::State& state, EndSet ends) {
  CollisionSolver solver;
  SolveOptions options;
  options.tolerance = 1e-8;
  options.ends = ends;
  const ContactLaw law = ContactLaw::natural(LawKind::viscoelastic_hertz, 0.3);
  CollisionResult result = solver.solve(law, options);
  for (auto _ : state) {  // NOLINT(clang-analyzer-deadcode.DeadStores): the benchmark loop idiom
    result = solver.solve(law, options);
    benchmark::DoNotOptimize(result);
  }
  state.counters["steps"] = static_cast<double>(result.stats.steps);
}

void sticking(benchmark::State& state, AdhesiveModel model) {
  const auto contact = ice(model);
  StickingSpeed result;
  for (auto _ : state) {  // NOLINT(clang-analyzer-deadcode.DeadStores): the benchmark loop idiom
    result = sticking_speed(contact, 1e-8);
    benchmark::DoNotOptimize(result);
  }
  state.counters["solves"] = result.solves;
}

// The inverse of adhesive_solve: ε at 3 v_s and v_s of the same contact give γ and A back.
void calibrate_sticking(benchmark::State& state, AdhesiveModel model) {
  Material material;
  material.young_modulus_pa = 7e9;
  material.poisson_ratio = 0.25;
  material.radius1_m = material.radius2_m = 1.5e-6;
  material.density_kg_m3 = 920.0;
  const auto contact = adhesive_contact_of(model, material, 0.19, 2e-10);
  const double vs = sticking_speed(contact, 1e-10).speed_m_per_s;
  const double eps = solve_adhesive(contact, 3.0 * vs, 1e-10).eps;
  AdhesiveStickingCalibration result;
  for (auto _ : state) {  // NOLINT(clang-analyzer-deadcode.DeadStores): the benchmark loop idiom
    result = calibrate_adhesive_sticking(model, material, eps, 3.0 * vs, vs, 1e-8);
    benchmark::DoNotOptimize(result);
  }
  state.counters["solves"] = result.solves;
  state.counters["gamma_error"] = result.surface_energy_j_per_m2 / 0.19 - 1.0;
}

void register_cases() {
  for (const AdhesiveModel model : {AdhesiveModel::jkr_lammps, AdhesiveModel::jkr, AdhesiveModel::dmt}) {
    const std::string name = adhesive_model_name(model);
    benchmark::RegisterBenchmark(("adhesive/" + name + "/3vs/T=1e-8").c_str(), adhesive_solve, model)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("sticking_speed/" + name + "/T=1e-8").c_str(), sticking, model)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("calibrate_sticking/" + name + "/T=1e-8").c_str(), calibrate_sticking,
                                 model)
        ->Unit(benchmark::kMillisecond);
  }
  benchmark::RegisterBenchmark("hertz/both_ends/zeta=0.3/T=1e-8", hertz_solve, EndSet::both())
      ->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("hertz/naive/zeta=0.3/T=1e-8", hertz_solve, EndSet{CollisionEnd::naive})
      ->Unit(benchmark::kMicrosecond);
}

}  // namespace

int main(int argc, char** argv) {
  register_cases();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
