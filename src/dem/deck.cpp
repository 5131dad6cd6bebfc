// SPDX-License-Identifier: BSD-3-Clause
// Each code's convention, derived in docs/dem.md: which numbers make the code's force equal to
// F = (4/3) E* sqrt(R_eff) ξ^{3/2} + 2 A E* sqrt(R_eff ξ) ξ'.
#include "dem/deck.hpp"

#include <fmt/core.h>

#include <cmath>
#include <stdexcept>

#include "dem/yade_conversion.hpp"
#include "restitution/errors.hpp"
#include "restitution/series.hpp"
#include "restitution/units.hpp"

namespace restitution::dem {
namespace {

// Shortest text that reads back to the same double.
std::string num(double x) {
  return fmt::format("{}", x);
}

// The elastic and dissipative coefficients K [N m^-3/2], D [N s m^-3/2] of m_eff ξ'' = -K ξ^{3/2} - D sqrt(ξ)
// ξ'.
struct Coefficients {
  double elastic = 0.0;
  double damping = 0.0;
};

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

// Mindlin's tangential stiffness over the Hertz force coefficient, k_t / k_n = 8 G* / ((4/3) E*) =
// 3 (1 - nu) / (2 - nu) for two spheres of one material: what LAMMPS's `mindlin NULL` and LIGGGHTS's
// `model hertz` compute from Y and nu, used here for the codes that take k_t as a number.
double mindlin_ratio(const Pair& p) {
  return 3.0 * (1.0 - p.poisson_ratio) / (2.0 - p.poisson_ratio);
}

// The tangential spring and dashpot for normal ones (kn, gn) in a code's own units: Mindlin's stiffness and a
// dashpot as strong as the normal one when mu > 0, none when frictionless.
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

void lammps(Deck& d, const Pair& p, double a, double mu) {
  const double eta = damping_per_mass(a, p.effective_modulus_pa, p.effective_mass_kg);
  d.parameters = {
      {"E", p.young_modulus_pa,
       "Young's modulus Y [Pa]; LAMMPS mixes two equal types to E* = Y / (2 (1 - nu^2))"},
      {"eta_n0", eta, "damping eta_n0 = 2 A E* / m_eff [1/(m s)], multiplied by m_eff sqrt(R_eff xi)"},
      {"nu", p.poisson_ratio, "Poisson ratio [1]"},
      {"mu_s", mu, "Coulomb friction coefficient [1]"},
  };
  // With friction: Mindlin's k_t = 8 G* a from Y and nu (NULL), the same law family as the normal force,
  // and x_gamma_t = 1, a tangential dashpot as strong as the normal one.
  const std::string tangential =
      mu > 0.0 ? fmt::format("mindlin NULL 1 {}", num(mu)) : "linear_nohistory 0 0";
  d.lines = {"pair_style granular",
             fmt::format("pair_coeff * * hertz/material {} {} {} tangential {} damping viscoelastic{}",
                         num(p.young_modulus_pa), num(eta), num(p.poisson_ratio), tangential,
                         d.end == CollisionEnd::delayed_recovery ? " limit_damping" : "")};
  d.notes = {mu > 0.0 ? "tangential mindlin NULL 1 mu: k_t = 8 G* a from Y and nu (Mindlin), x_gamma_t = 1 "
                        "(tangential damping = normal damping)"
                      : "tangential linear_nohistory 0 0: frictionless (x_gamma_t = 0, mu_s = 0)",
             friction_note(mu), clamp_note(d.code, d.end),
             "eta_n0 contains 1/m_eff: exact only for the pair it was made for (" + pair_note(p) +
                 "); other pairs get A' = A m_eff' / m_eff"};
}

void liggghts(Deck& d, const Pair& p, double a, double mu) {
  const double kn = hertz_modulus_pa(p.effective_modulus_pa);
  const double gn = damping_per_mass(a, p.effective_modulus_pa, p.effective_mass_kg);
  d.parameters = {
      {"kn", kn, "k_n = (4/3) E* [Pa], multiplied by sqrt(R_eff xi)"},
      {"gamman", gn, "gamma_n = 2 A E* / m_eff [1/(m s)], multiplied by m_eff sqrt(R_eff xi)"},
  };
  // With friction: Mindlin's k_t = 8 G* (as LIGGGHTS's own `model hertz` computes it) and gamma_t =
  // gamma_n, the same choices as the LAMMPS lines.
  const auto [kt, gt] = tangential(p, kn, gn, mu);
  d.parameters.push_back(
      {"kt", kt, "k_t = 8 G* (Mindlin) [Pa], multiplied by sqrt(R_eff xi); 0: frictionless"});
  d.parameters.push_back({"gammat", gt, "gamma_t = gamma_n [1/(m s)]; 0: frictionless"});
  d.parameters.push_back({"coefficientFriction", mu, "Coulomb friction coefficient [1]"});
  d.lines = {fmt::format("fix dem_kn all property/global kn peratomtypepair 1 {}", num(kn)),
             fmt::format("fix dem_kt all property/global kt peratomtypepair 1 {}", num(kt)),
             fmt::format("fix dem_gamman all property/global gamman peratomtypepair 1 {}", num(gn)),
             fmt::format("fix dem_gammat all property/global gammat peratomtypepair 1 {}", num(gt)),
             fmt::format("fix dem_cof all property/global coefficientFriction peratomtypepair 1 {}", num(mu)),
             fmt::format("pair_style gran model hertz/stiffness tangential {} limitForce {}",
                         mu > 0.0 ? "history" : "no_history",
                         d.end == CollisionEnd::delayed_recovery ? "on" : "off"),
             "pair_coeff * *"};
  d.notes = {mu > 0.0 ? "tangential history: kt = 8 G* (Mindlin), gammat = gamman"
                      : "kt = gammat = coefficientFriction = 0: frictionless",
             friction_note(mu), clamp_note(d.code, d.end),
             "gamman contains 1/m_eff: exact only for the pair it was made for (" + pair_note(p) +
                 "); other pairs get A' = A m_eff' / m_eff"};
}

void mercurydpm(Deck& d, const Pair& p, double a, double mu) {
  d.parameters = {
      {"effective_elastic_modulus", p.effective_modulus_pa, "E* = Y / (2 (1 - nu^2)) [Pa]"},
      {"dissipation", a, "the dissipative constant A [s]"},
      {"sliding_friction_coefficient", mu, "Coulomb friction coefficient [1]"},
  };
  if (mu > 0.0) {
    d.lines = {"Species<HertzianBSHPViscoelasticNormalSpecies, SlidingFrictionSpecies> species;",
               fmt::format("species.setEffectiveElasticModulus({});", num(p.effective_modulus_pa)),
               fmt::format("species.setDissipation({});", num(a)),
               fmt::format("species.setSlidingFrictionCoefficient({});", num(mu)),
               "speciesHandler.copyAndAddObject(species);"};
  } else {
    d.lines = {"Species<HertzianBSHPViscoelasticNormalSpecies> species;",
               fmt::format("species.setEffectiveElasticModulus({});", num(p.effective_modulus_pa)),
               fmt::format("species.setDissipation({});", num(a)),
               "speciesHandler.copyAndAddObject(species);"};
  }
  d.notes = {mu > 0.0 ? "SlidingFrictionSpecies: its spring is linear [N/m], not Mindlin's; set "
                        "setSlidingStiffness and setSlidingDissipation for your particle size"
                      : "no friction species: frictionless",
             friction_note(mu), clamp_note(d.code, d.end),
             "A and E* do not depend on size or mass: exact for every pair of this material"};
}

void yade(Deck& d, const Pair& p, double a, double vn, double mu) {
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
      "vn exists from YADE 2024.02a on: older versions (Debian 12's 2023.02a) reject these lines; "
      "`restitution "
      "dem --code yade --yade-version 2023.02a` prints what they can do",
      "YADE keeps beta = sigma^2 vn^(-1/5) for every contact (A = (2/3) beta (k_n0 / m_eff)^(-2/5)), so "
      "every pair gets this pair's eps(v): exact only for pairs with this pair's k_n0 / m_eff (" +
          pair_note(p) + ")"};
}

void chrono(Deck& d, const Pair& p, double a, double mu) {
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
      "Chrono's R_eff is the contact's effective curvature radius, which only the Multicore collision system "
      "sets; with Bullet every contact gets ChCollisionInfo's default 0.1 m (Kn, Gn far too large, eps far "
      "too low) unless SetDefaultEffectiveCurvatureRadius(R_eff) is called",
      friction_note(mu), clamp_note(d.code, d.end),
      "Chrono scales Kn and Gn with R_eff, not sqrt(R_eff), and Gn with m_eff: exact only for the pair it "
      "was made for (" +
          pair_note(p) + ")"};
}

}  // namespace

Code code_from_name(std::string_view name) {
  for (Code c : {Code::lammps, Code::liggghts, Code::mercurydpm, Code::yade, Code::chrono}) {
    if (name == code_name(c)) return c;
  }
  throw InvalidInput(
      fmt::format("code must be lammps, liggghts, mercurydpm, yade or chrono, got '{}'", std::string(name)));
}

const char* code_name(Code code) {
  switch (code) {
    case Code::lammps:
      return "lammps";
    case Code::liggghts:
      return "liggghts";
    case Code::mercurydpm:
      return "mercurydpm";
    case Code::yade:
      return "yade";
    case Code::chrono:
      return "chrono";
  }
  return "?";
}

bool always_clamps(Code code) {
  return code == Code::mercurydpm || code == Code::yade || code == Code::chrono;
}

Pair pair_of(const Material& material) {
  const ElasticConstants e = elastic_constants(material);
  Pair p;
  p.young_modulus_pa = material.young_modulus_pa;
  p.poisson_ratio = material.poisson_ratio;
  p.radius1_m = material.radius1_m;
  p.radius2_m = material.radius2_m;
  // elastic_constants validated the masses; recover them from m_eff's inputs.
  if (material.mass1_kg) {
    p.mass1_kg = *material.mass1_kg;
    p.mass2_kg = *material.mass2_kg;
  } else {
    p.mass1_kg = sphere_mass_kg(material.radius1_m, *material.density_kg_m3);
    p.mass2_kg = sphere_mass_kg(material.radius2_m, *material.density_kg_m3);
  }
  p.effective_modulus_pa = effective_modulus_pa(material.young_modulus_pa, material.poisson_ratio);
  p.effective_radius_m = e.effective_radius_m;
  p.effective_mass_kg = e.effective_mass_kg;
  return p;
}

Pair scaled(const Pair& pair, double factor) {
  Pair p = pair;
  const double cube = factor * factor * factor;
  p.radius1_m *= factor;
  p.radius2_m *= factor;
  p.effective_radius_m *= factor;
  p.mass1_kg *= cube;
  p.mass2_kg *= cube;
  p.effective_mass_kg *= cube;
  return p;
}

double Deck::parameter(std::string_view name) const {
  for (const Parameter& p : parameters) {
    if (p.name == name) return p.value;
  }
  throw std::out_of_range(fmt::format("deck has no parameter {}", std::string(name)));
}

void check_friction(double mu) {
  if (!std::isfinite(mu) || mu < 0.0) {
    throw InvalidInput(
        fmt::format("friction (--friction, the Coulomb mu) must be finite and >= 0, got {}", mu));
  }
}

Deck make_deck(Code code, CollisionEnd end, const Pair& pair, double dissipative_constant_s,
               double reference_velocity_m_s, double friction) {
  check_friction(friction);
  if (always_clamps(code) && end == CollisionEnd::naive) {
    throw InvalidInput(
        fmt::format("{} always clamps the normal force at zero, so it ends collisions at the "
                    "delayed-recovery end; --end naive cannot be expressed",
                    code_name(code)));
  }
  if (!std::isfinite(dissipative_constant_s) || dissipative_constant_s < 0.0) {
    throw InvalidInput(
        fmt::format("dissipative_constant must be finite and >= 0, got {}", dissipative_constant_s));
  }
  Deck d;
  d.code = code;
  d.end = end;
  switch (code) {
    case Code::lammps:
      lammps(d, pair, dissipative_constant_s, friction);
      break;
    case Code::liggghts:
      liggghts(d, pair, dissipative_constant_s, friction);
      break;
    case Code::mercurydpm:
      mercurydpm(d, pair, dissipative_constant_s, friction);
      break;
    case Code::yade:
      yade(d, pair, dissipative_constant_s, reference_velocity_m_s, friction);
      break;
    case Code::chrono:
      chrono(d, pair, dissipative_constant_s, friction);
      break;
  }
  return d;
}

double deck_beta(const Deck& deck, const Pair& other) {
  const double sqrt_r = std::sqrt(other.effective_radius_m);
  const double m = other.effective_mass_kg;
  const double e_star = other.effective_modulus_pa;
  Coefficients c;
  switch (deck.code) {
    case Code::lammps:
      c = {hertz_stiffness(effective_modulus_pa(deck.parameter("E"), deck.parameter("nu")),
                           other.effective_radius_m),
           deck.parameter("eta_n0") * m * sqrt_r};
      break;
    case Code::liggghts:
      c = {deck.parameter("kn") * sqrt_r, deck.parameter("gamman") * m * sqrt_r};
      break;
    case Code::mercurydpm:
      c = {hertz_stiffness(deck.parameter("effective_elastic_modulus"), other.effective_radius_m),
           2.0 * deck.parameter("dissipation") * deck.parameter("effective_elastic_modulus") * sqrt_r};
      break;
    case Code::yade: {
      const double k = hertz_stiffness(e_star, other.effective_radius_m) / m;
      c = law_coefficients(other, yade_dissipative_constant(deck.parameter("en"), deck.parameter("vn"), k));
      break;
    }
    case Code::chrono:
      c = {other.effective_radius_m * deck.parameter("Kn"),
           other.effective_radius_m * m * deck.parameter("Gn")};
      break;
  }
  return beta_of_coefficients(c.elastic, c.damping, m);
}

}  // namespace restitution::dem
