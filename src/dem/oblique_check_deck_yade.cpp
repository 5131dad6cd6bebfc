// SPDX-License-Identifier: BSD-3-Clause
// The oblique part of a YADE check deck (`dem --code yade --yade-version 2023.02a --friction MU --deck
// FILE`): LAMMPS's section (oblique_check_deck.cpp) in YADE's Python, the engines of the head-on deck's
// scenes.
#include <fmt/core.h>

#include <algorithm>

#include "dem/check_deck_codes.hpp"
#include "dem/oblique_check_deck.hpp"
#include "restitution/errors.hpp"

namespace restitution::dem {
namespace {

// One scene per pass, one collision per angle: body 2i at rest, body 2i + 1 touching it from above (+z) and
// moving down onto it. The slip at the contact point is vx - R omega_y per sphere with the normal +z towards
// the mover, as in tests/dem/oblique_yade_mindlin.cpp; gravity off, no numerical damping.
std::string collide_function(const std::vector<std::string>& lines) {
  return fmt::format(R"(
def collide_oblique(dt, steps):
    """e_t = -s'/s of each collision in OBLIQUE_ANGLES after steps of dt [s]."""
    O.reset()
    {0}
    movers = []
    for i, a in enumerate(OBLIQUE_ANGLES):
        x = OBLIQUE_SPACING * i
        O.bodies.append(sphere((x, 0, 0), OBLIQUE_R2))
        b = O.bodies.append(sphere((x, 0, OBLIQUE_R1 + OBLIQUE_R2), OBLIQUE_R1))
        t = math.radians(a)
        O.bodies[b].state.vel = Vector3(OBLIQUE_SPEED * math.sin(t), 0, -OBLIQUE_SPEED * math.cos(t))
        movers.append(b)
{1}    et = []
    for a, b in zip(OBLIQUE_ANGLES, movers):
        m, r = O.bodies[b].state, O.bodies[b - 1].state
        slip = m.vel[0] - OBLIQUE_R1 * m.angVel[1] - r.vel[0] - OBLIQUE_R2 * r.angVel[1]
        s0 = OBLIQUE_SPEED * math.sin(math.radians(a))
        et.append(-slip / s0 if s0 != 0 else float('nan'))  # head-on: no slip to restitute
    return et
)",
                     lines[0], yade_engines_and_run(lines, ", gravity=(0, 0, 0)"));
}

}  // namespace

std::string yade_oblique_check_section(const ObliqueLines& r, const std::vector<std::string>& lines) {
  require_yade_lines(lines);
  if (!r.geometry.second) throw InvalidInput("YADE's oblique check deck collides a pair, not a wall");
  const double r1 = r.geometry.first.radius_m;
  const double r2 = r.geometry.second->radius_m;
  const ObliqueCheckSteps s = oblique_check_steps(r, oblique_check_steps_per_contact(r.code));
  std::string d = "\n\n# " + oblique_check_heading(r, s) + "\nimport math\n";
  d += fmt::format(
      "OBLIQUE_ANGLES = {}  # degrees from the normal\nOBLIQUE_SPEED = {}  # m/s\n"
      "OBLIQUE_R1, OBLIQUE_R2 = {}, {}  # m: the moving sphere, the one at rest\n"
      "OBLIQUE_SPACING = {}  # m between the collisions\n",
      python_list(r.angles_deg), r.speed_m_s, r1, r2, 10.0 * (r1 + std::max(r1, r2)));
  d += collide_function(lines);
  d += fmt::format(
      "\noblique_10dt = collide_oblique({0}, {1})\noblique_dt = collide_oblique({0} / 10, {2})\n"
      "OBLIQUE_ET_RESTITUTION = ",
      s.dt_s, s.steps, 10 * s.steps);
  std::vector<double> et;
  for (const auto& i : r.impacts) et.push_back(i.result.tangential_restitution);
  d += python_list(et) + "\n\n# the oblique check lines\n";
  // The line's fixed words per angle, its four measured values as %-formats.
  const ObliqueCheckValues formats{"%.15g", "%.15g", "%.15g", "%.15g"};
  d += "OBLIQUE_LINES = [\n";
  for (std::size_t i = 0; i < r.angles_deg.size(); ++i) {
    d += fmt::format("    '{}',\n", oblique_check_line(r, i, formats));
  }
  d += R"(]
for line, et_10dt, et_dt, et_r in zip(OBLIQUE_LINES, oblique_10dt, oblique_dt, OBLIQUE_ET_RESTITUTION):
    et_code = (10 * et_dt - et_10dt) / 9
    print(line % (et_10dt, et_dt, et_code, et_code - et_r))
)";
  return d;
}

}  // namespace restitution::dem
