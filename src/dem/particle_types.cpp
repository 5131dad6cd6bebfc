// SPDX-License-Identifier: BSD-3-Clause
#include "dem/particle_types.hpp"

#include <fmt/core.h>

#include <cmath>

#include "restitution/errors.hpp"
#include "restitution/material.hpp"
#include "restitution/units.hpp"

namespace restitution::dem {
namespace {

// Value `i` of a list that has one value (for every type) or one per type.
double per_type(const std::vector<double>& values, std::size_t i) {
  return values.size() == 1 ? values[0] : values[i];
}

void check_length(const std::vector<double>& values, std::size_t types, const char* option) {
  if (values.size() != 1 && values.size() != types) {
    throw InvalidInput(fmt::format("{} has {} values for {} radii: give one value or one per radius", option,
                                   values.size(), types));
  }
}

}  // namespace

std::vector<ParticleType> particle_types(const std::vector<double>& radii_m,
                                         const std::vector<double>& densities_kg_m3,
                                         const std::vector<double>& young_moduli_pa,
                                         const std::vector<double>& poisson_ratios) {
  const std::size_t n = radii_m.size();
  if (n == 0) throw InvalidInput("--radius needs at least one radius");
  check_length(densities_kg_m3, n, "--density");
  check_length(young_moduli_pa, n, "--young-modulus");
  check_length(poisson_ratios, n, "--poisson-ratio");
  std::vector<ParticleType> types;
  for (std::size_t i = 0; i < n; ++i) {
    ParticleType t{radii_m[i], per_type(densities_kg_m3, i), per_type(young_moduli_pa, i),
                   per_type(poisson_ratios, i)};
    // The material's own validation (positive radius and density, Y > 0, nu in (-1, 0.5)).
    Material m;
    m.young_modulus_pa = t.young_modulus_pa;
    m.poisson_ratio = t.poisson_ratio;
    m.radius1_m = m.radius2_m = t.radius_m;
    m.density_kg_m3 = t.density_kg_m3;
    try {
      (void)elastic_constants(m);
    } catch (const InvalidInput& e) {
      throw InvalidInput(fmt::format("atom type {}: {}", i + 1, e.what()));
    }
    t.material = 0;
    for (const ParticleType& before : types) {
      if (before.young_modulus_pa == t.young_modulus_pa && before.poisson_ratio == t.poisson_ratio &&
          before.density_kg_m3 == t.density_kg_m3) {
        t.material = before.material;
        break;
      }
    }
    if (t.material == 0) {
      int highest = 0;
      for (const ParticleType& before : types) highest = std::max(highest, before.material);
      t.material = highest + 1;
    }
    types.push_back(t);
  }
  return types;
}

Pair type_pair(const ParticleType& a, const ParticleType& b) {
  Pair p;
  p.radius1_m = a.radius_m;
  p.radius2_m = b.radius_m;
  p.mass1_kg = sphere_mass_kg(a.radius_m, a.density_kg_m3);
  p.mass2_kg = sphere_mass_kg(b.radius_m, b.density_kg_m3);
  p.effective_radius_m = a.radius_m * b.radius_m / (a.radius_m + b.radius_m);
  p.effective_mass_kg = p.mass1_kg * p.mass2_kg / (p.mass1_kg + p.mass2_kg);
  if (a.young_modulus_pa == b.young_modulus_pa && a.poisson_ratio == b.poisson_ratio) {
    p.young_modulus_pa = a.young_modulus_pa;
    p.poisson_ratio = a.poisson_ratio;
    p.effective_modulus_pa = effective_modulus_pa(a.young_modulus_pa, a.poisson_ratio);
    return p;
  }
  const auto compliance = [](const ParticleType& t) {
    return (1.0 - t.poisson_ratio * t.poisson_ratio) / t.young_modulus_pa;
  };
  const auto shear_compliance = [](const ParticleType& t) {
    return 2.0 * (2.0 - t.poisson_ratio) * (1.0 + t.poisson_ratio) / t.young_modulus_pa;
  };
  const double e_star = 1.0 / (compliance(a) + compliance(b));
  const double g_star = 1.0 / (shear_compliance(a) + shear_compliance(b));
  const double r = g_star / e_star;
  p.poisson_ratio = (1.0 - 4.0 * r) / (1.0 - 2.0 * r);
  p.young_modulus_pa = 2.0 * (1.0 - p.poisson_ratio * p.poisson_ratio) * e_star;
  p.effective_modulus_pa = e_star;
  return p;
}

SizeClasses log_size_classes(double min_radius_m, double max_radius_m, int classes) {
  if (!(std::isfinite(min_radius_m) && std::isfinite(max_radius_m) && min_radius_m > 0.0 &&
        max_radius_m > min_radius_m)) {
    throw InvalidInput(
        fmt::format("--radius-range must be RMIN:RMAX:N with 0 < RMIN < RMAX (m), got RMIN {}, RMAX {}",
                    min_radius_m, max_radius_m));
  }
  if (classes < 1 || classes > 100) {
    throw InvalidInput(fmt::format("--classes must be in [1, 100], got {}", classes));
  }
  SizeClasses s;
  const double ratio = max_radius_m / min_radius_m;
  for (int k = 0; k <= classes; ++k) {
    s.edges_m.push_back(k == classes ? max_radius_m : min_radius_m * std::pow(ratio, double(k) / classes));
  }
  for (int k = 0; k < classes; ++k) s.radii_m.push_back(std::sqrt(s.edges_m[k] * s.edges_m[k + 1]));
  return s;
}

}  // namespace restitution::dem
