// SPDX-License-Identifier: BSD-3-Clause
#include "dem/code_runner.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <sstream>

#include "dem/process_output.hpp"
#include "restitution/errors.hpp"
#include "restitution/units.hpp"

namespace restitution::dem {
namespace {

std::string find_on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path != nullptr ? path : "");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::filesystem::path candidate = std::filesystem::path(dir) / program;
    if (::access(candidate.c_str(), X_OK) == 0) return candidate.string();
  }
  return {};
}

double natural_time(const Pair& p, double v) {
  const double k = hertz_stiffness(p.effective_modulus_pa, p.effective_radius_m) / p.effective_mass_kg;
  return std::pow(k, -0.4) * std::pow(v, -0.2);
}

std::string deck_text(const CollisionRun& run) {
  double t_min = HUGE_VAL;
  double t_max = 0.0;
  double spacing = 0.0;
  double skin = 0.0;
  for (const Collision& c : run.collisions) {
    const double t = natural_time(c.pair, c.velocity_m_s);
    t_min = std::min(t_min, t);
    t_max = std::max(t_max, t);
    spacing = std::max(spacing, 10.0 * (c.pair.radius1_m + c.pair.radius2_m));
    skin = std::max({skin, c.pair.radius1_m, c.pair.radius2_m});
  }
  const double dt = t_min / run.steps_per_time;
  const long steps = std::lround(5.0 * t_max / dt);
  const double box = spacing * static_cast<double>(run.collisions.size() + 1);
  std::string d = "units si\n";
  d += run.code == Code::liggghts ? "atom_style granular\nnewton off\ncommunicate single vel yes\n"
                                  : "atom_style sphere\ncomm_modify vel yes\n";
  d += "atom_modify map array\nboundary f f f\n";
  if (!run.processors.empty()) d += "processors " + run.processors + "\n";
  d += fmt::format("region box block {0} {1} {0} {1} {0} {1} units box\ncreate_box {2} box\n", -box, box,
                   run.types);
  for (std::size_t i = 0; i < run.collisions.size(); ++i) {
    const Collision& c = run.collisions[i];
    const double y = spacing * static_cast<double>(i);
    d += fmt::format("create_atoms {} single {} {} 0 units box\n", c.type1, -c.pair.radius1_m, y);
    d += fmt::format("create_atoms {} single {} {} 0 units box\n", c.type2, c.pair.radius2_m, y);
  }
  for (std::size_t i = 0; i < run.collisions.size(); ++i) {
    const Collision& c = run.collisions[i];
    // Diameter before mass: LAMMPS' `set diameter` recomputes the mass from the density.
    for (int j = 0; j < 2; ++j) {
      const std::size_t id = 2 * i + j + 1;
      d += fmt::format("set atom {} diameter {}\n", id, 2.0 * (j == 0 ? c.pair.radius1_m : c.pair.radius2_m));
      d += fmt::format("set atom {} mass {}\n", id, j == 0 ? c.pair.mass1_kg : c.pair.mass2_kg);
      d += fmt::format("set atom {} vx {}\n", id, (j == 0 ? 0.5 : -0.5) * c.velocity_m_s);
    }
  }
  for (const std::string& line : run.lines) d += line + "\n";
  d += fmt::format("neighbor {} bin\nneigh_modify delay 0\n", skin);
  d += fmt::format("timestep {}\nfix integrate all nve/sphere\nthermo {}\nrun {}\n", dt, steps, steps);
  for (std::size_t i = 0; i < run.collisions.size(); ++i) {
    const Collision& c = run.collisions[i];
    const std::size_t a = 2 * i + 1;
    const std::size_t b = 2 * i + 2;
    d += fmt::format("variable e{} equal (vx[{}]-vx[{}])/{}\n", i, b, a, c.velocity_m_s);
    d += fmt::format("variable g{} equal x[{}]-x[{}]-{}\n", i, b, a, c.pair.radius1_m + c.pair.radius2_m);
    d += fmt::format("print \"EPS {0} ${{e{0}}} ${{g{0}}}\"\n", i);
  }
  d += run.after_run;
  return d;
}

}  // namespace

std::string dem_program(Code code) {
  if (code == Code::lammps) return find_on_path("lmp");
  if (code == Code::liggghts) return find_on_path("liggghts");
  throw InvalidInput(fmt::format("{} cannot be run here: only lammps and liggghts are", code_name(code)));
}

DemRun run_collisions(const std::string& program, const CollisionRun& run) {
  DemRun result;
  result.output = output_with_input_file(deck_text(run), "", [&](const std::string& path) {
    return fmt::format("{} -in {} -log none -echo none 2>&1", program, path);
  });
  TaggedEps read = tagged_eps(result.output, "EPS", run.collisions.size());
  result.eps = std::move(read.eps);
  result.gap_m = std::move(read.gap_m);
  return result;
}

DemMeasurement measure_collisions(const std::string& program, const CollisionRun& run) {
  CollisionRun fine = run;
  fine.steps_per_time = 10 * run.steps_per_time;
  return richardson(run_collisions(program, run), run_collisions(program, fine));
}

DemRun run_dem_code(const std::string& program, const Deck& deck, const Pair& pair,
                    const std::vector<double>& speeds, int steps_per_time) {
  CollisionRun run;
  run.code = deck.code;
  run.lines = deck.lines;
  run.steps_per_time = steps_per_time;
  for (double v : speeds) run.collisions.push_back({1, 1, pair, v});
  return run_collisions(program, run);
}

DemMeasurement measure_dem_eps(const std::string& program, const Deck& deck, const Pair& pair,
                               const std::vector<double>& speeds, int coarse_steps_per_time) {
  return richardson(run_dem_code(program, deck, pair, speeds, coarse_steps_per_time),
                    run_dem_code(program, deck, pair, speeds, 10 * coarse_steps_per_time));
}

DemMeasurement richardson(const DemRun& coarse, const DemRun& fine) {
  DemMeasurement m;
  m.coarse = coarse.eps;
  m.fine = fine.eps;
  m.gap_m = fine.gap_m;
  m.output = fine.output;
  for (std::size_t i = 0; i < fine.eps.size(); ++i)
    m.extrapolated.push_back((10.0 * fine.eps[i] - coarse.eps[i]) / 9.0);
  return m;
}

}  // namespace restitution::dem
