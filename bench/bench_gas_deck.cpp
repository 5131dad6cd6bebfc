// SPDX-License-Identifier: BSD-3-Clause
// Cost of writing a gas deck (gas_deck/lammps_gas_deck.hpp) for N = 1e5 spheres at packing fraction 0.1 (the
// material of issue 35): placement on a cell list, Maxwellian velocities, the data file's text and the time
// step search. Issue 35's budget: 2 s. The placement alone is benchmarked too.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "gas_deck/lammps_gas_deck.hpp"
#include "gas_deck/placement.hpp"

namespace {

using namespace restitution;

void BM_GasDeck1e5(benchmark::State& state) {
  gas_deck::GasDeckRequest r;
  r.material.young_modulus_pa = 1e8;
  r.material.poisson_ratio = 0.4;
  r.material.density_kg_m3 = 920.0;
  r.material.radius1_m = r.material.radius2_m = 0.005;
  r.damping.eps = 0.8;
  r.damping.velocity_m_s = 2.0;
  r.particles = 100000;
  r.packing_fraction = 0.1;
  for (auto _ : state) benchmark::DoNotOptimize(gas_deck::lammps_gas_deck(r, "gas.data"));
}
BENCHMARK(BM_GasDeck1e5)->Unit(benchmark::kMillisecond);

void BM_Placement1e5(benchmark::State& state) {
  const double sigma = 0.01;
  const double box = std::cbrt(1e5 * std::numbers::pi / 6.0 * std::pow(sigma, 3) / 0.1);
  for (auto _ : state) benchmark::DoNotOptimize(gas_deck::random_positions(100000, sigma, box, 1));
}
BENCHMARK(BM_Placement1e5)->Unit(benchmark::kMillisecond);

}  // namespace
BENCHMARK_MAIN();
