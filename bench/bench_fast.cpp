// SPDX-License-Identifier: BSD-3-Clause
// Cost of the fast ε(ζ) table (restitution/fast.hpp) against the closed-form approximations DEM codes use
// (Padé [1/4] and [3/6] of 2011, the 1999 Padé, the series), per call, over random arguments: ζ log-uniform
// over every interval of the tables (1e-10 ... 1e7, series and asymptotic laws included), and over
// [1e-4, 1e4] for the comparison with the approximations; ε for the inverse log-uniform in ε and in 1 − ε.
// The collision duration and the maximal compression over the same ζ as ε.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "restitution/fast.hpp"
#include "restitution/series.hpp"
#include "restitution_series_study/series_coefficients.hpp"

namespace {

using namespace restitution;

constexpr std::size_t kPoints = 4096;  // a power of two: the loop index wraps with a mask

std::vector<double> log_uniform(double lo, double hi, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(std::log(lo), std::log(hi));
  std::vector<double> v(kPoints);
  for (double& x : v) x = std::exp(u(rng));
  return v;
}

// ε spread over the whole range: half log-uniform in ε ∈ [1e-12, 0.5], half with 1 − ε log-uniform there.
std::vector<double> random_eps(unsigned seed) {
  std::vector<double> v = log_uniform(1e-12, 0.5, seed);
  for (std::size_t i = 0; i < v.size(); i += 2) v[i] = 1.0 - v[i];
  return v;
}

template <class F>
void run(benchmark::State& state, const std::vector<double>& args, F f) {
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(f(args[i]));
    i = (i + 1) & (kPoints - 1);
  }
}

const std::vector<double>& all_zeta() {
  static const std::vector<double> v = log_uniform(1e-10, 1e7, 1);
  return v;
}
const std::vector<double>& dem_zeta() {
  static const std::vector<double> v = log_uniform(1e-4, 1e4, 2);
  return v;
}
const std::vector<double>& eps_values() {
  static const std::vector<double> v = random_eps(3);
  return v;
}
const series::Coefficients& coefficients() {
  static const series::Coefficients c = series::compute_coefficients(40);
  return c;
}

}  // namespace

int main(int argc, char** argv) {
  using restitution::CollisionEnd;
  for (const CollisionEnd end : {CollisionEnd::naive, CollisionEnd::delayed_recovery}) {
    const std::string tag = end_name(end);
    benchmark::RegisterBenchmark(("fast_eps/all/" + tag).c_str(), [end](benchmark::State& s) {
      run(s, all_zeta(), [end](double z) { return fast::eps(z, end); });
    });
    benchmark::RegisterBenchmark(("fast_one_minus_eps/all/" + tag).c_str(), [end](benchmark::State& s) {
      run(s, all_zeta(), [end](double z) { return fast::one_minus_eps(z, end); });
    });
    benchmark::RegisterBenchmark(("fast_zeta_from_eps/" + tag).c_str(), [end](benchmark::State& s) {
      run(s, eps_values(), [end](double e) { return fast::zeta_from_eps(e, end); });
    });
    benchmark::RegisterBenchmark(("fast_collision_duration/all/" + tag).c_str(), [end](benchmark::State& s) {
      run(s, all_zeta(), [end](double z) { return fast::collision_duration(z, end); });
    });
    benchmark::RegisterBenchmark(("fast_eps/dem/" + tag).c_str(), [end](benchmark::State& s) {
      run(s, dem_zeta(), [end](double z) { return fast::eps(z, end); });
    });
  }
  benchmark::RegisterBenchmark("fast_max_compression/all", [](benchmark::State& s) {
    run(s, all_zeta(), [](double z) { return fast::max_compression(z); });
  });
  benchmark::RegisterBenchmark("pade_2011_1_4/dem", [](benchmark::State& s) {
    run(s, dem_zeta(), [](double z) { return series::pade_2011_1_4(z).eps; });
  });
  benchmark::RegisterBenchmark("pade_2011_3_6/dem", [](benchmark::State& s) {
    run(s, dem_zeta(), [](double z) { return series::pade_2011_3_6(z).eps; });
  });
  benchmark::RegisterBenchmark("pade_1999/dem", [](benchmark::State& s) {
    const series::Pade1999 d = series::pade_1999_published();
    run(s, dem_zeta(), [&d](double z) { return series::pade_1999(z, d).eps; });
  });
  benchmark::RegisterBenchmark("naive_series_40/dem", [](benchmark::State& s) {
    const std::vector<double> c(coefficients().c.begin() + 1, coefficients().c.end());
    run(s, dem_zeta(), [&c](double z) { return series::naive_series(z, c).eps; });
  });
  benchmark::RegisterBenchmark("delayed_recovery_series_60/dem", [](benchmark::State& s) {
    const std::vector<double> h(coefficients().h.begin(), coefficients().h.begin() + 61);
    run(s, dem_zeta(), [&h](double z) { return series::delayed_recovery_series(z, h).eps; });
  });
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
