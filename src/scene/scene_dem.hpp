// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A scene's [[dem]] section (docs/dem.md, docs/scenes.md): a DEM code's input lines for a scene material, the
// ε(v) they give and, for LAMMPS and LIGGGHTS, the ε(v) the code itself measures on them. Typed values; the
// CLI writes the CSV, the plot and the words (cli/scene/scene_dem.cpp).
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "dem/dem_codes.hpp"
#include "dem/dem_parameters.hpp"
#include "dem/lines_check.hpp"
#include "dem/yade_versions.hpp"
#include "restitution/collision_solver.hpp"
#include "restitution/material.hpp"

namespace restitution::scene {

struct Scene;

struct DemTask {
  std::string name;
  std::string title;
  std::string material;  // a [materials.X] of this scene, whose A the lines take unless inputs.eps is given
  // The study's inputs as the keys give them (the rows of dem/dem_parameters.hpp): eps with velocity
  // calibrate A; the accuracy is the scene's tolerance.
  dem::DemInputs inputs;
  bool run_code = true;  // LAMMPS and LIGGGHTS: run the code at each speed
  int line = 0;
};

// YADE (not run by scenes): the lines are for the yade on PATH or, without one, the newest version; on a
// YADE that cannot express the law they are the constant-ε lines, and `exact_deck` the law's own lines.
struct DemYadeTarget {
  dem::TargetedYade yade;
  std::optional<dem::Deck> exact_deck;
};

struct DemOutcome {
  dem::CodeComparison comparison;     // the deck, restitution's ε and, when it ran, the code's
  bool code_not_installed = false;    // asked to run a code the scene runs, which is not on PATH
  std::optional<DemYadeTarget> yade;  // codes with a version query (YADE)
};

// Throws InvalidInput for a task the code cannot express (an end it cannot reach).
DemOutcome run_dem_section(const Scene& scene, const DemTask& task);

namespace detail {
class TomlReader;
// Reads the keys of one [[dem]] (name already read). Throws InvalidInput naming the key.
DemTask read_dem_task(TomlReader& r, std::string name, const std::map<std::string, Material>& materials);
}  // namespace detail

}  // namespace restitution::scene
