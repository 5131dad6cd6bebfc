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

std::string deck_text(const Deck& deck, const Pair& p, const std::vector<double>& speeds,
                      int steps_per_time) {
  const double v_min = *std::min_element(speeds.begin(), speeds.end());
  const double v_max = *std::max_element(speeds.begin(), speeds.end());
  const double dt = natural_time(p, v_max) / steps_per_time;
  const long steps = std::lround(5.0 * natural_time(p, v_min) / dt);
  const double spacing = 10.0 * (p.radius1_m + p.radius2_m);
  const double box = spacing * static_cast<double>(speeds.size() + 1);
  std::string d = "units si\n";
  d += deck.code == Code::liggghts ? "atom_style granular\nnewton off\ncommunicate single vel yes\n"
                                   : "atom_style sphere\ncomm_modify vel yes\n";
  d += "atom_modify map array\nboundary f f f\n";
  d += fmt::format("region box block {0} {1} {0} {1} {0} {1} units box\ncreate_box 1 box\n", -box, box);
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    const double y = spacing * static_cast<double>(i);
    d += fmt::format("create_atoms 1 single {} {} 0 units box\n", -p.radius1_m, y);
    d += fmt::format("create_atoms 1 single {} {} 0 units box\n", p.radius2_m, y);
  }
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    // Diameter before mass: LAMMPS' `set diameter` recomputes the mass from the density.
    for (int j = 0; j < 2; ++j) {
      const std::size_t id = 2 * i + j + 1;
      d += fmt::format("set atom {} diameter {}\n", id, 2.0 * (j == 0 ? p.radius1_m : p.radius2_m));
      d += fmt::format("set atom {} mass {}\n", id, j == 0 ? p.mass1_kg : p.mass2_kg);
      d += fmt::format("set atom {} vx {}\n", id, (j == 0 ? 0.5 : -0.5) * speeds[i]);
    }
  }
  for (const std::string& line : deck.lines) d += line + "\n";
  d += fmt::format("neighbor {} bin\nneigh_modify delay 0\n", std::max(p.radius1_m, p.radius2_m));
  d += fmt::format("timestep {}\nfix integrate all nve/sphere\nthermo {}\nrun {}\n", dt, steps, steps);
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    const std::size_t a = 2 * i + 1;
    const std::size_t b = 2 * i + 2;
    d += fmt::format("variable e{} equal (vx[{}]-vx[{}])/{}\n", i, b, a, speeds[i]);
    d += fmt::format("variable g{} equal x[{}]-x[{}]-{}\n", i, b, a, p.radius1_m + p.radius2_m);
    d += fmt::format("print \"EPS {0} ${{e{0}}} ${{g{0}}}\"\n", i);
  }
  return d;
}

}  // namespace

std::string dem_program(Code code) {
  if (code == Code::lammps) return find_on_path("lmp");
  if (code == Code::liggghts) return find_on_path("liggghts");
  throw InvalidInput(fmt::format("{} cannot be run here: only lammps and liggghts are", code_name(code)));
}

DemRun run_dem_code(const std::string& program, const Deck& deck, const Pair& pair,
                    const std::vector<double>& speeds, int steps_per_time) {
  DemRun run;
  run.output =
      output_with_input_file(deck_text(deck, pair, speeds, steps_per_time), "", [&](const std::string& path) {
        return fmt::format("{} -in {} -log none -echo none 2>&1", program, path);
      });
  TaggedEps read = tagged_eps(run.output, "EPS", speeds.size());
  run.eps = std::move(read.eps);
  run.gap_m = std::move(read.gap_m);
  return run;
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
