// SPDX-License-Identifier: BSD-3-Clause
// The YADE check deck: a Python script for `yade -n -x`. The three lines `restitution dem --code yade`
// prints (the material, the Ip2 functor, the Law2 functor) stand in it as written, in the places a user
// puts them; each collision is its own scene with dt per speed (YADE has no reason to share one).
#include <fmt/core.h>

#include <cmath>

#include "dem/check_deck_codes.hpp"
#include "restitution/errors.hpp"

namespace restitution::dem {
std::string python_list(const std::vector<double>& values) {
  std::string s = "[";
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) s += ", ";
    // Python has no nan or inf literal: e_t at 0 degrees is nan.
    s += std::isfinite(values[i]) ? fmt::format("{}", values[i]) : fmt::format("float('{}')", values[i]);
  }
  return s + "]";
}

void require_yade_lines(const std::vector<std::string>& lines) {
  if (lines.size() != 3) {
    throw InvalidInput(fmt::format("a YADE deck needs the three YADE lines, got {}", lines.size()));
  }
}

std::string yade_engines_and_run(const std::vector<std::string>& lines, const std::string& newton_extra) {
  require_yade_lines(lines);
  return fmt::format(R"(    O.engines = [
        ForceResetter(),
        InsertionSortCollider([Bo1_Sphere_Aabb()]),
        InteractionLoop([Ig2_Sphere_Sphere_ScGeom()],
                        [{0}],
                        [{1}]),
        NewtonIntegrator(damping=0{2}),
    ]
    O.dt = dt
    O.run(steps, True)
)",
                     lines[1], lines[2], newton_extra);
}

std::string yade_collide_function(const std::vector<std::string>& lines) {
  require_yade_lines(lines);
  return fmt::format(R"(
def collide(r1, r2, v, dt, steps):
    """Two spheres touching at the origin, closing at v [m/s]: eps and the surface gap [m] after steps."""
    O.reset()
    {0}
    O.bodies.append([sphere((-r1, 0, 0), r1), sphere((r2, 0, 0), r2)])
    O.bodies[0].state.vel = Vector3(v / 2, 0, 0)
    O.bodies[1].state.vel = Vector3(-v / 2, 0, 0)
{1}    a, b = O.bodies[0].state, O.bodies[1].state
    return (b.vel[0] - a.vel[0]) / v, b.pos[0] - a.pos[0] - (r1 + r2)
)",
                     lines[0], yade_engines_and_run(lines, ""));
}

std::string yade_check_deck(const CheckDeckRequest& r, int n) {
  std::string s = check_deck_preamble(r, n);
  s += fmt::format(
      R"(
import yade

TARGET = '{0}'  # the YADE the lines are for
if TARGET and yade.config.version != TARGET:
    print('{1}-warning: the lines are for YADE %s, this is YADE %s' % (TARGET, yade.config.version))

)",
      r.yade_version, kCheckTag);
  s += yade_collide_function(r.lines);
  s += fmt::format(R"(

N = {}  # coarse dt = T/N, fine T/(10 N); each run lasts 6 T (the contact is over after about 3)
SPEEDS = )",
                   n);
  s += python_list(r.speeds_m_s) +
       "  # m/s\n"
       "# type1, type2, radius1 [m], radius2 [m], k = (4/3) E* sqrt(R_eff) / m_eff [m^-1/2 s^-2], the eps\n"
       "# restitution states these lines give at each speed\n"
       "PAIRS = [\n";
  for (const CheckPair& p : r.pairs) {
    // k as the deck's T = k^-0.4 v^-0.2 gives it back from T at 1 m/s, not k itself: the two differ in the
    // last bits, and these are the digits the decks have printed.
    const double k_over_m = std::pow(natural_time_s(p.pair, 1.0), -2.5);
    s += fmt::format("    ({}, {}, {}, {}, {}, {}),\n", p.type1, p.type2, p.pair.radius1_m, p.pair.radius2_m,
                     k_over_m, python_list(p.eps_restitution));
  }
  s += fmt::format(R"(]
for type1, type2, r1, r2, k, eps_restitution in PAIRS:
    for v, eps_r in zip(SPEEDS, eps_restitution):
        T = k ** -0.4 * v ** -0.2
        eps_10dt, _ = collide(r1, r2, v, T / N, 6 * N)
        eps_dt, gap = collide(r1, r2, v, T / (10 * N), 60 * N)
        eps_code = (10 * eps_dt - eps_10dt) / 9
        print('{0} code=yade types=%d,%d speed=%r eps_10dt=%.15g eps_dt=%.15g eps_code=%.15g '
              'eps_restitution=%r rel_diff=%.15g gap_m=%.15g'
              % (type1, type2, v, eps_10dt, eps_dt, eps_code, eps_r, (eps_code - eps_r) / eps_r, gap))
)",
                   kCheckTag);
  return s;
}

}  // namespace restitution::dem
