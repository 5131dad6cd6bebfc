// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A scene's [[adhesion]] section computed (docs/scenes.md, docs/adhesion.md): the adhesive contact of the
// section's material, its damping (calibrated from eps at a velocity, or the material's A), every impact
// speed solved as `restitution eps --adhesion` solves it, the sticking speed and the elastic closed forms.
// Typed values; the CLI writes the CSV, the figure and the words.
#include <cstddef>
#include <optional>
#include <vector>

#include "restitution/adhesion.hpp"
#include "restitution/adhesive_calibration.hpp"
#include "scene/scene.hpp"
#include "scene/scene_adhesion.hpp"

namespace restitution::scene {

struct AdhesionOutcome {
  AdhesiveContact contact;              // with the damping used
  double dissipative_constant_s = 0.0;  // A [s] (LAMMPS's damp = 2AE*/m_eff for jkr-lammps, dmt and sjkr)
  std::optional<AdhesiveDampingCalibration> calibration;  // when the section gave eps and velocity
  double tolerance = 0.0;                                 // of every solve
  StickingSpeed sticking;
  double elastic_hysteresis_work_j = 0.0;  // W of the break rule, undamped (0 for dmt and sjkr)
  double break_overlap_m = 0.0;
  std::vector<AdhesiveCollision> collisions;  // parallel to the section's speeds
  std::size_t stuck = 0;                      // collisions whose spheres stayed bound
};

// Solves at the section's tolerance, else the scene's. Throws InvalidInput naming the scene, the section and
// the problem (an eps the undamped model does not exceed at that velocity), NumericalFailure when CVODE
// fails.
AdhesionOutcome run_adhesion_section(const Scene& scene, const AdhesionTask& task);

}  // namespace restitution::scene
