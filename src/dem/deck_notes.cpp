// SPDX-License-Identifier: BSD-3-Clause
// What the codes' writers share: numbers as text, the law's coefficients, the notes on clamping, friction and
// the pair a deck is made for, and the tangential model.
#include "dem/deck_notes.hpp"

#include <fmt/core.h>

#include <cmath>

#include "restitution/units.hpp"

namespace restitution::dem {
namespace {

// Mindlin's tangential stiffness over the Hertz force coefficient, k_t / k_n = 8 G* / ((4/3) E*) =
// 3 (1 - nu) / (2 - nu) for two spheres of one material: what LAMMPS's `mindlin NULL` and LIGGGHTS's
// `model hertz` compute from Y and nu, used here for the codes that take k_t as a number.
double mindlin_ratio(const Pair& p) {
  return 3.0 * (1.0 - p.poisson_ratio) / (2.0 - p.poisson_ratio);
}

}  // namespace

std::string num(double x) {
  return fmt::format("{}", x);
}

Coefficients law_coefficients(const Pair& p, double dissipative_constant_s) {
  const double sqrt_r = std::sqrt(p.effective_radius_m);
  return {hertz_stiffness(p.effective_modulus_pa, p.effective_radius_m),
          2.0 * dissipative_constant_s * p.effective_modulus_pa * sqrt_r};
}

std::string clamp_note(Code code, CollisionEnd end) {
  if (always_clamps(code)) {
    return fmt::format(
        "{} always clamps the normal force at zero: the collision ends at the delayed-recovery end",
        code_name(code));
  }
  return end == CollisionEnd::delayed_recovery
             ? "the normal force is clamped at zero: the collision ends when it vanishes (delayed-recovery "
               "end)"
             : "no clamp: the force may pull, the collision ends when the spheres separate (naive end)";
}

std::string pair_note(const Pair& p) {
  return fmt::format("made for R_eff = {:.6g} m, m_eff = {:.6g} kg", p.effective_radius_m,
                     p.effective_mass_kg);
}

Coefficients tangential(const Pair& p, double kn, double gn, double mu) {
  return mu > 0.0 ? Coefficients{mindlin_ratio(p) * kn, gn} : Coefficients{};
}

std::string friction_note(double mu) {
  return mu > 0.0 ? fmt::format(
                        "Coulomb friction mu = {} acts only tangentially: it does not change the normal eps "
                        "of a head-on collision (the eps below)",
                        num(mu))
                  : "frictionless (mu = 0); friction would not change the normal eps of a head-on collision";
}

}  // namespace restitution::dem
