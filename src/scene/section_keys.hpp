// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Key checks that several scene sections share: coefficients of restitution, positive values, ζ in the
// checked range and the `end`, `ends` and `law` keys. Each fails through the reader, naming the file, line
// and key.
#include <vector>

#include "restitution/collision_solver.hpp"
#include "restitution/contact_law.hpp"

namespace restitution::scene::detail {

class TomlReader;

// A coefficient of restitution: strictly between 0 and 1.
void check_eps(const TomlReader& r, const char* key, const std::vector<double>& values);
void check_positive(const TomlReader& r, const char* key, const std::vector<double>& values);
// 0 <= ζ <= kLargestCheckedZeta.
void check_zeta(const TomlReader& r, const std::vector<double>& zeta);
// `end = "naive" | "delayed-recovery"`; CalibrationRequest's default when absent.
CollisionEnd read_end(TomlReader& r);
// `ends = "naive" | "delayed-recovery" | "both"` or a list of them; both when absent.
EndSet read_ends(TomlReader& r);
// `law = "NAME"` (law_names()); viscoelastic Hertz when absent.
LawKind read_law(TomlReader& r);
// The ζ values of a law other than viscoelastic Hertz: a requested naive end must exist at every ζ (below the
// critical ζ of Tsuji and the dash-pot).
void check_law_zeta(TomlReader& r, LawKind law, EndSet ends, const std::vector<double>& zeta);

}  // namespace restitution::scene::detail
