// SPDX-License-Identifier: BSD-3-Clause
// ε of two viscoelastic spheres at both ends of the collision, for ζ = β v^{1/5} (natural units).
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <restitution/restitution.hpp>

int main(int argc, char** argv) try {
  const double zeta = argc > 1 ? std::strtod(argv[1], nullptr) : 1.0;
  restitution::CollisionSolver solver;  // reusable; one per thread
  const auto result = solver.solve(restitution::ContactLaw::hertz_natural(zeta), {});
  for (const auto end : restitution::kCollisionEnds) {  // "naive", "delayed-recovery"
    std::printf("%s %.17g\n", restitution::end_name(end), result[end]->eps);
  }
} catch (const std::exception& e) {  // InvalidInput (e.g. ζ < 0), NumericalFailure
  std::fprintf(stderr, "app: %s\n", e.what());
  return 2;
}
