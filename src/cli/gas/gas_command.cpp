// SPDX-License-Identifier: BSD-3-Clause
// `restitution gas`: the freely cooling granular gas of these spheres in its homogeneous cooling state, from
// the kinetic theory with the law's exact ε(v) (src/gas/, docs/gas.md): T(t), Haff's τ₀, the local exponent,
// the cooling rate, the collision frequency and ε_eff(T), as a table, JSON, CSV and a plot.
#include <fmt/core.h>
#include <fmt/format.h>

#include <cstdio>
#include <filesystem>
#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/common/build_json.hpp"
#include "cli/common/commands.hpp"
#include "cli/common/json_writer.hpp"
#include "cli/common/options.hpp"
#include "cli/common/plot_script.hpp"
#include "cli/gas/gas_deck_options.hpp"
#include "cli/gas/gas_options.hpp"
#include "cli/gas/gas_table.hpp"
#include "files/output_files.hpp"
#include "files/output_guards.hpp"
#include "files/scratch_file.hpp"
#include "restitution_gas/gas_inputs.hpp"
#include "scene/figure_formats.hpp"

namespace restitution::cli {
namespace {

struct GasCommandOptions {
  GasOptions gas;
  GasDeckOptions deck;  // --deck, --compare (cli/gas/gas_deck_options.hpp)
  bool json = false;
  std::string out;     // CSV file
  std::string plot;    // figure file (png, pdf, svg by its extension)
  std::string format;  // figure formats besides the one --plot's extension names
};

// The driven gas's thermostat and steady state (none: the freely cooling gas).
struct Driving {
  gas::Thermostat thermostat;
  gas::SteadyState steady;
};

const char* thermostat_name(const gas::Thermostat& t) {
  return t.kind == gas::ThermostatKind::langevin ? "langevin" : "white-noise";
}

void add_driving_json(JsonWriter& json, const Driving& d) {
  json.key("thermostat").begin_object().field("kind", thermostat_name(d.thermostat));
  if (d.thermostat.kind == gas::ThermostatKind::langevin) {
    json.field("bath_temperature_j", d.thermostat.bath_temperature_j)
        .field("bath_time_s", d.thermostat.bath_time_s);
  } else {
    json.field("power_w", d.thermostat.power_w);
  }
  json.end_object();
  const gas::SteadyState& s = d.steady;
  json.field("steady_temperature_j", s.temperature_j).field("steady_a2", s.a2);
  json.field("relaxation_time_s", s.relaxation_time_s).field("driving_exponent", s.driving_exponent);
  json.field("constant_eps_driving_exponent", s.constant_eps_driving_exponent);
  json.field("steady_effective_eps", s.effective_eps)
      .field("steady_collision_frequency_hz", s.collision_frequency_hz);
  json.field("steady_power_w", s.power_w);
}

std::string json_text(const gas::CoolingRequest& r, const gas::CoolingCurve& c, const GasCommandOptions& o,
                      const std::optional<Driving>& driving) {
  JsonWriter json;
  json.begin_object();
  json.key("law").begin_object();
  json.field("kind", law_name(r.law.kind)).field("end", end_name(r.law.end));
  json.field("zeta_at_reference", r.law.zeta_at_reference);
  json.field("reference_speed_m_s", r.law.reference_speed_m_s).end_object();
  json.field("mass_kg", r.particles.mass_kg).field("diameter_m", r.particles.diameter_m);
  json.field("packing_fraction", r.particles.packing_fraction);
  json.field("contact_correlation", c.contact_correlation).field("number_density_m3", c.number_density_m3);
  json.field("initial_temperature_j", r.initial_temperature_j);
  json.field("tau0_s", c.tau0_s).field("haff_eps", c.haff_eps);
  if (!c.a2_evolving) json.field("a2", c.a2);  // evolving: the array "a2" of the curve
  json.field("collision_rate_factor", r.collision_rate_factor).field("duration_s", c.duration_s);
  if (driving) add_driving_json(json, *driving);
  for (const gas::CurveColumn& col : gas::curve_columns(c)) json.field(col.name, *col.values);
  if (!o.out.empty()) json.field("csv", o.out);
  if (!o.plot.empty()) json.field("plot", o.plot);
  return finish_json_document(json) + "\n";
}

std::string driving_text(const Driving& d) {
  const gas::SteadyState& s = d.steady;
  const bool langevin = d.thermostat.kind == gas::ThermostatKind::langevin;
  const std::string bath = langevin
                               ? fmt::format("Langevin bath T_b = {:.10g} J, tau_b = {:.10g} s",
                                             d.thermostat.bath_temperature_j, d.thermostat.bath_time_s)
                               : fmt::format("white noise, power {:.10g} W per sphere", d.thermostat.power_w);
  return fmt::format(
      "# driven by {}: steady T_s = {:.10g} J, a2 = {:.6g} (stationary), relaxation time {:.6g} s, eps_eff "
      "= {:.8g}, {:.6g} collisions/s, {:.6g} W per sphere dissipated\n"
      "# d ln T_s / d ln {} = {:.6f} (a constant eps: {:.6f})\n",
      bath, s.temperature_j, s.a2, s.relaxation_time_s, s.effective_eps, s.collision_frequency_hz, s.power_w,
      langevin ? "T_b" : "P", s.driving_exponent, s.constant_eps_driving_exponent);
}

std::string text_table(const gas::CoolingRequest& r, const gas::CoolingCurve& c,
                       const std::optional<Driving>& driving) {
  std::string out;
  auto line = std::back_inserter(out);
  fmt::format_to(line, "# restitution gas: {}\n", gas_law_text(r));
  fmt::format_to(
      line,
      "# spheres m = {:.6g} kg, sigma = {:.6g} m, phi = {:g} (g2 = {:.6g}, n = {:.6g} 1/m^3); T0 = {:.6g} "
      "J\n",
      r.particles.mass_kg, r.particles.diameter_m, r.particles.packing_fraction, c.contact_correlation,
      c.number_density_m3, r.initial_temperature_j);
  const char* a2_kind = c.a2_evolving ? " (first Sonine correction, evolving from this: column a2)"
                        : c.a2 == 0.0 ? " (Maxwellian)"
                                      : " (first Sonine correction, constant)";
  fmt::format_to(line, "# Haff's law tangent at t = 0: tau0 = {:.10g} s, eps = {:.10g}; a2 = {:g}{}\n",
                 c.tau0_s, c.haff_eps, c.a2, a2_kind);
  if (driving) out += driving_text(*driving);
  fmt::format_to(line, "{:>13} {:>13} {:>10} {:>10} {:>9} {:>12} {:>12} {:>12} {:>10}{}\n", "time_s",
                 "temperature_j", "T/T0", "Haff T/T0", "exponent", "cooling_1/s", "collisions/s",
                 "collisions", "eps_eff", c.a2_evolving ? fmt::format(" {:>11}", "a2") : "");
  for (std::size_t i = 0; i < c.time_s.size(); ++i) {
    fmt::format_to(
        line, "{:>13.6e} {:>13.6e} {:>10.4e} {:>10.4e} {:>9.5f} {:>12.5e} {:>12.5e} {:>12.5e} {:>10.7f}{}\n",
        c.time_s[i], c.temperature_j[i], c.temperature_j[i] / r.initial_temperature_j,
        c.haff_temperature_j[i] / r.initial_temperature_j, c.local_exponent[i], c.cooling_rate_hz[i],
        c.collision_frequency_hz[i], c.collisions_per_particle[i], c.effective_eps[i],
        c.a2_evolving ? fmt::format(" {:>11.4e}", c.sonine_a2[i]) : "");
  }
  return out;
}

void write_files(const gas::CoolingRequest& r, const gas::CoolingCurve& c, const GasCommandOptions& o) {
  const std::string table = gas_csv(c);
  if (!o.out.empty()) files::write_file_atomically(o.out, table);
  if (o.plot.empty()) return;
  // Without --out the plot reads a scratch copy of the table beside the image, removed afterwards.
  std::optional<files::ScratchFile> scratch;
  if (o.out.empty()) scratch.emplace(o.plot, "data.csv", table);
  const std::filesystem::path data = scratch ? scratch->path() : std::filesystem::path(o.out);
  const std::string why = run_plot_script("gas_cooling", data, o.plot, gas_plot_arguments(r, c),
                                          scene::plot_figure_formats(o.plot, o.format));
  if (!why.empty()) fmt::print(stderr, "{}", no_plot_warning("gas", why));
}

int run_gas(const GasCommandOptions& o) {
  if (gas_deck_requested(o.deck)) return run_gas_deck(o.deck, o.gas, o.json);
  if (!o.out.empty()) files::check_output_file(o.out);
  if (!o.plot.empty()) files::check_figure_file(o.plot, "--plot");
  if (!o.out.empty() && !o.plot.empty())
    files::check_outputs_apart({{"--out", o.out}, {"--plot", o.plot}}, {});
  const gas::CoolingRequest request = cooling_request(o.gas);
  const std::optional<gas::Thermostat> thermostat = thermostat_of(o.gas);
  const gas::DrivenCurve theory = gas::gas_curve(request, thermostat);
  const gas::CoolingCurve& curve = theory.curve;
  std::optional<Driving> driving;
  if (thermostat) driving = Driving{*thermostat, theory.steady};
  write_files(request, curve, o);
  // One write: a stdout that cannot take it is reported once, as the I/O failure it is (main's flush).
  const std::string text =
      o.json ? json_text(request, curve, o, driving) : text_table(request, curve, driving);
  std::fputs(text.c_str(), stdout);
  return 0;
}

}  // namespace

void add_gas_command(CLI::App& app, Action& chosen) {
  auto o = std::make_shared<GasCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "gas",
      "the freely cooling gas of these spheres from kinetic theory with the exact eps(v): T(t), Haff's "
      "tau0, the local exponent; with --thermostat the driven gas: steady T_s and a2, relaxation "
      "(docs/gas.md)");
  add_gas_options(*cmd, o->gas);
  add_gas_deck_options(*cmd, o->deck);
  cmd->add_flag("--json", o->json,
                "print one JSON object (numbers in the shortest form that reads back to the same double)");
  cmd->add_option("--out", o->out, "write the curve to this CSV file")->check(non_empty_path());
  CLI::Option* plot = add_plot_option(cmd, o->plot, "plot T(t)/T0 and the local exponent to this file");
  add_figure_format_option(cmd, o->format)->needs(plot);
  cmd->callback([o, &chosen] { chosen = [o] { return run_gas(*o); }; });
}

}  // namespace restitution::cli
