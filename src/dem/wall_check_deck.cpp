// SPDX-License-Identifier: BSD-3-Clause
// The LAMMPS wall check deck (dem/wall_lines.hpp): one sphere per speed, in a row along x, touching the
// `fix wall/gran` zplane at z = 0 and moving onto it; no gravity, so ε is v_z'/v exactly as the law defines
// it.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "dem/check_deck.hpp"
#include "dem/check_deck_codes.hpp"
#include "dem/dem_codes.hpp"
#include "dem/wall_lines.hpp"
#include "restitution/errors.hpp"

namespace restitution::dem {
namespace {

constexpr int kDefaultSteps = 2000;

std::string pass(const WallResult& w, double dt, long steps) {
  const Pair& c = w.contact;
  const double reach = c.radius1_m;
  const double v_max = std::max_element(w.eps.begin(), w.eps.end(), [](const SpeedEps& a, const SpeedEps& b) {
                         return a.velocity_m_s < b.velocity_m_s;
                       })->velocity_m_s;
  const double spacing = 4.0 * reach;
  // The box holds the row and the highest rebound (at most the impact speed for the whole run).
  const double top = 2.0 * reach + v_max * dt * static_cast<double>(steps);
  std::string d = "units si\natom_style sphere\natom_modify map array sort 0 0.0\nboundary f f f\n";
  d += fmt::format("region box block {} {} {} {} {} {} units box\ncreate_box 1 box\n", -0.5 * spacing,
                   spacing * (static_cast<double>(w.eps.size()) - 0.5), -0.5 * spacing, 0.5 * spacing, -reach,
                   top);
  for (std::size_t i = 0; i < w.eps.size(); ++i) {
    d += fmt::format("create_atoms 1 single {} 0 {} units box\n", spacing * static_cast<double>(i), reach);
  }
  for (std::size_t i = 0; i < w.eps.size(); ++i) {
    // Diameter before mass: `set diameter` recomputes the mass from the density.
    d += fmt::format("set atom {0} diameter {1}\nset atom {0} mass {2}\nset atom {0} vz {3}\n", i + 1,
                     2.0 * c.radius1_m, c.mass1_kg, -w.eps[i].velocity_m_s);
  }
  d += "# the lines `restitution dem --wall` printed, unchanged:\n";
  for (const std::string& line : w.deck.lines) d += line + "\n";
  d += fmt::format("timestep {}\nfix integrate all nve/sphere\nthermo {}\nrun {}\n", dt, steps, steps);
  for (std::size_t i = 0; i < w.eps.size(); ++i) {
    d += fmt::format("variable rc_eps{} equal vz[{}]/{}\n", i, i + 1, w.eps[i].velocity_m_s);
    d += fmt::format("variable rc_gap{} equal z[{}]-{}\n", i, i + 1, c.radius1_m);
  }
  return d;
}

}  // namespace

std::string wall_check_deck(const WallResult& result, int steps_per_time) {
  if (code_entry(result.deck.code).write_wall == nullptr) {
    throw InvalidInput(
        fmt::format("--wall --deck: only {} has a wall check deck",
                    code_list(" and ", [](const CodeEntry& e) { return e.write_wall != nullptr; })));
  }
  if (result.eps.empty()) throw InvalidInput("--wall --deck needs at least one speed");
  const int n = steps_per_time > 0 ? steps_per_time : kDefaultSteps;
  double v_min = INFINITY;
  double v_max = 0.0;
  for (const SpeedEps& e : result.eps) {
    v_min = std::min(v_min, e.velocity_m_s);
    v_max = std::max(v_max, e.velocity_m_s);
  }
  // The fastest impact sets dt, the slowest the run (five natural times: the contact is over after three).
  const double dt = natural_time_s(result.contact, v_max) / n;
  const long steps = std::lround(std::ceil(5.0 * natural_time_s(result.contact, v_min) / dt));
  const double sphere_steps = static_cast<double>(result.eps.size()) * 11.0 * static_cast<double>(steps);
  if (sphere_steps > kMaxDeckSphereSteps) {
    throw InvalidInput(fmt::format(
        "--deck: {} spheres x {} steps (both passes) = {:.3g} sphere-steps; a wall check deck takes at most "
        "{:.3g}: give speeds closer together",
        result.eps.size(), 11 * steps, sphere_steps, kMaxDeckSphereSteps));
  }
  std::string d = fmt::format(
      "# restitution wall check deck: run `lmp -in FILE`. Spheres of R = {} m, m = {} kg on a {} wall "
      "(E* = {} Pa), A = {:.10g} s;\n# each speed's sphere moves onto fix wall/gran at z = 0, the run "
      "repeats "
      "at dt = T/{} and T/{}, and one line per speed prints\n# {} code=lammps types=1,0 speed=V eps_10dt "
      "eps_dt eps_code (Richardson) eps_restitution rel_diff gap_m\n",
      result.contact.radius1_m, result.contact.mass1_kg, result.rigid_wall ? "rigid" : "given",
      result.contact.effective_modulus_pa, result.dissipative_constant_s, n, 10 * n, kCheckTag);
  d += fmt::format("\n# pass 1 of 2: dt = T/{} = {} s\n", n, dt);
  d += pass(result, dt, steps);
  for (std::size_t i = 0; i < result.eps.size(); ++i)
    d += fmt::format("variable rc_10dt{0} equal ${{rc_eps{0}}}\n", i);
  d += "clear\n";
  d += fmt::format("\n# pass 2 of 2: dt = T/{} = {} s\n", 10 * n, dt / 10.0);
  d += pass(result, dt / 10.0, 10 * steps);
  d += "\n# the check lines\n";
  for (std::size_t i = 0; i < result.eps.size(); ++i) {
    const double eps = result.eps[i].eps;
    d += fmt::format("variable rc_dt{0} equal ${{rc_eps{0}}}\n", i);
    d += fmt::format("variable rc_code{0} equal (10*v_rc_dt{0}-v_rc_10dt{0})/9\n", i);
    d += fmt::format("variable rc_diff{0} equal (v_rc_code{0}-{1})/{1}\n", i, eps);
    d += fmt::format(
        "print \"{1} code=lammps types=1,0 speed={2} eps_10dt=${{rc_10dt{0}}} eps_dt=${{rc_dt{0}}} "
        "eps_code=${{rc_code{0}}} eps_restitution={3} rel_diff=${{rc_diff{0}}} gap_m=${{rc_gap{0}}}\"\n",
        i, kCheckTag, result.eps[i].velocity_m_s, eps);
  }
  return d;
}

}  // namespace restitution::dem
