// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `restitution dem --constant-eps`: the constant-ε companion of the law's lines, for a Haff's-law reference
// beside the viscoelastic gas (docs/dem.md). The code's own speed-independent damping (LAMMPS `damping
// tsuji`) given the restitution coefficient that makes it produce the law's ε at the calibration speed with
// the same end (`damping-check --recipe lammps-tsuji --target-eps`): its ε is that one at every speed.
#include <string>
#include <vector>

#include "dem/deck.hpp"
#include "dem/lines_check.hpp"
#include "restitution/collision_solver.hpp"

namespace restitution::damping_check {

struct ConstantEpsLines {
  double velocity_m_s = 0.0;       // the calibration speed
  double eps = 0.0;                // the law's ε there: the companion's ε at every speed
  double eps_to_request = 0.0;     // what the code's recipe is given
  std::vector<std::string> lines;  // replace the law's lines
};

// For the LAMMPS lines of `r` (check_lines' result) made for `pair`; InvalidInput naming --constant-eps for
// any other code.
ConstantEpsLines constant_eps_lines(const dem::LinesResult& r, const dem::Pair& pair, double tolerance,
                                    CollisionSolver& solver);

}  // namespace restitution::damping_check
