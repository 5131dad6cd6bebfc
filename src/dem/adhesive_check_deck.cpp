// SPDX-License-Identifier: BSD-3-Clause
#include "dem/adhesive_check_deck.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace restitution::dem {

std::string adhesive_check_deck(const AdhesiveDeckRequest& r) {
  const std::size_t n = r.speeds_m_per_s.size();
  const double radius = r.radius_m, spacing = 20.0 * radius, gap = 1e-3 * radius;
  std::string d = "atom_modify map array sort 0 0.0\nboundary f f f\n";
  const std::size_t before_box = r.liggghts ? 4 : 3;
  for (std::size_t i = 0; i < before_box; ++i) d += r.lines.at(i) + "\n";
  d += fmt::format("region box block {} {} {} {} {} {} units box\ncreate_box 1 box\n", -spacing, spacing,
                   -spacing, spacing * static_cast<double>(n), -spacing, spacing);
  double longest_s = 0.0;  // the slowest approach plus three contact times
  for (std::size_t i = 0; i < n; ++i) {
    const double y = spacing * static_cast<double>(i);
    d += fmt::format("create_atoms 1 single {} {} 0 units box\ncreate_atoms 1 single {} {} 0 units box\n",
                     -radius - gap / 2, y, radius + gap / 2, y);
    longest_s = std::max(longest_s, gap / r.speeds_m_per_s[i] + 3.0 * r.collisions[i].contact_time_s);
  }
  d += fmt::format("set group all diameter {}\nset group all density {}\n", 2 * radius, r.density_kg_per_m3);
  for (std::size_t i = 0; i < n; ++i) {
    const double v = r.speeds_m_per_s[i];
    d += fmt::format("set atom {} vx {}\nset atom {} vx {}\n", 2 * i + 1, 0.5 * v, 2 * i + 2, -0.5 * v);
  }
  for (std::size_t i = before_box; i < r.lines.size(); ++i) {
    if (r.lines[i].rfind("timestep", 0) != 0) d += r.lines[i] + "\n";
  }
  d += fmt::format("timestep {}\nthermo 0\nrun {}\n", r.timestep_s,
                   static_cast<long>(std::ceil(longest_s / r.timestep_s)));
  for (std::size_t i = 0; i < n; ++i) {
    const double v = r.speeds_m_per_s[i];
    const auto& c = r.collisions[i];
    d += fmt::format("print \"EXPECT {} {} {} {}\"\n", i, v, adhesive_outcome_name(c.outcome), c.eps);
    d += fmt::format("print \"PAIR {} $((vx[{}]-vx[{}])/{}) $(x[{}]-x[{}]-{})\"\n", i, 2 * i + 2, 2 * i + 1,
                     v, 2 * i + 2, 2 * i + 1, 2 * radius);
  }
  return d;
}

}  // namespace restitution::dem
