// SPDX-License-Identifier: BSD-3-Clause
#include "cli/gas/gas_deck_options.hpp"

#include <fmt/core.h>

#include <limits>

#include "cli/common/build_json.hpp"
#include "cli/common/json_writer.hpp"
#include "cli/common/options.hpp"
#include "cli/common/stop_signals.hpp"
#include "cli/gas/driven_compare_report.hpp"
#include "cli/gas/gas_compare_report.hpp"
#include "cli/gas/gas_deck_files.hpp"
#include "files/output_files.hpp"
#include "files/output_guards.hpp"
#include "gas_deck/gas_deck_request.hpp"
#include "restitution/errors.hpp"

namespace restitution::cli {

void add_gas_deck_options(CLI::App& cmd, GasDeckOptions& o) {
  cmd.add_option(
      "--deck", o.deck,
      "write a LAMMPS (or --code liggghts) input of this gas to FILE, its constant-eps companion to "
      "STEM_constant_eps.EXT "
      "and their data file to STEM.data (docs/gas.md, The LAMMPS deck)");
  cmd.add_option("--code", o.code,
                 "with --deck: the DEM code, lammps or liggghts (LIGGGHTS 3.8.0: the same data "
                 "file, hertz/stiffness lines, a model hertz companion)")
      ->capture_default_str();
  cmd.add_option("--particles", o.particles,
                 fmt::format("spheres in the deck's periodic box, in [2, {}] (the data file takes about "
                             "{} bytes per sphere)",
                             gas_deck::kMaxParticles, gas_deck::kDataBytesPerSphere))
      ->capture_default_str()
      ->check(whole_number_in(2, static_cast<long long>(gas_deck::kMaxParticles)));
  cmd.add_option("--seed", o.seed, "seed of the deck's random positions and velocities, an integer >= 0")
      ->capture_default_str()
      ->check(whole_number_in(0, std::numeric_limits<long long>::max()));
  cmd.add_option(
         "--max-eps-error", o.max_eps_error,
         "the deck's time step keeps the worst |eps error| of LAMMPS's integrator within this, at 3 x the "
         "rms relative speed, in [1e-6, 0.05]")
      ->capture_default_str();
  cmd.add_option("--compare", o.compare,
                 "LAMMPS logs (or screen output) of the deck's runs: compare them with the theory")
      ->expected(1, -1);
  cmd.add_option("--compare-output", o.compare_output,
                 "with --compare: write FOLDER/gas_compare.csv and the plot FOLDER/gas_compare.png");
}

bool gas_deck_requested(const GasDeckOptions& o) {
  return o.deck.has_value() || !o.compare.empty();
}

namespace {

// A deck of more spheres takes seconds to write: the command says how big it will be before it starts.
constexpr std::size_t kQuietDeckParticles = 1'000'000;
// A deck is two runs; more logs than this would draw an unreadable figure for minutes (10,000 logs took over
// five).
constexpr std::size_t kMaxComparedLogs = 64;

// The deck's request for the gas of `gas`, its errors in the order the options are read.
gas_deck::GasDeckRequest deck_request(const GasDeckOptions& o, const GasOptions& gas) {
  gas_deck::require_deck_law(gas.inputs.law);
  const gas::CoolingRequest theory = cooling_request(gas);
  gas_deck::DeckSettings settings{dem::kDefaultCode, o.particles, o.seed, o.max_eps_error};
  try {
    settings.code = dem::code_from_name(o.code);
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("--code: {}", e.what()));
  }
  const Material material = material_from(material_options(gas));
  return gas_deck::gas_deck_request(gas.inputs, theory, material, thermostat_of(gas), settings);
}

// Every file the command writes, with the option that names it.
std::vector<files::NamedPath> gas_deck_command_outputs(const GasDeckOptions& o,
                                                       const std::optional<GasDeckPaths>& paths) {
  std::vector<files::NamedPath> outputs;
  if (paths) outputs = gas_deck_outputs(*paths);
  if (o.compare_output) {
    for (const char* name : {"gas_compare.csv", "gas_compare.png"})
      outputs.push_back({"--compare-output", std::filesystem::path(*o.compare_output) / name});
  }
  return outputs;
}

std::vector<files::NamedPath> compare_inputs(const GasDeckOptions& o) {
  std::vector<files::NamedPath> inputs;
  inputs.reserve(o.compare.size());
  for (const std::string& log : o.compare) inputs.push_back({"--compare", log});
  return inputs;
}

}  // namespace

int run_gas_deck(const GasDeckOptions& o, const GasOptions& gas, bool json) {
  if (o.compare.size() > kMaxComparedLogs)
    throw InvalidInput(fmt::format("--compare takes at most {} logs (a deck's two runs are two), got {}",
                                   kMaxComparedLogs, o.compare.size()));
  const gas_deck::GasDeckRequest request = deck_request(o, gas);
  if (request.bath && o.compare_output) {
    throw InvalidInput(
        "--compare-output: the driven gas's comparison writes no CSV or plot; --json gives its curves "
        "(driven_comparison), and scripts/plots/driven_gas_runs.py draws them");
  }
  std::optional<GasDeckPaths> paths;
  if (o.deck) paths = gas_deck_paths(*o.deck);
  if (o.compare_output) files::check_output_folder(*o.compare_output);
  files::check_outputs_apart(gas_deck_command_outputs(o, paths),
                             compare_inputs(o));  // before anything is written
  std::optional<gas_deck::GasDeck> deck;
  if (paths && request.particles > kQuietDeckParticles) {
    // Built in memory and written at the end: say up front what is coming (about 6 s per 1e6 spheres).
    fmt::print(stderr, "restitution: writing a deck of {} spheres: a data file of about {:.2g} MB\n",
               request.particles,
               static_cast<double>(request.particles * gas_deck::kDataBytesPerSphere) / 1e6);
  }
  if (paths) {
    // Ctrl-C while the set is written removes its temporaries and exits 130, like run and sweep.
    const StopSignals signals;
    deck = write_gas_deck(*paths, request);
    throw_if_interrupted();
  }
  // A driven deck's logs are compared with the driven theory, a freely cooling one's with Haff's and ours.
  std::optional<gas_deck::DrivenComparison> driven;
  std::optional<gas_deck::GasComparison> comparison;
  if (!o.compare.empty() && request.bath) {
    driven = gas_deck::compare_driven_logs(o.compare, gas_deck::gas_setup(request), *thermostat_of(gas),
                                           request.bath->relaxation_time_s, print_log_note);
  } else if (!o.compare.empty()) {
    comparison = gas_deck::compare_logs(o.compare, gas_deck::gas_setup(request), print_log_note);
    const std::string warning =
        o.compare_output ? write_comparison_files(*o.compare_output, *comparison) : "";
    if (!warning.empty()) fmt::print(stderr, "restitution: warning: {}\n", warning);
  }
  if (json) {
    JsonWriter w;
    w.begin_object();
    if (deck) write_gas_deck_json(w, *paths, *deck);
    if (comparison) write_comparison_json(w, *comparison);
    if (driven) write_driven_comparison_json(w, *driven);
    fmt::print("{}\n", finish_json_document(w));
  } else {
    if (deck) print_gas_deck_text(*paths, *deck, request);
    if (comparison) print_comparison_text(*comparison);
    if (driven) print_driven_comparison_text(*driven);
  }
  return 0;
}

}  // namespace restitution::cli
