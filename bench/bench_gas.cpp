// SPDX-License-Identifier: BSD-3-Clause
// Cost of the kinetic theory of the freely cooling gas (src/gas/, docs/gas.md): T(t), the local exponent, the
// collision frequency and ε_eff on 20 points per decade over six decades of time, for the issue's gas
// (ρ = 920 kg/m³, R = 5 mm, φ = 0.1, rms speed 1 m/s, ε = 0.8 at 2 m/s): viscoelastic Hertz from the fast
// table, a constant ε, and constant damping (ε(v) from solves on a grid in ln ζ). The target of issue 35 is
// 50 ms for six decades. The driven gas (issue 49): its steady state for one driving (target 10 ms) and its
// relaxation from T0 = T_s/100 over six decades of time (target 50 ms), with the evolving a₂.
#include <benchmark/benchmark.h>

#include <numbers>

#include "restitution_gas/cooling.hpp"
#include "restitution_gas/driven.hpp"

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

void run(benchmark::State& state, const gas::ImpactLaw& law, bool a2_evolving = false) {
  gas::CoolingRequest r = issue_gas(law);
  r.a2_evolving = a2_evolving;
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

// The same with the evolving Sonine a₂ (--a2 evolving): μ₄ too at each node, and the collocation of a₂.
void BM_GasViscoelasticHertzEvolvingA2(benchmark::State& state) {
  run(state, gas::impact_law_from_eps(LawKind::viscoelastic_hertz, 0.8, 2.0, CollisionEnd::delayed_recovery),
      true);
}
BENCHMARK(BM_GasViscoelasticHertzEvolvingA2)->Unit(benchmark::kMillisecond);

// Small dissipation (ε = 0.99 at 2 m/s): a₂ relaxes fast against the cooling, so its panels narrow.
void BM_GasViscoelasticHertzEvolvingA2SmallDissipation(benchmark::State& state) {
  run(state, gas::impact_law_from_eps(LawKind::viscoelastic_hertz, 0.99, 2.0, CollisionEnd::delayed_recovery),
      true);
}
BENCHMARK(BM_GasViscoelasticHertzEvolvingA2SmallDissipation)->Unit(benchmark::kMillisecond);

void BM_GasConstantEps(benchmark::State& state) {
  run(state, gas::constant_eps_law(0.8));
}
BENCHMARK(BM_GasConstantEps)->Unit(benchmark::kMillisecond);

void BM_GasConstantDamping(benchmark::State& state) {
  run(state,
      gas::impact_law_from_eps(LawKind::hertz_constant_damping, 0.8, 2.0, CollisionEnd::delayed_recovery));
}
BENCHMARK(BM_GasConstantDamping)->Unit(benchmark::kMillisecond);

// The issue's gas in a Langevin bath (T_b = 1e-3 J, τ_b = 0.5 s) with the evolving a₂.
gas::DrivenRequest driven_gas() {
  gas::DrivenRequest r;
  r.gas = issue_gas(
      gas::impact_law_from_eps(LawKind::viscoelastic_hertz, 0.8, 2.0, CollisionEnd::delayed_recovery));
  r.gas.a2_evolving = true;
  r.thermostat = {gas::ThermostatKind::langevin, 1e-3, 0.5, 0.0};
  return r;
}

void BM_DrivenGasSteadyState(benchmark::State& state) {
  const gas::DrivenRequest r = driven_gas();
  for (auto _ : state) benchmark::DoNotOptimize(gas::steady_state(r).temperature_j);
}
BENCHMARK(BM_DrivenGasSteadyState)->Unit(benchmark::kMillisecond);

// From T_s/100 up to the steady state: 20 points per decade from 1e-4 to 1e2 relaxation times.
void BM_DrivenGasRelaxationSixDecades(benchmark::State& state) {
  gas::DrivenRequest r = driven_gas();
  const gas::SteadyState s = gas::steady_state(r);
  r.gas.initial_temperature_j = 0.01 * s.temperature_j;
  r.gas.duration_in_haff_times = false;
  r.gas.duration = 100.0 * s.relaxation_time_s;
  std::size_t points = 0;
  for (auto _ : state) {
    const gas::DrivenCurve c = gas::driven_curve(r);
    points = c.curve.time_s.size();
    benchmark::DoNotOptimize(c.curve.temperature_j.back());
  }
  state.counters["points"] = static_cast<double>(points);
}
BENCHMARK(BM_DrivenGasRelaxationSixDecades)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
