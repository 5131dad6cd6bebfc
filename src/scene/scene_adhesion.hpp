// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A scene's [[adhesion]] section: ε(v) of two adhesive spheres of a material and their sticking speed
// (docs/adhesion.md, docs/scenes.md). The keys mean what `restitution eps --adhesion` and `sweep --adhesion`
// take: model, surface_energy (cohesion_energy_density for sjkr), the damping from eps at a velocity (as
// `calibrate --adhesion`) or the material's dissipative constant, the impact speeds and the tolerance.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "restitution/adhesion.hpp"
#include "restitution/material.hpp"

namespace restitution::scene {

struct AdhesionTask {
  std::string name;
  std::string title;
  std::string material;  // a [materials.X]: Y, ν, radii, density or masses (and A without eps)
  AdhesiveModel model = AdhesiveModel::jkr;
  std::optional<double> surface_energy_j_per_m2;           // γ per surface (jkr, jkr-lammps, dmt)
  std::optional<double> cohesion_energy_density_j_per_m3;  // k_c (sjkr)
  // The damping: with velocity, A calibrated to give eps there; without, the material's A (0: elastic).
  std::optional<double> eps;
  std::optional<double> velocity_m_s;
  std::vector<double> speeds_m_s;   // impact speeds of the table
  std::optional<double> tolerance;  // of every adhesive solve; default: the scene's
  int line = 0;
};

namespace detail {
class TomlReader;
// Reads the keys of one [[adhesion]] (name already read): material, model, surface_energy,
// cohesion_energy_density, eps, velocity, speeds, tolerance, title. Throws InvalidInput naming the key.
AdhesionTask read_adhesion_task(TomlReader& r, std::string name,
                                const std::map<std::string, Material>& materials);
}  // namespace detail

}  // namespace restitution::scene
