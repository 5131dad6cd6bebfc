#pragma once
// The approximations a scene can set beside the numerics: their names in scene files, their table columns,
// their sources and the end of the collision each describes (evaluated with the published coefficients).
#include <array>

#include "restitution/collision_solver.hpp"
#include "restitution/series.hpp"

namespace restitution::scene::detail {

// Names in scene files are series::approximation_name(kind) (src/series_study/series_named.hpp), the
// spelling every command shares.
struct ApproximationInfo {
  series::Approximation kind;
  const char* label;   // column suffix in tables
  const char* source;  // what it is, for the report
  CollisionEnd end;    // the end of the collision it describes
};

inline constexpr std::array<ApproximationInfo, 7> kApproximations{{
    {series::Approximation::naive_series, "naive_series", "naive series, 2008 paper Table III (c_1 ... c_10)",
     CollisionEnd::naive},
    {series::Approximation::delayed_recovery_series, "delayed_recovery_series",
     "delayed-recovery series, 2008 paper Table V (h_0 ... h_20)", CollisionEnd::delayed_recovery},
    {series::Approximation::pade_1999, "pade_1999",
     "1999 paper's Padé [1/4] (Eq. 35 with a_3, a_4 of Eq. 33)", CollisionEnd::naive},
    {series::Approximation::pade_1999_corrected, "pade_1999_corrected",
     "1999 paper's Padé [1/4] form with the recomputed a_3, a_4 (docs/series.md)", CollisionEnd::naive},
    {series::Approximation::simple_theory_1999, "simple_theory_1999",
     "1999 paper's simple theory eps + w eps^(3/5) = 1 (Eq. 27)", CollisionEnd::naive},
    {series::Approximation::pade_2011_1_4, "pade_2011_1_4", "Müller & Pöschel 2011 Padé [1/4] in sqrt(zeta)",
     CollisionEnd::delayed_recovery},
    {series::Approximation::pade_2011_3_6, "pade_2011_3_6", "Müller & Pöschel 2011 Padé [3/6] in sqrt(zeta)",
     CollisionEnd::delayed_recovery},
}};

const ApproximationInfo& approximation_info(series::Approximation kind);

}  // namespace restitution::scene::detail
