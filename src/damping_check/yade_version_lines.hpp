// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `restitution dem --code yade` for a named YADE version (docs/dem.md, YADE): a version with `vn` (2024.02a
// on) keeps the exact law's (en, vn) lines; one without (Debian 12's 2023.02a) gets the Tsuji-type `betan`
// that gives the law's ε at the reference speed, the one ε those lines give at every speed (the inverse of
// the thornton-2013 recipe, whose γ is YADE's betan), and the exact lines only as a labelled alternative.
#include "dem/lines_check.hpp"
#include "dem/yade_versions.hpp"

namespace restitution::damping_check {

// `r` is check_lines' result for YADE (r.yade set) made with `tolerance`; InvalidInput when the law's ε at
// the reference speed is out of betan's reach.
void target_yade_version(dem::LinesResult& r, const dem::YadeVersion& version, double tolerance);

}  // namespace restitution::damping_check
