#pragma once
// The scene runner's links to the modules other than the solver: the published series and approximants
// (series module), the power-law fit (asymptotics module), the stability report and the work-precision
// measurement. Each fills what this build provides and says in a note what it cannot.
#include <filesystem>
#include <vector>

#include "scene/scene.hpp"
#include "scene/scene_run.hpp"

namespace restitution::scene::detail {

// Approximations of ε at the sweep's ζ values for the requested ends.
void add_approximations(const Sweep& sweep, const std::vector<double>& zeta, SweepExtras& extras);

// Power-law fits ε ≈ a ζ^p over ζ >= zeta_min for each requested end, from the solved ε values, and the
// derived large-ζ laws as columns when the sweep asks for `asymptotics`.
void add_power_law_fits(const Sweep& sweep, const std::vector<double>& zeta,
                        const std::vector<const CollisionResult*>& results, SweepExtras& extras);

// Runs a stability study (stability_report.hpp, at the scene's tolerance) and summarises it in one line, or
// a work-precision study (work_precision.hpp, against the reference file) with one line per engine and end.
StudyOutcome run_study(const ExternalStudy& study, double tolerance,
                       const std::filesystem::path& reference_file);

}  // namespace restitution::scene::detail
