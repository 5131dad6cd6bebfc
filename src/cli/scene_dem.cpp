#include "cli/scene_dem.hpp"

#include <fmt/core.h>

#include <cmath>

#include "cli/dem_runner.hpp"
#include "dem/deck.hpp"
#include "dem/deck_eps.hpp"
#include "restitution/calibration.hpp"
#include "restitution/material.hpp"

namespace restitution::cli {
namespace {

double dissipative_constant(const scene::Scene& scene, const scene::DemTask& task, const Material& m,
                            CollisionSolver& solver) {
  if (!task.eps) return material_constants(m).dissipative_constant_s;
  CalibrationRequest request;
  request.eps = *task.eps;
  request.velocity_m_s = *task.velocity_m_s;
  request.end = task.end;
  request.tolerance = scene.tolerance;
  request.method = scene.method;
  request.k = elastic_constants(m).k;
  return *calibrate(request, solver).dissipative_constant_s;
}

}  // namespace

DemSection dem_section(const scene::Scene& scene, const scene::DemTask& task) {
  const dem::Code code = dem::code_from_name(task.code);
  const Material& material = scene.materials.at(task.material);
  const dem::Pair pair = dem::pair_of(material);
  CollisionSolver solver;
  const double a = dissipative_constant(scene, task, material, solver);
  const dem::Deck deck =
      dem::make_deck(code, task.end, pair, a, task.velocity_m_s.value_or(1.0), task.friction);
  const double beta = dem::deck_beta(deck, pair);
  std::vector<double> predicted;
  for (double v : task.speeds) predicted.push_back(dem::eps_for(beta, v, task.end, scene.tolerance, solver));

  DemSection s;
  const std::string measured_column = fmt::format("eps_{}", dem::code_name(code));
  DemMeasurement measured;
  bool ran = false;
  if (task.run_code && (code == dem::Code::lammps || code == dem::Code::liggghts)) {
    const std::string program = dem_program(code);
    if (program.empty()) {
      s.warnings.push_back(
          fmt::format("{} is not installed (scripts/setup installs it): not run", task.code));
    } else {
      measured = measure_dem_eps(program, deck, pair, task.speeds);
      ran = true;
    }
  }
  s.csv = ran ? fmt::format("velocity_m_s,eps_restitution,{},rel_diff\n", measured_column)
              : "velocity_m_s,eps_restitution\n";
  for (std::size_t i = 0; i < task.speeds.size(); ++i) {
    s.csv += fmt::format("{:.17g},{:.17g}", task.speeds[i], predicted[i]);
    if (ran) {
      const double diff =
          (measured.extrapolated[i] - predicted[i]) / std::min(predicted[i], 1.0 - predicted[i]);
      s.csv += fmt::format(",{:.17g},{:.17g}", measured.extrapolated[i], diff);
    }
    s.csv += "\n";
  }
  s.plot_args = {"--x",     "velocity_m_s", "--y",      "eps_restitution",      "--xscale", "log",
                 "--title", task.title,     "--xlabel", "impact speed v [m/s]", "--ylabel", "eps"};
  if (ran) {
    s.plot_args.insert(s.plot_args.end(), {"--points", measured_column, "--error", "rel_diff",
                                           "--error-label", "|eps_code - eps| / min(eps, 1 - eps)"});
  }

  std::string& md = s.markdown;
  md += fmt::format(
      "{} lines for material `{}`, A = {:.10g} s, {} end{}:\n\n```\n", dem::code_name(code), task.material, a,
      end_name(task.end),
      task.eps ? fmt::format(" (calibrated to eps = {} at {} m/s)", *task.eps, *task.velocity_m_s) : "");
  for (const auto& p : deck.parameters) md += fmt::format("{} = {}: {}\n", p.name, p.value, p.meaning);
  for (const auto& line : deck.lines) md += line + "\n";
  md += "```\n\n";
  for (const auto& note : deck.notes) md += "* " + note + "\n";
  md += "\n| v [m/s] | eps (restitution) |";
  md += ran ? fmt::format(" eps ({}, extrapolated) | difference / min(eps, 1 - eps) |\n|---|---|---|---|\n",
                          dem::code_name(code))
            : "\n|---|---|\n";
  for (std::size_t i = 0; i < task.speeds.size(); ++i) {
    md += fmt::format("| {:g} | {:.10f} |", task.speeds[i], predicted[i]);
    if (ran) {
      md +=
          fmt::format(" {:.10f} | {:.2e} |", measured.extrapolated[i],
                      (measured.extrapolated[i] - predicted[i]) / std::min(predicted[i], 1.0 - predicted[i]));
    }
    md += "\n";
  }
  md += "\n";
  if (ran) {
    md += fmt::format(
        "{} ran the lines above at dt = T/2000 and T/20000 (T the natural time of the fastest collision); "
        "the "
        "column is the Richardson extrapolation (10 eps_fine - eps_coarse)/9.\n\n",
        dem::code_name(code));
  }
  return s;
}

}  // namespace restitution::cli
