// SPDX-License-Identifier: BSD-3-Clause
#include "cli/gas/gas_deck_files.hpp"

#include <fmt/core.h>

#include "cli/common/stop_signals.hpp"
#include "files/file_set.hpp"
#include "files/output_files.hpp"
#include "restitution/errors.hpp"

namespace restitution::cli {

namespace fs = std::filesystem;

GasDeckPaths gas_deck_paths(const std::string& file) {
  if (file.empty()) throw InvalidInput("--deck needs a file name, got an empty one");
  files::check_output_file(file);
  const fs::path path(file);
  const std::string stem = path.stem().string();
  GasDeckPaths p;
  p.law_input = path;
  p.constant_eps_input = path.parent_path() / (stem + "_constant_eps" + path.extension().string());
  p.data = path.parent_path() / (stem + ".data");
  if (p.data == p.law_input) p.data = path.parent_path() / (stem + "_gas.data");  // FILE named *.data
  return p;
}

gas_deck::GasDeck write_gas_deck(const GasDeckPaths& paths, const gas_deck::GasDeckRequest& request) {
  gas_deck::GasDeck deck = gas_deck::lammps_gas_deck(request, paths.data.filename().string());
  // One set: the inputs read the data file, so the law's input, the one the printed command starts, comes
  // last.
  files::write_file_set({{paths.data, &deck.data},
                         {paths.constant_eps_input, &deck.constant_eps_input},
                         {paths.law_input, &deck.law_input}},
                        throw_if_interrupted);
  return deck;
}

std::vector<files::NamedPath> gas_deck_outputs(const GasDeckPaths& paths) {
  return {{"--deck", paths.law_input},
          {"--deck (its constant-eps companion)", paths.constant_eps_input},
          {"--deck (its data file)", paths.data}};
}

void print_gas_deck_text(const GasDeckPaths& paths, const gas_deck::GasDeck& d,
                         const gas_deck::GasDeckRequest& request) {
  fmt::print("# gas deck: {} spheres, packing fraction {}, box {:.6g} m ({:.4g} diameters), seed {}\n",
             request.particles, request.packing_fraction, d.box_m, d.box_m / d.diameter_m, request.seed);
  fmt::print(
      "# viscoelastic gas: {}\n# constant-eps companion (eps = {:.10g}): {}\n"
      "# data file: {} ({} bytes, {:.1f} per sphere)\n",
      paths.law_input.string(), d.constant_eps, paths.constant_eps_input.string(), paths.data.string(),
      d.data.size(), static_cast<double>(d.data.size()) / static_cast<double>(request.particles));
  fmt::print(
      "# tau0 = {:.6g} s (constant-eps gas at T0 = {:.6g} J); duration {:.6g} s = {:.4g} tau0; {} "
      "temperature prints\n",
      d.haff_time_s, d.initial_temperature_j, d.duration_s, d.duration_s / d.haff_time_s,
      d.print_times_s.size() + 1);
  fmt::print("# dt0 = {:.6g} s (worst |eps error| {:.3g} <= {} at {:.4g} m/s), growing as (T0/T)^(1/10)\n",
             d.time_step_s, d.eps_error_worst, request.max_eps_error, d.fast_speed_m_s);
  if (d.box_m > d.shear_critical_length_m) {
    fmt::print(
        "# shear instability: L_c = {:.4g} diameters, below the box; its longest shear mode grows "
        "{:.3g}-fold over the run\n",
        d.shear_critical_length_m / d.diameter_m, d.shear_mode_growth);
  } else {
    fmt::print("# shear instability: L_c = {:.4g} diameters, above the box: every shear mode decays\n",
               d.shear_critical_length_m / d.diameter_m);
  }
  for (const auto& w : d.warnings) fmt::print("# warning: {}\n", w);
  fmt::print("# run from {}: {} and {} (or {}); then restitution gas --compare LOG...\n",
             paths.data.parent_path().empty() ? fs::path(".").string() : paths.data.parent_path().string(),
             gas_deck::gas_deck_command(request.code, paths.law_input.filename().string(), 1),
             gas_deck::gas_deck_command(request.code, paths.constant_eps_input.filename().string(), 1),
             gas_deck::gas_deck_command(request.code, "...", 4));
}

void write_gas_deck_json(JsonWriter& json, const GasDeckPaths& paths, const gas_deck::GasDeck& d) {
  json.key("deck").begin_object();
  json.field("file", paths.law_input.string()).field("constant_eps_file", paths.constant_eps_input.string());
  json.field("data_file", paths.data.string())
      .field("data_bytes", static_cast<long>(d.data.size()))
      .field("box_m", d.box_m)
      .field("haff_time_s", d.haff_time_s);
  json.field("duration_s", d.duration_s).field("time_step_s", d.time_step_s);
  json.field("eps_error_worst", d.eps_error_worst).field("fast_speed_m_s", d.fast_speed_m_s);
  json.field("constant_eps", d.constant_eps).field("shear_critical_length_m", d.shear_critical_length_m);
  json.field("shear_mode_growth", d.shear_mode_growth).field("warnings", d.warnings).end_object();
}

}  // namespace restitution::cli
