// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The wording of a scene report for the studies' typed results (scene/scene_results.hpp): what an
// approximation is and where it comes from, how it compares with the numerics, why a fit or a study has no
// result, and the summary lines of the stability and work-precision studies. Formatting only.
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "scene/scene_results.hpp"
#include "scene/scene_studies.hpp"

namespace restitution::cli {

// What the column evaluates and where it comes from.
std::string approximation_source(const scene::ApproximationColumn& column);
// The column's largest |relative difference| from the numerics and the points it is taken over (of `points`).
std::string comparison_text(const scene::ApproximationComparison& comparison, std::size_t points);
std::string fit_shortfall_text(const scene::FitShortfall& shortfall);
// The report's lines for a [[stability]] or [[work_precision]] study.
std::vector<std::string> study_lines(const scene::ExternalStudy& study, const scene::StudyOutcome& outcome);
// The sections that compute their collisions outside the scene's shared plan (the rows of
// scene/scene_sections.hpp with own_solves words) and how, for the report's account of the work: "" when the
// scene has none.
std::string own_collisions_text(const scene::Scene& scene);

}  // namespace restitution::cli
