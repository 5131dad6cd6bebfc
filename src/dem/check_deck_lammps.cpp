// SPDX-License-Identifier: BSD-3-Clause
// The LAMMPS and LIGGGHTS check deck: both read LAMMPS's input language. One simulation holds every type
// pair at every speed, each collision a pair of touching spheres closing along x, on a square grid in the y-z
// plane (lammps_family_layout: out of each other's reach, in a box that grows with the square root of their
// number); the deck runs it at the coarse dt, keeps each ε in a variable (`clear`
// keeps variables), runs it again at the fine dt and prints the check lines. Per-atom lookups (vx[i]) work
// under MPI too: the deck runs unchanged with `mpirun -np N`.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "dem/check_deck_codes.hpp"
#include "dem/dem_codes.hpp"
#include "restitution/errors.hpp"

namespace restitution::dem {
namespace {

struct Row {
  const CheckPair* pair;
  std::size_t speed;  // index into the request's speeds
};

std::vector<Row> rows_of(const CheckDeckRequest& r) {
  std::vector<Row> rows;
  for (const CheckPair& p : r.pairs) {
    for (std::size_t s = 0; s < r.speeds_m_s.size(); ++s) rows.push_back({&p, s});
  }
  return rows;
}

}  // namespace

Layout lammps_family_layout(const CheckDeckRequest& r, double run_s) {
  Layout l;
  for (const CheckPair& p : r.pairs) l.reach_m = std::max({l.reach_m, p.pair.radius1_m, p.pair.radius2_m});
  const std::size_t rows = r.pairs.size() * r.speeds_m_s.size();
  l.columns = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(rows))));
  l.spacing_m = 4.0 * l.reach_m;
  // Each sphere leaves at most half the impact speed (ε <= 1), for at most the whole run.
  const double v_max = *std::max_element(r.speeds_m_s.begin(), r.speeds_m_s.end());
  l.half_width_m = 4.0 * l.reach_m + 0.5 * v_max * run_s;
  l.y_max_m = l.spacing_m * (static_cast<double>(l.columns) - 0.5);
  l.z_max_m = l.spacing_m * (std::ceil(static_cast<double>(rows) / static_cast<double>(l.columns)) - 0.5);
  return l;
}

std::string lammps_family_pass(const CheckDeckRequest& r, double dt, long steps) {
  const std::vector<Row> rows = rows_of(r);
  const Layout l = lammps_family_layout(r, dt * static_cast<double>(steps));
  std::string d = "units si\n";
  d += code_entry(r.code).check_deck_atom_style;
  // No atom sorting: the spheres never mix, and its bins are the codes' first limit on the box.
  d += "atom_modify map array sort 0 0.0\nboundary f f f\n";
  const double low = -0.5 * l.spacing_m;
  d += fmt::format("region box block {} {} {} {} {} {} units box\ncreate_box {} box\n", -l.half_width_m,
                   l.half_width_m, low, l.y_max_m, low, l.z_max_m, r.type_count);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Pair& p = rows[i].pair->pair;
    const std::size_t column = i % l.columns;
    const std::size_t row = i / l.columns;
    const double y = l.spacing_m * static_cast<double>(column);
    const double z = l.spacing_m * static_cast<double>(row);
    d += fmt::format("create_atoms {} single {} {} {} units box\n", rows[i].pair->type1, -p.radius1_m, y, z);
    d += fmt::format("create_atoms {} single {} {} {} units box\n", rows[i].pair->type2, p.radius2_m, y, z);
  }
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Pair& p = rows[i].pair->pair;
    const double v = r.speeds_m_s[rows[i].speed];
    // Diameter before mass: LAMMPS' `set diameter` recomputes the mass from the density.
    for (int j = 0; j < 2; ++j) {
      const std::size_t id = 2 * i + j + 1;
      d += fmt::format("set atom {} diameter {}\n", id, 2.0 * (j == 0 ? p.radius1_m : p.radius2_m));
      d += fmt::format("set atom {} mass {}\n", id, j == 0 ? p.mass1_kg : p.mass2_kg);
      d += fmt::format("set atom {} vx {}\n", id, (j == 0 ? 0.5 : -0.5) * v);
    }
  }
  d += "# the lines `restitution dem` printed, unchanged:\n";
  for (const std::string& line : r.lines) d += line + "\n";
  d += fmt::format("neighbor {} bin\nneigh_modify delay 0\n", l.reach_m);
  d += fmt::format("timestep {}\nfix integrate all nve/sphere\nthermo {}\nrun {}\n", dt, steps, steps);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Pair& p = rows[i].pair->pair;
    d += fmt::format("variable rc_eps{} equal (vx[{}]-vx[{}])/{}\n", i, 2 * i + 2, 2 * i + 1,
                     r.speeds_m_s[rows[i].speed]);
    d += fmt::format("variable rc_gap{} equal x[{}]-x[{}]-{}\n", i, 2 * i + 2, 2 * i + 1,
                     p.radius1_m + p.radius2_m);
  }
  return d;
}

TimeStep lammps_family_time_step(const CheckDeckRequest& r, int n) {
  const double v_min = *std::min_element(r.speeds_m_s.begin(), r.speeds_m_s.end());
  const double v_max = *std::max_element(r.speeds_m_s.begin(), r.speeds_m_s.end());
  // One dt for the whole system: the shortest collision sets it, the longest the length of the run (five
  // natural times: the contact is over after about three).
  double shortest = INFINITY;
  double longest = 0.0;
  for (const CheckPair& p : r.pairs) {
    shortest = std::min(shortest, natural_time_s(p.pair, v_max));
    longest = std::max(longest, natural_time_s(p.pair, v_min));
  }
  const double dt = shortest / n;
  return {dt, std::lround(std::ceil(5.0 * longest / dt))};
}

std::string lammps_family_check_deck(const CheckDeckRequest& r, int n) {
  const auto [dt, steps] = lammps_family_time_step(r, n);
  const std::vector<Row> rows = rows_of(r);
  // Two spheres a collision; `steps` at dt, then 10 `steps` at dt/10.
  const double sphere_steps = 2.0 * static_cast<double>(rows.size()) * 11.0 * static_cast<double>(steps);
  if (sphere_steps > kMaxDeckSphereSteps) {
    throw InvalidInput(fmt::format(
        "--deck: {} spheres x {} steps (both passes) = {:.3g} sphere-steps; a {} check deck takes at most "
        "{:.3g} (about three minutes): its collisions differ too much in duration (T grows with the radius "
        "and with v^(-1/5)), give narrower radii or speeds, or write several decks",
        2 * rows.size(), 11 * steps, sphere_steps, code_name(r.code), kMaxDeckSphereSteps));
  }

  std::string d = check_deck_preamble(r, n);
  d += fmt::format("\n# pass 1 of 2: dt = T/{} = {} s\n", n, dt);
  d += lammps_family_pass(r, dt, steps);
  for (std::size_t i = 0; i < rows.size(); ++i)
    d += fmt::format("variable rc_10dt{0} equal ${{rc_eps{0}}}\n", i);
  d += "clear\n";
  d += fmt::format("\n# pass 2 of 2: dt = T/{} = {} s\n", 10 * n, dt / 10.0);
  d += lammps_family_pass(r, dt / 10.0, 10 * steps);
  d += "\n# the check lines\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double eps = rows[i].pair->eps_restitution[rows[i].speed];
    d += fmt::format("variable rc_dt{0} equal ${{rc_eps{0}}}\n", i);
    d += fmt::format("variable rc_code{0} equal (10*v_rc_dt{0}-v_rc_10dt{0})/9\n", i);
    d += fmt::format("variable rc_diff{0} equal (v_rc_code{0}-{1})/{1}\n", i, eps);
    d += fmt::format(
        "print \"{1} code={2} types={3},{4} speed={5} eps_10dt=${{rc_10dt{0}}} eps_dt=${{rc_dt{0}}} "
        "eps_code=${{rc_code{0}}} eps_restitution={6} rel_diff=${{rc_diff{0}}} gap_m=${{rc_gap{0}}}\"\n",
        i, kCheckTag, code_name(r.code), rows[i].pair->type1, rows[i].pair->type2,
        r.speeds_m_s[rows[i].speed], eps);
  }
  return d;
}

}  // namespace restitution::dem
