// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The scene runner's links to the modules other than the solver: the published series and approximants
// (series module), the power-law fit (asymptotics module), the stability report and the work-precision
// measurement. Each fills typed results (scene_results.hpp); the wording of the report is the CLI's.
#include <filesystem>
#include <vector>

#include "scene/scene.hpp"
#include "scene/scene_run.hpp"
#include "scene/scene_studies.hpp"

namespace restitution::scene::detail {

// Approximations of ε at the sweep's ζ values for the requested ends, then (`asymptotics`) the derived
// large-ζ laws of the requested ends.
void add_approximations(const Sweep& sweep, const std::vector<double>& zeta, SweepExtras& extras);

// Power-law fits ε ≈ a ζ^p over ζ >= zeta_min for each requested end, from the solved ε values, and the
// fits with too few points recorded as FitShortfall.
void add_power_law_fits(const Sweep& sweep, const std::vector<double>& zeta,
                        const std::vector<const CollisionResult*>& results, SweepExtras& extras);

// Runs a stability study (stability_report.hpp, at the scene's tolerance) and summarises it, or a
// work-precision study (work_precision.hpp, against the reference file) with its highlights per engine and
// end.
StudyOutcome run_study(const ExternalStudy& study, double tolerance,
                       const std::filesystem::path& reference_file);

}  // namespace restitution::scene::detail
