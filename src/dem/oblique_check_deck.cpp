// SPDX-License-Identifier: BSD-3-Clause
#include "dem/oblique_check_deck.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "dem/dem_codes.hpp"
#include "restitution/units.hpp"

namespace restitution::dem {
namespace {

// One pass: a fresh system with one collision per angle at dt, e_t of each into variable `name`{i}. A pair:
// atom 2i+1 at rest, 2i+2 above it moving down onto it; a wall: atom i+1 touching the plane z = 0. LAMMPS's
// slip is vx - R omega_y per sphere with the normal +z towards the mover, and so is LIGGGHTS's
// (tests/dem/oblique_runs.hpp).
std::string oblique_pass(const ObliqueLines& r, const std::vector<std::string>& prerequisites,
                         const std::vector<std::string>& lines, double dt, long steps, const char* name) {
  const bool pair = r.geometry.second.has_value();
  const double r1 = r.geometry.first.radius_m;
  const double r2 = pair ? r.geometry.second->radius_m : 0.0;
  const double spacing = 10.0 * (r1 + std::max(r1, r2));
  const std::size_t n = r.angles_deg.size();
  std::string d = "clear\n";
  for (const auto& line : prerequisites) d += line + "\n";
  d += "atom_modify map array\nboundary f f f\n";
  d += fmt::format("region rc_oblique_box block {} {} {} {} {} {} units box\ncreate_box 1 rc_oblique_box\n",
                   -spacing, spacing * static_cast<double>(n), -spacing, spacing, -spacing, spacing);
  const std::size_t per_angle = pair ? 2 : 1;
  for (std::size_t i = 0; i < n; ++i) {
    const double x = spacing * static_cast<double>(i);
    if (pair) d += fmt::format("create_atoms 1 single {} 0 0 units box\n", x);
    d += fmt::format("create_atoms 1 single {} 0 {} units box\n", x, pair ? r1 + r2 : r1);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t mover = per_angle * (i + 1);
    // Diameter before mass: LAMMPS' `set diameter` recomputes the mass from the density.
    if (pair) {
      d += fmt::format("set atom {} diameter {}\nset atom {} mass {}\n", mover - 1, 2.0 * r2, mover - 1,
                       r.geometry.second->mass_kg);
    }
    d += fmt::format("set atom {} diameter {}\nset atom {} mass {}\n", mover, 2.0 * r1, mover,
                     r.geometry.first.mass_kg);
    const double a = r.angles_deg[i] * kRadiansPerDegree;
    d += fmt::format("set atom {} vx {} vz {}\n", mover, r.speed_m_s * std::sin(a),
                     -r.speed_m_s * std::cos(a));
  }
  for (const auto& line : lines) d += line + "\n";
  if (pair) d += fmt::format("neighbor {} bin\nneigh_modify every 1 delay 0 check no\n", 0.1 * r1);
  // Spins are no atom vector of variable formulas: a per-atom compute, evaluated by fix ave/time on the last
  // step, whose value can be read after the run.
  d += "compute rc_oblique_omega all property/atom omegay\n";
  std::string values;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t mover = per_angle * (i + 1);
    const double slip0 = r.speed_m_s * std::sin(r.angles_deg[i] * kRadiansPerDegree);
    const std::string rest =
        pair ? fmt::format("-vx[{}]-{}*c_rc_oblique_omega[{}]", mover - 1, r2, mover - 1) : "";
    d += fmt::format("variable rc_oblique_et{0} equal -(vx[{1}]-{2}*c_rc_oblique_omega[{1}]{3})/{4}\n", i,
                     mover, r1, rest, slip0);
    values += fmt::format(" v_rc_oblique_et{}", i);
  }
  d += fmt::format("fix rc_oblique_nve all nve/sphere\nfix rc_oblique_hold all ave/time {0} 1 {0}{1}\n",
                   steps, values);
  d += fmt::format("timestep {}\nthermo {}\nrun {}\n", dt, steps, steps);
  for (std::size_t i = 0; i < n; ++i) {
    // fix ave/time of one value is a global scalar, of several a vector.
    const std::string held = n == 1 ? "f_rc_oblique_hold" : fmt::format("f_rc_oblique_hold[{}]", i + 1);
    d += fmt::format("variable rc_oblique_got{} equal {}\n", i, held);
    d += fmt::format("variable {}{} equal ${{rc_oblique_got{}}}\n", name, i, i);
  }
  return d;
}

}  // namespace

int oblique_check_steps_per_contact(Code code) {
  return code_entry(code).oblique_check_steps;
}

ObliqueCheckSteps oblique_check_steps(const ObliqueLines& r, int per_contact) {
  ObliqueCheckSteps s;
  s.per_contact = per_contact;
  s.shortest_contact_s = HUGE_VAL;
  double longest = 0.0;
  for (const auto& i : r.impacts) {
    s.shortest_contact_s = std::min(s.shortest_contact_s, i.result.contact_time_s);
    longest = std::max(longest, i.result.contact_time_s);
  }
  s.dt_s = s.shortest_contact_s / per_contact;
  s.steps = static_cast<long>(std::ceil(1.1 * longest / s.dt_s));
  return s;
}

std::string oblique_check_heading(const ObliqueLines& r, const ObliqueCheckSteps& s) {
  return fmt::format(
      "oblique impacts ({}): the lines again, at each angle restitution dem lists, at {} m/s; dt = t_c/{} "
      "and "
      "t_c/{}, t_c = {} s the shortest contact",
      r.geometry.second ? "pair" : "wall", r.speed_m_s, s.per_contact, 10 * s.per_contact,
      s.shortest_contact_s);
}

std::string oblique_check_line(const ObliqueLines& r, std::size_t i, const ObliqueCheckValues& values) {
  return fmt::format(
      "{} code={} contact={} angle={} et_10dt={} et_dt={} et_code={} et_restitution={} diff={}",
      kObliqueCheckTag, code_name(r.code), r.geometry.second ? "pair" : "wall", r.angles_deg[i],
      values.et_10dt, values.et_dt, values.et_code, r.impacts[i].result.tangential_restitution, values.diff);
}

std::string oblique_check_section(const ObliqueLines& printed, const std::vector<std::string>& prerequisites,
                                  const std::vector<std::string>& lines) {
  // A head-on angle has no slip at impact: e_t = -s'/s is undefined there (and the deck's formula would
  // divide by 0, which stops LAMMPS), so only the angles with an e_t are collided.
  ObliqueLines r = printed;
  r.angles_deg.clear();
  r.impacts.clear();
  std::string skipped;
  for (std::size_t i = 0; i < printed.angles_deg.size(); ++i) {
    if (std::isfinite(printed.impacts[i].result.tangential_restitution)) {
      r.angles_deg.push_back(printed.angles_deg[i]);
      r.impacts.push_back(printed.impacts[i]);
    } else {
      skipped +=
          fmt::format("# oblique impacts: angle {} deg has no slip at impact (e_t undefined): not checked\n",
                      printed.angles_deg[i]);
    }
  }
  if (r.angles_deg.empty()) return "\n" + skipped;
  const ObliqueCheckSteps s = oblique_check_steps(r, oblique_check_steps_per_contact(r.code));
  std::string d = "\n" + skipped + "# " + oblique_check_heading(r, s) + "\n";
  d += oblique_pass(r, prerequisites, lines, s.dt_s, s.steps, "rc_oblique_10dt");
  d += oblique_pass(r, prerequisites, lines, s.dt_s / 10.0, 10 * s.steps, "rc_oblique_dt");
  d += "\n# the oblique check lines\n";
  for (std::size_t i = 0; i < r.angles_deg.size(); ++i) {
    const double et = r.impacts[i].result.tangential_restitution;
    d += fmt::format("variable rc_oblique_code{0} equal (10*v_rc_oblique_dt{0}-v_rc_oblique_10dt{0})/9\n", i);
    d += fmt::format("variable rc_oblique_diff{0} equal v_rc_oblique_code{0}-({1})\n", i, et);
    const auto variable = [i](const char* name) { return fmt::format("${{rc_oblique_{}{}}}", name, i); };
    d += "print \"" +
         oblique_check_line(r, i, {variable("10dt"), variable("dt"), variable("code"), variable("diff")}) +
         "\"\n";
  }
  return d;
}

std::string oblique_check_section(const ObliqueLines& r, const Deck& deck) {
  if (code_entry(r.code).oblique == ObliqueReader::yade_mindlin)
    return yade_oblique_check_section(r, deck.lines);
  return oblique_check_section(r, deck.prerequisites, deck.lines);
}

}  // namespace restitution::dem
