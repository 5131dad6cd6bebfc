// SPDX-License-Identifier: BSD-3-Clause
#include "adhesion/adhesive_scales.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "adhesion/jkr_branch.hpp"
#include "restitution/errors.hpp"

namespace restitution::adhesion {
namespace {

void require_positive(double value, const char* what) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw InvalidInput(fmt::format("{} must be finite and positive (got {})", what, value));
  }
}

void require_non_negative(double value, const char* what) {
  if (!std::isfinite(value) || value < 0.0) {
    throw InvalidInput(fmt::format("{} must be finite and not negative (got {})", what, value));
  }
}

constexpr double kPi = std::numbers::pi;

void check_sjkr_contact(const AdhesiveContact& contact) {
  require_positive(contact.cohesion_energy_density_j_per_m3, "the cohesion energy density k_c [J/m³]");
  require_non_negative(contact.damping, "the damping coefficient gamman [1/(m s)]");
  const double r1 = contact.sphere_radius_1_m, r2 = contact.sphere_radius_2_m;
  if (r1 == 0.0 && r2 == 0.0) return;  // equal spheres
  require_positive(r1, "the first sphere's radius [m]");
  require_positive(r2, "the second sphere's radius [m]");
  const double effective = r1 * r2 / (r1 + r2);
  if (std::abs(effective - contact.effective_radius_m) > 1e-12 * effective) {
    throw InvalidInput(
        fmt::format("the sphere radii {} m and {} m give R = {} m, not the effective radius {} m", r1, r2,
                    effective, contact.effective_radius_m));
  }
}

// sjkr: Hertz ρδ^{3/2} against the small-overlap cohesion 2πk_cRδ, equal at δ = L.
void scale_sjkr(const AdhesiveContact& contact, ScaledAdhesion& scaled, double& force_n) {
  const double radius = contact.effective_radius_m;
  const double stiffness = (4.0 / 3.0) * contact.effective_modulus_pa * std::sqrt(radius);  // ρ
  const double cohesion = 2.0 * kPi * contact.cohesion_energy_density_j_per_m3 * radius;    // [N/m]
  scaled.length_m = std::pow(cohesion / stiffness, 2.0);
  force_n = cohesion * scaled.length_m;
  scaled.bound_level = -0.05;
  const bool equal = contact.sphere_radius_1_m == 0.0 && contact.sphere_radius_2_m == 0.0;
  scaled.sjkr_radii.first = (equal ? 2.0 * radius : contact.sphere_radius_1_m) / scaled.length_m;
  scaled.sjkr_radii.second = (equal ? 2.0 * radius : contact.sphere_radius_2_m) / scaled.length_m;
  scaled.sjkr_radii.effective = radius / scaled.length_m;
}

}  // namespace

void check_contact(const AdhesiveContact& contact) {
  require_positive(contact.effective_modulus_pa, "the effective modulus E* [Pa]");
  require_positive(contact.effective_radius_m, "the effective radius R [m]");
  require_positive(contact.effective_mass_kg, "the effective mass m* [kg]");
  if (contact.model == AdhesiveModel::sjkr) {
    check_sjkr_contact(contact);
    return;
  }
  require_non_negative(contact.surface_energy_j_per_m2, "the surface energy γ [J/m²]");
  if (contact.surface_energy_j_per_m2 == 0.0) {
    throw InvalidInput(
        "the surface energy γ is 0: without adhesion the collision is the non-adhesive law's (--law "
        "viscoelastic-hertz with the same damping)");
  }
  require_non_negative(contact.damping, contact.model == AdhesiveModel::jkr
                                            ? "the dissipative constant A [s]"
                                            : "the damping coefficient damp [1/(m s)]");
}

ScaledAdhesion scale_adhesion(const AdhesiveContact& contact) {
  check_contact(contact);
  const double radius = contact.effective_radius_m;
  const double gamma = contact.surface_energy_j_per_m2;
  ScaledAdhesion scaled;
  scaled.model = contact.model;
  double force_n = 0.0;
  if (contact.model == AdhesiveModel::dmt) {
    const double stiffness = (4.0 / 3.0) * contact.effective_modulus_pa * std::sqrt(radius);  // ρ
    force_n = 4.0 * kPi * gamma * radius;                                                     // F_D
    scaled.length_m = std::pow(force_n / stiffness, 2.0 / 3.0);
    scaled.bound_level = -0.3;
  } else if (contact.model == AdhesiveModel::sjkr) {
    scale_sjkr(contact, scaled, force_n);
  } else {
    const double work_of_adhesion = 2.0 * gamma;  // w
    const double a_unit = std::cbrt(kPi * work_of_adhesion * radius * radius / contact.effective_modulus_pa);
    force_n = kPi * work_of_adhesion * radius;
    scaled.length_m = a_unit * a_unit / radius;
    scaled.break_radius = contact.model == AdhesiveModel::jkr_lammps ? kForceControlledBreakRadius
                                                                     : kDisplacementControlledBreakRadius;
    scaled.break_energy = jkr_break_work(scaled.break_radius);
    scaled.bound_level = 0.0;
  }
  scaled.time_s = std::sqrt(contact.effective_mass_kg * scaled.length_m / force_n);
  scaled.energy_j = force_n * scaled.length_m;
  switch (contact.model) {
    case AdhesiveModel::jkr_lammps:
      scaled.damping =
          contact.damping * std::sqrt(scaled.length_m * radius) * scaled.time_s;  // A = sqrt(δ0 R)
      break;
    case AdhesiveModel::jkr:
      scaled.damping = contact.damping / scaled.time_s;
      break;
    case AdhesiveModel::dmt:
    case AdhesiveModel::sjkr:
      scaled.damping = contact.damping * std::sqrt(radius * scaled.length_m) * scaled.time_s;
      break;
  }
  if (!std::isfinite(scaled.time_s) || !std::isfinite(scaled.damping) || scaled.length_m <= 0.0) {
    throw InvalidInput(
        fmt::format("the adhesive contact's scales are not representable in double (length {} m, "
                    "time {} s): the parameters are too extreme",
                    scaled.length_m, scaled.time_s));
  }
  return scaled;
}

double branch_potential(const ScaledAdhesion& scaled, double position) {
  const AdhesiveModel model = scaled.model;
  if (model == AdhesiveModel::sjkr) return sjkr_potential(scaled.sjkr_radii, position);
  if (model == AdhesiveModel::dmt) {
    const double u2 = position * position;
    return 0.4 * u2 * u2 * position - u2;  // ∫0^x (x'^{3/2} − 1) dx', x = u²
  }
  return jkr_potential(position);
}

double scaled_overlap(AdhesiveModel model, double position) {
  return model == AdhesiveModel::dmt || model == AdhesiveModel::sjkr ? position * position
                                                                     : jkr_overlap(position);
}

}  // namespace restitution::adhesion
