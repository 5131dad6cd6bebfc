// SPDX-License-Identifier: BSD-3-Clause
// Prints the results of a grid of CVODE solves to the bit (hexadecimal floats): the four laws, 41 parameters
// in [1e-3, 1e3], methods auto, adams and bdf, T = 1e-6 and 1e-10, the naive, the delayed-recovery and both
// ends. tests/sundials_patches.cmake builds it twice, with and without our patches to CVODE
// (scripts/sundials-patches/), and the test compares the two outputs byte for byte.
#include <cmath>
#include <cstdio>
#include <exception>

#include "restitution/collision_solver.hpp"

namespace {

using namespace restitution;

void print(const CollisionResult& r) {
  std::printf(" steps %ld rhs %ld max_compression %a %a", r.stats.steps, r.stats.rhs_evaluations,
              r.max_compression.tau, r.max_compression.x);
  for (const CollisionEnd end : {CollisionEnd::naive, CollisionEnd::delayed_recovery}) {
    if (const auto& e = r[end]) {
      std::printf(" | %a %a %a %a %a %a", e->eps, e->one_minus_eps, e->tau, e->x, e->velocity,
                  e->dissipated_energy);
    }
  }
}

}  // namespace

int main() {
  constexpr int kParameters = 41;
  const EndSet end_sets[] = {EndSet{CollisionEnd::naive}, EndSet{CollisionEnd::delayed_recovery},
                             EndSet{CollisionEnd::naive, CollisionEnd::delayed_recovery}};
  CollisionSolver solver;
  long solved = 0;
  for (const LawKind kind : kLawKinds) {
    for (int i = 0; i < kParameters; ++i) {
      const double parameter = std::pow(10.0, -3.0 + 6.0 * i / (kParameters - 1));
      for (const Method method : {Method::automatic, Method::adams, Method::bdf}) {
        for (const double tolerance : {1e-6, 1e-10}) {
          for (std::size_t e = 0; e < std::size(end_sets); ++e) {
            SolveOptions options;
            options.tolerance = tolerance;
            options.method = method;
            options.ends = end_sets[e];
            std::printf("%s %a %s %g %zu", law_name(kind), parameter, method_name(method), tolerance, e);
            try {
              print(solver.solve(ContactLaw::of_parameter(kind, parameter), options));
              ++solved;
            } catch (const std::exception& error) {  // refused or failed alike in both builds
              std::printf(" refused: %s", error.what());
            }
            std::printf("\n");
          }
        }
      }
    }
  }
  std::fprintf(stderr, "%ld solves\n", solved);
  return solved > 0 ? 0 : 1;
}
