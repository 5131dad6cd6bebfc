#pragma once
// The scene runner's links to the modules other than the solver: the published series and approximants
// (series module) and the power-law fit (asymptotics module). Each fills what this build provides and says
// in a note what it cannot.
#include <vector>

#include "restitution/scene.hpp"
#include "restitution/scene_run.hpp"

namespace restitution::scene::detail {

// Approximations of ε at the sweep's ζ values for the requested ends.
void add_approximations(const Sweep& sweep, const std::vector<double>& zeta, SweepExtras& extras);

// Power-law fits ε ≈ a ζ^p over ζ >= zeta_min for each requested end, from the solved ε values.
void add_power_law_fits(const Sweep& sweep, const std::vector<double>& zeta,
                        const std::vector<const CollisionResult*>& results, SweepExtras& extras);

// What this build can say about a work-precision or stability study.
std::string study_note(const ExternalStudy& study);

}  // namespace restitution::scene::detail
