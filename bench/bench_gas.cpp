// SPDX-License-Identifier: BSD-3-Clause
// Cost of the kinetic theory of the freely cooling gas (src/gas/, docs/gas.md): T(t), the local exponent, the
// collision frequency and ε_eff on 20 points per decade over six decades of time, for the issue's gas
// (ρ = 920 kg/m³, R = 5 mm, φ = 0.1, rms speed 1 m/s, ε = 0.8 at 2 m/s): viscoelastic Hertz from the fast
// table, a constant ε, and constant damping (ε(v) from solves on a grid in ln ζ). The target of issue 35 is
// 50 ms for six decades.
#include <benchmark/benchmark.h>

#include <numbers>

#include "restitution_gas/cooling.hpp"

namespace {

using namespace restitution;

gas::CoolingRequest issue_gas(const gas::ImpactLaw& law) {
  gas::CoolingRequest r;
  r.particles.diameter_m = 0.01;
  r.particles.mass_kg = 4.0 / 3.0 * std::numbers::pi * 0.005 * 0.005 * 0.005 * 920.0;
  r.particles.packing_fraction = 0.1;
  r.initial_temperature_j = r.particles.mass_kg;
  r.law = law;
  r.duration = 1e4;  // Haff times: t from 1e-2 to 1e4 τ₀
  r.duration_in_haff_times = true;
  r.points_per_decade = 20;
  return r;
}

void run(benchmark::State& state, const gas::ImpactLaw& law) {
  const gas::CoolingRequest r = issue_gas(law);
  std::size_t points = 0;
  for (auto _ : state) {
    const gas::CoolingCurve c = gas::cooling_curve(r);
    points = c.time_s.size();
    benchmark::DoNotOptimize(c.temperature_j.back());
  }
  state.counters["points"] = static_cast<double>(points);
}

void BM_GasViscoelasticHertz(benchmark::State& state) {
  run(state, gas::impact_law_from_eps(LawKind::viscoelastic_hertz, 0.8, 2.0, CollisionEnd::delayed_recovery));
}
BENCHMARK(BM_GasViscoelasticHertz)->Unit(benchmark::kMillisecond);

void BM_GasConstantEps(benchmark::State& state) {
  run(state, gas::constant_eps_law(0.8));
}
BENCHMARK(BM_GasConstantEps)->Unit(benchmark::kMillisecond);

void BM_GasConstantDamping(benchmark::State& state) {
  run(state,
      gas::impact_law_from_eps(LawKind::hertz_constant_damping, 0.8, 2.0, CollisionEnd::delayed_recovery));
}
BENCHMARK(BM_GasConstantDamping)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
