// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A scene's [[oblique]] section: oblique impacts of a material's spheres (or a sphere on a wall) with one or
// more LAMMPS tangential models over impact angles and initial spins, and Maw, Barber & Fawcett's diagram
// (docs/oblique.md, docs/scenes.md). The keys mean what `restitution oblique`'s options mean.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "restitution/material.hpp"
#include "restitution/solve_types.hpp"
#include "restitution_oblique/oblique_study.hpp"

namespace restitution::scene {

struct ObliqueTask {
  std::string name;
  std::string title;
  std::string material;             // a [materials.X]: radius (radius2), density or mass, and A if given
  std::vector<std::string> models;  // tangential models, LAMMPS's keywords; default mindlin (as `dem`)
  // The study's inputs as the keys give them (the rows of restitution_oblique/oblique_parameters.hpp): the
  // material, its A and the model are set per model when the section runs (scene_oblique_run.cpp).
  oblique::ObliqueInputs inputs;
  // One section may sweep several models, whose stiffnesses differ in unit: k_t of linear_history (N/m,
  // inputs.tangential_stiffness) and of the models whose k_t is per contact radius, the mindlin family and
  // liggghts_history (N/m², default 8 G*).
  std::optional<double> mindlin_stiffness;
  bool plot = true;  // Maw's diagram (needs friction > 0)
  int line = 0;
};

namespace detail {
class TomlReader;
// Reads the keys of one [[oblique]] (name already read): material, model, friction, angles, spins, wall,
// impact_velocity (old name: speed, read with a line in `warnings`), tangential_stiffness, mindlin_stiffness,
// tangential_damping, end, torque_arm, fixed_normal, wall_young_modulus, wall_poisson_ratio, tolerance, plot,
// title. Throws InvalidInput naming the key.
ObliqueTask read_oblique_task(TomlReader& r, std::string name,
                              const std::map<std::string, Material>& materials,
                              std::vector<std::string>& warnings);
}  // namespace detail

}  // namespace restitution::scene
