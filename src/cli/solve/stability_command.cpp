// SPDX-License-Identifier: BSD-3-Clause
// `restitution stability`: the stability report over ζ in [0, 1e6] for both ends, as a table, JSON, or
// (with --out) CSV + JSON + PNG.
#include <fmt/core.h>

#include <filesystem>
#include <memory>

#include "analysis/stability_report.hpp"
#include "cli/common/build_json.hpp"
#include "cli/common/commands.hpp"
#include "cli/common/json_writer.hpp"
#include "cli/common/options.hpp"
#include "cli/common/plot_script.hpp"
#include "cli/common/progress.hpp"
#include "cli/common/stop_signals.hpp"
#include "files/output_files.hpp"
#include "sweep/number_text.hpp"

namespace restitution::cli {
namespace {

struct StabilityCliOptions {
  double tolerance = 1e-9;
  int points_per_decade = 1;
  bool json = false;
  std::string out;
  std::string format = "png";
};

std::string flag_text(const StabilityFlag& f) {
  if (f.kind == StabilityFlagKind::self_convergence)
    return fmt::format("self-convergence {:.3g} > tolerance", f.value);
  return fmt::format("{} differs by {:.3g} > tolerance", method_name(f.method), f.value);
}

std::string flags_text(const StabilityPoint& p) {
  std::string text;
  for (const StabilityFlag& f : p.flags) text += (text.empty() ? "" : "; ") + flag_text(f);
  return text;
}

std::string failure_text(const EngineCheck& e) {
  return e.failure == EngineFailure::too_much_work ? "too much work (stiff)" : e.failure_message;
}

std::string engine_text(const EngineCheck& e) {
  return e.solved ? number17(e.relative_difference) : failure_text(e);
}

std::string csv(const StabilityReport& report) {
  std::string out = "zeta,end,method,eps,one_minus_eps,tau,steps,rhs_evaluations,self_convergence";
  for (const Method m : kCrossCheckedMethods) out += fmt::format(",{0}_difference,{0}_steps", method_name(m));
  out += ",verdict\n";
  for (const StabilityPoint& p : report.points) {
    out += fmt::format("{},{},{},{},{},{},{},{},{}", number17(p.zeta), end_name(p.end), method_name(p.method),
                       number17(p.result.eps), number17(p.result.one_minus_eps), number17(p.result.tau),
                       p.steps, p.rhs_evaluations, number17(p.self_convergence));
    for (const EngineCheck& e : p.engines) out += fmt::format(",{},{}", engine_text(e), e.steps);
    out += fmt::format(",\"{}\"\n", p.flags.empty() ? "ok" : flags_text(p));
  }
  return out;
}

std::string json_text(const StabilityReport& report) {
  JsonWriter json;
  json.begin_object().field("tolerance", report.tolerance).field("flagged", report.flagged());
  json.key("points").begin_array();
  for (const StabilityPoint& p : report.points) {
    json.begin_object()
        .field("zeta", p.zeta)
        .field("end", end_name(p.end))
        .field("method", method_name(p.method))
        .field("eps", p.result.eps)
        .field("one_minus_eps", p.result.one_minus_eps)
        .field("tau", p.result.tau)
        .field("steps", p.steps)
        .field("rhs_evaluations", p.rhs_evaluations)
        .field("self_convergence", p.self_convergence);
    json.key("engines").begin_object();
    for (const EngineCheck& e : p.engines) {
      json.key(method_name(e.method)).begin_object().field("solved", e.solved).field("steps", e.steps);
      if (e.solved)
        json.field("relative_difference", e.relative_difference);
      else
        json.field("failure", failure_text(e));
      json.end_object();
    }
    json.end_object();
    json.field("verdict", p.flags.empty() ? "ok" : "flagged");
    json.key("flags").begin_array();
    for (const StabilityFlag& f : p.flags) json.value(flag_text(f));
    json.end_array().end_object();
  }
  json.end_array();
  json.key("decades").begin_array();
  for (const DecadeSummary& d : report.decades) {
    json.begin_object()
        .field("decade", d.decade)
        .field("end", end_name(d.end))
        .field("worst_self_convergence", d.worst_self_convergence)
        .field("worst_engine_difference", d.worst_engine_difference)
        .field("engine_failures", d.engine_failures)
        .end_object();
  }
  json.end_array();
  return finish_json_document(json) + "\n";
}

void print_table(const StabilityReport& report) {
  fmt::print(
      "stability report, tolerance {:g} (self-convergence: change at tolerance/100; engines: relative\n"
      "difference from the production result; both relative to min(eps, 1 - eps))\n",
      report.tolerance);
  fmt::print("{:>10} {:>17} {:>6} {:>22} {:>8} {:>10}", "zeta", "end", "method", "eps", "steps", "self-conv");
  for (const Method m : kCrossCheckedMethods) fmt::print(" {:>22}", method_name(m));
  fmt::print("  verdict\n");
  for (const StabilityPoint& p : report.points) {
    fmt::print("{:>10.3g} {:>17} {:>6} {:>22.15g} {:>8} {:>10.2g}", p.zeta, end_name(p.end),
               method_name(p.method), p.result.eps, p.steps, p.self_convergence);
    for (const EngineCheck& e : p.engines)
      fmt::print(" {:>22}", e.solved ? fmt::format("{:.2g}", e.relative_difference) : failure_text(e));
    fmt::print("  {}\n", p.flags.empty() ? "ok" : flags_text(p));
  }
  fmt::print("{} of {} points flagged\n", report.flagged(), report.points.size());
}

int run_stability(const StabilityCliOptions& o) {
  StabilityOptions options;
  options.tolerance = o.tolerance;
  if (!o.out.empty()) files::check_output_folder(o.out);
  // Ctrl-C stops at the next zeta, before anything is printed or written; one that arrives while the files
  // are written or plotted still stops the command with its message.
  const StopSignals signals;
  const StabilityReport report = [&] {
    ProgressLine progress("stability (zeta)");
    options.progress = progress.stoppable_callback();
    return stability_report(stability_grid(o.points_per_decade), options);
  }();
  if (!o.out.empty()) {
    const std::filesystem::path folder(o.out);
    files::write_file_atomically(folder / "stability.csv", csv(report));
    files::write_file_atomically(folder / "stability.json", json_text(report));
    const std::string why =
        run_plot_script("stability", folder / "stability.csv", folder / "stability.png",
                        {fmt::format("{}", report.tolerance)}, scene::figure_formats_from_list(o.format));
    if (!why.empty()) fmt::print(stderr, "{}", no_plot_warning("stability", why));
  }
  if (o.json)
    fmt::print("{}", json_text(report));
  else
    print_table(report);
  return 0;
}

}  // namespace

void add_stability_command(CLI::App& app, Action& chosen) {
  auto o = std::make_shared<StabilityCliOptions>();
  CLI::App* cmd =
      app.add_subcommand("stability", "self-convergence and engine agreement over zeta in [0, 1e6]");
  cmd->add_option("--tolerance", o->tolerance, "production tolerance T in [1e-9, 1e-2]; the check uses T/100")
      ->capture_default_str();
  cmd->add_option("--points-per-decade", o->points_per_decade,
                  fmt::format("grid points per decade of zeta (1..{})", kMaxStabilityPointsPerDecade))
      ->capture_default_str();
  cmd->add_flag("--json", o->json,
                "print one JSON object (numbers in the shortest form that reads back to the same double)");
  cmd->add_option("--out", o->out, "folder for stability.csv, stability.json and stability.png")
      ->check(non_empty_path());
  add_figure_format_option(cmd, o->format);
  cmd->callback([o, &chosen] { chosen = [o] { return run_stability(*o); }; });
}

}  // namespace restitution::cli
