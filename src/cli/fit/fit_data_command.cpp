// SPDX-License-Identifier: BSD-3-Clause
// `restitution fit-data FILE`: fit measured ε(v) with every candidate law, intervals from the profile of χ²,
// the law the data prefer (docs/fit.md).
#include <fmt/core.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "cli/common/commands.hpp"
#include "cli/common/deprecated_alias.hpp"
#include "cli/common/material_options.hpp"
#include "cli/common/options.hpp"
#include "cli/common/plot_script.hpp"
#include "cli/fit/fit_data_report.hpp"
#include "cli/fit/fit_plot_tables.hpp"
#include "files/output_files.hpp"
#include "files/output_guards.hpp"
#include "restitution/errors.hpp"
#include "restitution/fit.hpp"
#include "restitution/material.hpp"
#include "scene/figure_formats.hpp"

namespace restitution::cli {
namespace {

struct FitDataOptions {
  std::string file;
  std::vector<std::string> laws;
  std::string speed_independent_end = end_name(kDefaultSpeedIndependentEnd);
  double tolerance = SolveOptions{}.tolerance;
  std::string method = method_name(SolveOptions{}.method);
  MaterialOptions material;
  bool json = false;
  std::string output;
  std::string plot;    // figure file (png, pdf, svg by its extension)
  std::string format;  // figure formats besides the one --plot's extension names
};

// The tables the figure script reads, beside the image while it draws; removed however the drawing ends.
struct PlotTables {
  std::filesystem::path points;
  std::filesystem::path curves;
  PlotTables(std::filesystem::path points_csv, std::filesystem::path curves_csv)
      : points(std::move(points_csv)), curves(std::move(curves_csv)) {}
  PlotTables(const PlotTables&) = delete;
  PlotTables& operator=(const PlotTables&) = delete;
  ~PlotTables() {
    std::error_code ignored;
    std::filesystem::remove(points, ignored);
    std::filesystem::remove(curves, ignored);
  }
};

// The data with error bars, each law's ε(v) with its 95 % band and the residuals (scripts/plots/fit_data.py,
// the figure of a scene's [[fit]]). A plot that cannot be made is a warning: the fit is printed regardless.
// Returns whether the figure was drawn.
bool draw(const FitDataOptions& o, const FitData& data, const FitResult& result, const FitOptions& options) {
  const PlotTables tables{o.plot + ".data.csv", o.plot + ".curves.csv"};
  files::write_file_atomically(tables.points, fit_data_table(data, result));
  files::write_file_atomically(tables.curves, fit_curves_table(data, result, options));
  const std::string why =
      run_plot_script("fit_data", tables.points, o.plot, {"--curves", tables.curves.string()},
                      scene::plot_figure_formats(o.plot, o.format));
  if (!why.empty()) fmt::print(stderr, "{}", no_plot_warning("fit-data", why));
  return why.empty();
}

// A refusal of the data as a whole (too few points) names the file, as the row errors of the CSV do.
void check_data_of_file(const FitData& data, const std::string& file) {
  try {
    check_fit_data(data);
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("{}: {}", file, e.what()));
  }
}

int run_fit_data(const FitDataOptions& o) {
  // Everything is checked before anything is written.
  std::vector<files::NamedPath> outputs;
  if (!o.output.empty()) outputs.push_back({"--out", o.output});
  if (!o.plot.empty()) outputs.push_back({"--plot", o.plot});
  files::check_outputs_apart(outputs, {{"", o.file}});
  if (!o.output.empty()) files::check_output_file(o.output);
  if (!o.plot.empty()) files::check_figure_file(o.plot, "--plot");
  FitOptions options;
  options.candidates = fit_candidates(o.laws, o.speed_independent_end);
  options.tolerance = o.tolerance;
  options.method = method_from_name(o.method);
  if (o.material.any()) options.k = elastic_constants(material_from(o.material)).k;
  const FitData data = read_fit_csv(o.file);
  check_data_of_file(data, o.file);
  const FitResult result = fit_data(data, options);
  const FitReportInput report{o.file, &data, &result, options.k};
  // The JSON holds every point: made only when asked for (a million rows make ~100 MB of it).
  const std::string json = o.json || !o.output.empty() ? fit_json(report) : std::string();
  if (!o.output.empty()) files::write_file_atomically(o.output, json + "\n");
  const bool drawn = !o.plot.empty() && draw(o, data, result, options);
  fmt::print("{}", o.json ? json + "\n" : fit_table(report));
  if (!o.output.empty() && !o.json) fmt::print("wrote {}\n", o.output);
  if (drawn && !o.json) fmt::print("wrote {}\n", o.plot);
  return 0;
}

}  // namespace

void add_fit_data_command(CLI::App& app, Action& chosen) {
  auto o = std::make_shared<FitDataOptions>();
  CLI::App* cmd = app.add_subcommand(
      "fit-data",
      "fit measured eps(v) (CSV: v,eps[,sigma]) with viscoelastic Hertz at both ends, Tsuji and the linear "
      "dash-pot: best parameter, 68 % and 95 % profile intervals, chi2/dof, AIC, residual tests "
      "(docs/fit.md)");
  cmd->add_option(
         "file", o->file,
         "CSV with a header naming the columns v [m/s], eps and optionally sigma (other usual spellings "
         "and the bounds: docs/fit.md)")
      ->required();
  cmd->add_option(
      "--law", o->laws,
      "fit only these laws (repeatable): viscoelastic-hertz (both ends), tsuji-hertz, linear-dashpot");
  cmd->add_option("--speed-independent-end", o->speed_independent_end,
                  "end of the collision for tsuji-hertz and linear-dashpot (the data cannot tell: only their "
                  "parameter differs)")
      ->check(CLI::IsMember(end_names()))
      ->capture_default_str();
  cmd->add_option("--tolerance", o->tolerance,
                  "accuracy of each solve of tsuji-hertz and linear-dashpot, in [1e-11, 1e-2] (viscoelastic "
                  "Hertz uses the certified fast table, 1e-13)")
      ->capture_default_str();
  cmd->add_option("--method", o->method,
                  "integration method for those solves: " + alternatives(method_names()))
      ->check(CLI::IsMember(method_names()))
      ->capture_default_str();
  add_material_options(*cmd, o->material);
  cmd->add_flag("--json", o->json, "print one JSON object instead of the table");
  CLI::Option* out =
      cmd->add_option(
             "--out", o->output,
             "also write the JSON object to this file (for calibrate --from-fit and dem --from-fit); "
             "never the input file")
          ->check(non_empty_path());
  add_deprecated_alias(*cmd, out, "--output");
  CLI::Option* plot =
      add_plot_option(cmd, o->plot, "draw the data, each law's eps(v) with its 95 % band and the residuals");
  add_figure_format_option(cmd, o->format)->needs(plot);
  cmd->callback([o, &chosen] { chosen = [o] { return run_fit_data(*o); }; });
}

}  // namespace restitution::cli
