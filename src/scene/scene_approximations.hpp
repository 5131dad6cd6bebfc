// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The approximations a scene can set beside the numerics: their names in scene files, their table columns
// and the end of the collision each describes (evaluated with the published coefficients). What each is and
// where it comes from is the report's wording (src/cli/scene/scene_text.cpp).
#include <array>

#include "restitution/collision_solver.hpp"
#include "restitution/series.hpp"

namespace restitution::scene::detail {

// Names in scene files are series::approximation_name(kind) (restitution_series_study/series_named.hpp), the
// spelling every command shares.
struct ApproximationInfo {
  series::Approximation kind;
  const char* label;  // column suffix in tables
  CollisionEnd end;   // the end of the collision it describes
};

inline constexpr std::array<ApproximationInfo, 7> kApproximations{{
    {series::Approximation::naive_series, "naive_series", CollisionEnd::naive},
    {series::Approximation::delayed_recovery_series, "delayed_recovery_series",
     CollisionEnd::delayed_recovery},
    {series::Approximation::pade_1999, "pade_1999", CollisionEnd::naive},
    {series::Approximation::pade_1999_corrected, "pade_1999_corrected", CollisionEnd::naive},
    {series::Approximation::simple_theory_1999, "simple_theory_1999", CollisionEnd::naive},
    {series::Approximation::pade_2011_1_4, "pade_2011_1_4", CollisionEnd::delayed_recovery},
    {series::Approximation::pade_2011_3_6, "pade_2011_3_6", CollisionEnd::delayed_recovery},
}};

const ApproximationInfo& approximation_info(series::Approximation kind);

}  // namespace restitution::scene::detail
