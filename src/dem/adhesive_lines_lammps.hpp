// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// LAMMPS 20220106's `pair granular` lines for an adhesive pair (jkr or dmt with `damping viscoelastic`) and
// what they give under LAMMPS's own rules: ε at the requested speeds and the sticking speed (docs/adhesion.md
// §9). The lines carry what the model needs to run: atom_style sphere, comm_modify vel yes, a tangential
// model that survives a neighbour-list rebuild (`linear_history 0 0 0`: with `linear_nohistory` jkr stops at
// the first rebuild with "Neighbor history overflow"), a skin of 3 times the pull-off distance (the cutoff is
// 2R − |δ_pull-off| + skin: a smaller skin drops the contact early) and a time step resolving the contact.
#include <string>
#include <vector>

#include "restitution/adhesion.hpp"

namespace restitution::dem {

struct AdhesiveLammpsRequest {
  AdhesiveContact contact;  // model jkr_lammps or dmt; the damping is LAMMPS's damp [1/(m s)]
  double young_modulus_pa = 0.0;
  double poisson_ratio = 0.0;
  // Impact speeds [m/s]; empty: 0.97, 1.03, 1.05, 1.5, 3, 10 and 100 times the sticking speed (needs v_s >
  // 0).
  std::vector<double> speeds;
  double tolerance = kDefaultTolerance;
};

struct AdhesiveLammpsLines {
  std::vector<std::string> lines;
  double skin_m = 0.0;
  double timestep_s = 0.0;
  double break_overlap_m = 0.0;
  StickingSpeed sticking;           // under LAMMPS's rules
  StickingSpeed textbook_sticking;  // jkr only: the textbook break rule with the same A (0 solves for dmt)
  std::vector<double> speeds;
  std::vector<AdhesiveCollision> collisions;
};

// Throws InvalidInput for a model LAMMPS does not code this way (`jkr`, the textbook one) or for no speeds
// where the sticking speed is 0.
[[nodiscard]] AdhesiveLammpsLines adhesive_lammps_lines(const AdhesiveLammpsRequest& request);

}  // namespace restitution::dem
