// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The check deck of an adhesive pair (`dem --adhesion ... --deck FILE`, LAMMPS or LIGGGHTS): the printed
// lines, one pair of equal spheres per listed speed, 20 radii apart, each starting a thousandth of a radius
// from touching. After the run it prints, per pair, what restitution expects ("EXPECT i v outcome eps") and
// what the code measured ("PAIR i eps gap": the relative speed ratio and the centre distance − 2R, ≤ the
// break overlap while the spheres still hold on). docs/adhesion.md §9–§10.
#include <string>
#include <vector>

#include "restitution/adhesion.hpp"

namespace restitution::dem {

struct AdhesiveDeckRequest {
  bool liggghts = false;           // the prerequisites before the box: 3 lines (LAMMPS) or 4 (LIGGGHTS)
  std::vector<std::string> lines;  // as printed; the `timestep` line is replaced by timestep_s
  double radius_m = 0.0;
  double density_kg_per_m3 = 0.0;
  double timestep_s = 0.0;
  std::vector<double> speeds_m_per_s;
  std::vector<AdhesiveCollision> collisions;  // one per speed
};

[[nodiscard]] std::string adhesive_check_deck(const AdhesiveDeckRequest& request);

}  // namespace restitution::dem
