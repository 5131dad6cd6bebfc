// SPDX-License-Identifier: BSD-3-Clause
// Chrono's lines: ChContactMaterialSMC with Kn, Gn and the Hertz contact force model (C++).
#include "dem/deck_chrono.hpp"

#include <fmt/core.h>

#include <cmath>

#include "dem/deck_notes.hpp"
#include "restitution/units.hpp"

namespace restitution::dem {

void write_chrono(Deck& d, const Pair& p, double a, double /*vn*/, double mu) {
  const double sqrt_r = std::sqrt(p.effective_radius_m);
  const double kn = hertz_modulus_pa(p.effective_modulus_pa) / sqrt_r;
  const double gn = damping_per_mass(a, p.effective_modulus_pa, p.effective_mass_kg) / sqrt_r;
  d.parameters = {
      {"Kn", kn, "(4/3) E* / sqrt(R_eff) [Pa m^-1/2], multiplied by R_eff sqrt(xi)"},
      {"Gn", gn, "2 A E* / (m_eff sqrt(R_eff)) [m^-3/2 s^-1], multiplied by m_eff R_eff sqrt(xi)"},
  };
  // With friction: Mindlin's Kt = (8 G* / ((4/3) E*)) Kn and Gt = Gn, the same choices as the LAMMPS lines.
  const auto [kt, gt] = tangential(p, kn, gn, mu);
  d.parameters.push_back(
      {"Kt", kt, "8 G* / sqrt(R_eff) (Mindlin) [Pa m^-1/2], scaled as Kn; 0: frictionless"});
  d.parameters.push_back({"Gt", gt, "Gt = Gn [m^-3/2 s^-1]; 0: frictionless"});
  d.parameters.push_back({"friction", mu, "Coulomb friction coefficient [1]"});
  d.lines = {"auto material = chrono_types::make_shared<ChContactMaterialSMC>();",
             fmt::format("material->SetKn({});", num(kn)), fmt::format("material->SetGn({});", num(gn)),
             fmt::format("material->SetKt({}); material->SetGt({}); material->SetFriction({});", num(kt),
                         num(gt), num(mu)),
             "sys.SetContactForceModel(ChSystemSMC::ContactForceModel::Hertz);",
             "sys.UseMaterialProperties(false);",
             // Kn and Gn are scaled by the contact's effective radius, which only Multicore computes.
             "sys.SetCollisionSystemType(ChCollisionSystem::Type::MULTICORE);  // needed: R_eff per contact",
             fmt::format("// with Bullet instead: ChCollisionInfo::SetDefaultEffectiveCurvatureRadius({});",
                         num(p.effective_radius_m))};
  d.notes = {
      mu > 0.0 ? "Kt = 8 G* / sqrt(R_eff) (Mindlin), Gt = Gn" : "Kt = Gt = friction = 0: frictionless",
      // One note in several literals (parenthesized: not a missing comma).
      ("Chrono's R_eff is the contact's effective curvature radius, which only the Multicore collision "
       "system sets; with Bullet every contact gets ChCollisionInfo's default 0.1 m (Kn, Gn far too large, "
       "eps far too low) unless SetDefaultEffectiveCurvatureRadius(R_eff) is called"),
      friction_note(mu), clamp_note(d.code, d.end),
      "Chrono scales Kn and Gn with R_eff, not sqrt(R_eff), and Gn with m_eff: exact only for the pair it "
      "was made for (" +
          pair_note(p) + ")"};
}

Coefficients read_chrono(const Deck& d, const Pair& other) {
  return {other.effective_radius_m * d.parameter("Kn"),
          other.effective_radius_m * other.effective_mass_kg * d.parameter("Gn")};
}

}  // namespace restitution::dem
