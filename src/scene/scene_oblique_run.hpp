// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A scene's [[oblique]] section computed (docs/scenes.md, docs/oblique.md): each tangential model's sweep
// over the section's angles and spins, solved as `restitution oblique` solves it (one path: the section's
// keys become the study's inputs), each model's sticking limit where Maw's diagram is drawn, and the numbers
// the report quotes. Typed values; the CLI writes the CSV, the plot and the words.
#include <cstddef>
#include <vector>

#include "restitution_oblique/oblique_study.hpp"
#include "scene/scene.hpp"
#include "scene/scene_oblique.hpp"

namespace restitution::scene {

struct ObliqueModelRun {
  oblique::ObliqueSetup setup;
  std::vector<oblique::ObliqueImpact> impacts;
  // The sticking limit e_t(μ → ∞), Maw's diagram's reference: computed only where the diagram is drawn
  // (ObliqueOutcome::plotted), NaN with an empty failure otherwise.
  oblique::StickingLimit sticking;
  // e_t's range over the impacts that have one (±inf: none), the impacts sliding for at least 99 % of the
  // contact (with damping the contact sticks for its first instants: the damping's part of the cap), and
  // the impacts that failed.
  double lowest_et = 0.0;
  double highest_et = 0.0;
  std::size_t sliding = 0;
  std::size_t failed = 0;
};

struct ObliqueOutcome {
  std::vector<ObliqueModelRun> runs;  // one per model, in the section's order
  bool plotted = false;               // plot = true and μ > 0: Maw's diagram and the sticking limits
  // ε depends on the normal speed v cos θ: its range over the first model's solved impacts (±HUGE_VAL:
  // none), and the first solved impact's, which draws the diagram's gross-slip line (NaN: none).
  double eps_low = 0.0;
  double eps_high = 0.0;
  double first_eps = 0.0;
  double maw_chi = 0.0;  // Maw's χ of the first model's setup
};

// Throws InvalidInput naming the scene, the section and the problem when an impact cannot be solved.
ObliqueOutcome run_oblique_section(const Scene& scene, const ObliqueTask& task);

}  // namespace restitution::scene
