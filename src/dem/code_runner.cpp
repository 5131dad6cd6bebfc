// SPDX-License-Identifier: BSD-3-Clause
#include "dem/code_runner.hpp"

#include <fmt/core.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "dem/check_deck_codes.hpp"
#include "dem/process_output.hpp"
#include "restitution/errors.hpp"

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

// The check deck's first pass (dem/check_deck_codes.hpp) at one time step, printing "EPS row eps gap" per
// row (type pair and speed).
std::string deck_text(const CheckDeckRequest& r, const PassOptions& options) {
  const auto [dt, steps] = lammps_family_time_step(r, options.steps_per_time);
  std::string d = lammps_family_pass(r, dt, steps);
  if (!options.processors.empty()) {
    // Before the box exists: LAMMPS fixes the processor grid when the box is created.
    const std::size_t box = d.find("region box ");
    if (box == std::string::npos) throw std::logic_error("check deck pass without `region box`");
    d.insert(box, "processors " + options.processors + "\n");
  }
  const std::size_t rows = r.pairs.size() * r.speeds_m_s.size();
  for (std::size_t i = 0; i < rows; ++i)
    d += fmt::format("print \"EPS {0} ${{rc_eps{0}}} ${{rc_gap{0}}}\"\n", i);
  return d + options.after_run;
}

DemRun run_deck(const std::string& program, const std::vector<std::string>& launcher, const std::string& deck,
                std::size_t rows) {
  ChildRun ran = output_with_input_file(deck, "", [&](const std::string& path) {
    std::vector<std::string> command = launcher;
    command.insert(command.end(), {program, "-in", path, "-log", "none", "-echo", "none"});
    return command;
  });
  TaggedEps read = tagged_eps(ran.output, "EPS", rows);
  DemRun run;
  run.failure = code_run_failure(ran, program, read);
  run.exited_ok = child_succeeded(ran.status);
  run.output = std::move(ran.output);
  run.eps = std::move(read.eps);
  run.gap_m = std::move(read.gap_m);
  return run;
}

}  // namespace

std::string dem_program(Code code) {
  const CodeEntry& entry = code_entry(code);
  if (entry.scene_runs) return find_on_path(entry.program);
  throw InvalidInput(fmt::format("{} cannot be run here: only {} are", code_name(code),
                                 code_list(" and ", [](const CodeEntry& e) { return e.scene_runs; })));
}

DemRun run_dem_code(const std::string& program, const Deck& deck, const Pair& pair,
                    const std::vector<double>& speeds, int steps_per_time) {
  CheckDeckRequest r;
  r.code = deck.code;
  r.lines = deck.lines;
  r.speeds_m_s = speeds;
  r.pairs = {{1, 1, pair, {}}};
  return run_type_pairs(program, r, {steps_per_time, "", "", {}});
}

DemRun run_type_pairs(const std::string& program, const CheckDeckRequest& request,
                      const PassOptions& options) {
  return run_deck(program, options.launcher, deck_text(request, options),
                  request.pairs.size() * request.speeds_m_s.size());
}

DemMeasurement measure_type_pairs(const std::string& program, const CheckDeckRequest& request,
                                  const PassOptions& options) {
  PassOptions fine = options;
  fine.steps_per_time = 10 * options.steps_per_time;
  return richardson(run_type_pairs(program, request, options), run_type_pairs(program, request, fine));
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
  m.failure = !coarse.failure.empty() ? coarse.failure : fine.failure;
  m.exited_ok = coarse.exited_ok && fine.exited_ok;
  for (std::size_t i = 0; i < fine.eps.size(); ++i)
    m.extrapolated.push_back((10.0 * fine.eps[i] - coarse.eps[i]) / 9.0);
  return m;
}

}  // namespace restitution::dem
