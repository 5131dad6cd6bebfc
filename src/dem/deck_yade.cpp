// SPDX-License-Identifier: BSD-3-Clause
// YADE's lines: FrictMat, Ip2_FrictMat_FrictMat_MindlinPhys with (en, vn), Law2_ScGeom_MindlinPhys_Mindlin.
#include "dem/deck_yade.hpp"

#include <fmt/core.h>

#include <cmath>

#include "dem/deck_notes.hpp"
#include "dem/yade_conversion.hpp"
#include "restitution/errors.hpp"
#include "restitution/series.hpp"
#include "restitution/units.hpp"

namespace restitution::dem {
namespace {

double density_of(const Pair& p) {
  const double rho1 = p.mass1_kg / sphere_mass_kg(p.radius1_m, 1.0);
  const double rho2 = p.mass2_kg / sphere_mass_kg(p.radius2_m, 1.0);
  if (std::fabs(rho1 - rho2) > 1e-12 * rho1) {
    throw InvalidInput(fmt::format(
        "yade: one FrictMat has one density, but the two spheres' masses give {:.6g} and {:.6g} kg/m^3", rho1,
        rho2));
  }
  return rho1;
}

}  // namespace

void write_yade(Deck& d, const Pair& p, double a, double vn, double mu) {
  const Coefficients c = law_coefficients(p, a);
  const double k = c.elastic / p.effective_mass_kg;
  // YADE inverts the Padé [3/6] for σ; feeding it the Padé's own value at the exact σ = sqrt(β vn^{1/5})
  // makes it recover the exact A.
  const double zeta = zeta_from(hertz_constants(k, a).beta, vn);
  const double en = series::pade_2011_3_6(zeta).eps;
  d.parameters = {
      {"young", p.young_modulus_pa, "Young's modulus Y [Pa]"},
      {"poisson", p.poisson_ratio, "Poisson ratio [1]"},
      {"density", density_of(p), "density [kg/m^3]"},
      {"en", en,
       "Pade [3/6] value at the exact sigma (not the true eps): YADE inverts it back to the exact A [1]"},
      {"vn", vn, "reference impact speed [m/s]"},
      {"frictionAngle", std::atan(mu), "atan(mu), mu the Coulomb friction coefficient [rad]"},
  };
  d.lines = {
      fmt::format("O.materials.append(FrictMat(young={}, poisson={}, density={}, frictionAngle={}))",
                  num(p.young_modulus_pa), num(p.poisson_ratio), num(density_of(p)), num(std::atan(mu))),
      fmt::format("Ip2_FrictMat_FrictMat_MindlinPhys(en=MatchMaker(algo='val', val={}), "
                  "vn=MatchMaker(algo='val', val={}))",
                  num(en), num(vn)),
      "Law2_ScGeom_MindlinPhys_Mindlin()"};
  d.notes = {
      mu > 0.0 ? "frictionAngle = atan(mu); the Mindlin law takes its shear stiffness from Y and nu"
               : "frictionAngle = 0: frictionless",
      friction_note(mu), clamp_note(d.code, d.end),
      // One note in several literals (parenthesized: not a missing comma).
      ("vn exists from YADE 2024.02a on: older versions (Debian 12's 2023.02a) reject these lines; "
       "`restitution dem --code yade --yade-version 2023.02a` prints what they can do"),
      "YADE keeps beta = sigma^2 vn^(-1/5) for every contact (A = (2/3) beta (k_n0 / m_eff)^(-2/5)), so "
      "every pair gets this pair's eps(v): exact only for pairs with this pair's k_n0 / m_eff (" +
          pair_note(p) + ")"};
}

Coefficients read_yade(const Deck& d, const Pair& other) {
  const double k =
      hertz_stiffness(other.effective_modulus_pa, other.effective_radius_m) / other.effective_mass_kg;
  return law_coefficients(other, yade_dissipative_constant(d.parameter("en"), d.parameter("vn"), k));
}

}  // namespace restitution::dem
