// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The atom types of a polydisperse DEM system (docs/dem.md, "Polydisperse sets"): one radius, density and
// elastic material per type, and the contact pair of two types with its own E*, G*, R_eff and m_eff.
#include <vector>

#include "dem/deck.hpp"

namespace restitution::dem {

struct ParticleType {
  double radius_m = 0.0;
  double density_kg_m3 = 0.0;
  double young_modulus_pa = 0.0;
  double poisson_ratio = 0.0;
  int material = 1;  // 1-based: types with the same (Y, nu, density) share a material number
};

// Types 1..N from per-type lists: `radii_m` gives N; each other list has one value (every type) or N. A
// length mismatch throws InvalidInput naming the option (--density, --young-modulus, --poisson-ratio); a
// value out of range throws InvalidInput naming it and the type.
std::vector<ParticleType> particle_types(const std::vector<double>& radii_m,
                                         const std::vector<double>& densities_kg_m3,
                                         const std::vector<double>& young_moduli_pa,
                                         const std::vector<double>& poisson_ratios);

// The contact of a sphere of type a with one of type b, as the law sees it: E* from
// 1/E* = (1 - nu_a^2)/Y_a + (1 - nu_b^2)/Y_b, R_eff, m_eff. Its young_modulus_pa and poisson_ratio are the
// one (Y, nu) that a code mixing two equal values (LAMMPS' hertz/material, Mindlin's NULL k_t) turns into
// this pair's E* and Mindlin G*, 1/G* = 2 (2 - nu_a)(1 + nu_a)/Y_a + 2 (2 - nu_b)(1 + nu_b)/Y_b: for one
// material the material's own Y and nu; for two, nu = (1 - 4 r)/(1 - 2 r) with r = G*/E* (it lies between
// nu_a and nu_b) and Y = 2 (1 - nu^2) E*.
Pair type_pair(const ParticleType& a, const ParticleType& b);

// A size range [min, max] binned into `classes` log-spaced classes: edges min (max/min)^(k/classes), each
// class represented by the geometric mean of its edges (its log-midpoint). InvalidInput naming
// --radius-range / --classes for 0 < min < max and 1 <= classes <= 100 unmet.
struct SizeClasses {
  std::vector<double> edges_m;  // classes + 1 values, from min to max
  std::vector<double> radii_m;  // one per class
};
SizeClasses log_size_classes(double min_radius_m, double max_radius_m, int classes);

}  // namespace restitution::dem
