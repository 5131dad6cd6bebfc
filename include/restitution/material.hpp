// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A pair of viscoelastic spheres described by material data in SI units, and the constants of their
// collision equation (docs/design.md §1; 1999 paper Eqs. 1-5):
//     ρ = 2 Y sqrt(R_eff) / (3 (1 - ν²)),  R_eff = R1 R2 / (R1 + R2),  m_eff = m1 m2 / (m1 + m2),
//     A = (1/3) (3η2 - η1)² / (3η2 + 2η1) · (1 - ν²)(1 - 2ν) / (Y ν²).
// Both spheres are of the same material. Error messages name the offending key as scene files spell it.
#include <array>
#include <optional>

#include "restitution/units.hpp"

namespace restitution {

struct Viscosities {
  double eta1_pa_s = 0.0;  // η1, shear viscosity [Pa s]
  double eta2_pa_s = 0.0;  // η2, bulk viscosity [Pa s]
};

struct Material {
  double young_modulus_pa = 0.0;  // Y > 0
  double poisson_ratio = 0.0;     // ν in (-1, 0.5)
  double radius1_m = 0.0;         // R1 > 0
  double radius2_m = 0.0;         // R2 > 0
  // Masses: either both given, or computed from the density as (4/3) π R³ density.
  std::optional<double> density_kg_m3;
  std::optional<double> mass1_kg, mass2_kg;
  // Dissipation: exactly one of the dissipative constant A and the viscosities.
  std::optional<double> dissipative_constant_s;
  std::optional<Viscosities> viscosities;
};

struct ElasticConstants {
  double effective_radius_m = 0.0;
  double effective_mass_kg = 0.0;
  double elastic_constant = 0.0;  // ρ [N m^{-3/2}] = [kg s^-2 m^-1/2]
  double k = 0.0;                 // ρ / m_eff [s^-2 m^-1/2]
};

struct MaterialConstants {
  ElasticConstants elastic;
  double dissipative_constant_s = 0.0;  // A [s]
  HertzConstants hertz;                 // k, γ, β
};

// The elastic part only (the dissipation fields are ignored): what calibration needs to turn β into A.
ElasticConstants elastic_constants(const Material& material);

// Validates every field (InvalidInput naming the key: young_modulus, poisson_ratio, radius1, radius2,
// density, mass1, mass2, dissipative_constant, viscosities) and derives the constants.
MaterialConstants material_constants(const Material& material);

// The fields a front end reads for a Material, each optional: a scene's [material] table, Python's
// restitution.Material and the command line's material options all assemble a Material through
// material_from_fields, so the rules (one radius for both spheres or a pair, one mass or a pair) and their
// words have one home.
struct MaterialFields {
  std::optional<double> young_modulus_pa;
  std::optional<double> poisson_ratio;
  std::optional<double> radius_m;                // both spheres
  std::optional<std::array<double, 2>> radii_m;  // or one each
  std::optional<double> density_kg_m3;
  std::optional<double> mass_kg;                   // both spheres
  std::optional<std::array<double, 2>> masses_kg;  // or one each
  std::optional<double> dissipative_constant_s;
  std::optional<Viscosities> viscosities;
};

// A missing or contradictory field: the key as scene files spell it, and what is wrong with it.
struct MaterialFieldProblem {
  const char* field = "";
  const char* message = "";
};
std::optional<MaterialFieldProblem> material_fields_problem(const MaterialFields& fields);

// The Material of the fields; throws InvalidInput "material: FIELD: MESSAGE" for
// material_fields_problem(fields). The values themselves are checked by check_material.
Material material_from_fields(const MaterialFields& fields);

// Validates what a material gives: the elastic data always, the dissipation when given (without it a
// material can still be calibrated, which computes A). Throws InvalidInput naming the key.
void check_material(const Material& material);

}  // namespace restitution
