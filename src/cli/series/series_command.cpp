// SPDX-License-Identifier: BSD-3-Clause
// `restitution series coefficients|eval|validate|certify`: the analytic series, their recomputed
// coefficients and their validation against the solver.
#include <fmt/core.h>
#include <fmt/format.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/common/build_json.hpp"
#include "cli/common/commands.hpp"
#include "cli/common/json_writer.hpp"
#include "cli/common/options.hpp"
#include "cli/series/series_reports.hpp"
#include "restitution/errors.hpp"
#include "restitution/series.hpp"
#include "restitution_series_study/series_named.hpp"

namespace restitution::cli {
namespace {

void print_column(const char* name, int first_index, const std::vector<double>& values) {
  for (std::size_t i = 0; i < values.size(); ++i)
    fmt::print("  {}_{:<3} {:>25.17g}\n", name, first_index + static_cast<int>(i), values[i]);
}

struct CoefficientsOptions {
  std::string kind;
  int count = 0;
  bool json = false;
};

int run_coefficients(const CoefficientsOptions& o) {
  const auto lists = series::coefficients_by_kind(o.kind, o.count, "--");
  JsonWriter json;
  json.begin_object().field("kind", o.kind);
  if (lists.size() == 1) {
    json.field("coefficients", lists[0].values);
  } else {
    for (const auto& list : lists) json.field(list.symbol, list.values);
  }
  if (o.json) {
    fmt::print("{}\n", finish_json_document(json));
    return 0;
  }
  if (o.kind == "max-compression") {
    fmt::print(
        "maximal compression, natural units: tau_max = tau_max0 + sum a_k zeta^k, x_max = sum b_k zeta^k\n");
    fmt::print("  tau_max0 = {:.17g}\n", series::undamped_max_time());
  } else {
    fmt::print("{}\n", o.kind == "naive" ? "naive series eps = 1 + sum_{k>=1} c_k zeta^k"
                                         : "delayed-recovery series eps = sum_{k>=0} h_k zeta^{k/2}");
  }
  for (const auto& list : lists) print_column(list.symbol.c_str(), list.first_index, list.values);
  return 0;
}

struct EvalOptions {
  std::string kind;
  double zeta = 0;
  std::optional<int> terms;
  std::string coefficients = "computed";
  bool json = false;
};

int run_eval(const EvalOptions& o) {
  const auto [values, terms, published] =
      series::evaluate_by_kind(o.kind, std::span(&o.zeta, 1), o.terms, o.coefficients == "published", "--");
  const series::Value& v = values.front();
  const char* coefficients = published ? "published" : "computed";
  if (o.json) {
    JsonWriter json;
    json.begin_object().field("kind", o.kind).field("zeta", o.zeta);
    if (terms > 0) json.field("terms", terms).field("coefficients", coefficients);
    json.field("eps", v.eps).field("one_minus_eps", v.one_minus_eps);
    fmt::print("{}\n", finish_json_document(json));
  } else {
    fmt::print("{} at zeta = {}{}: eps = {:.17g}, 1 - eps = {:.17g}\n", o.kind, o.zeta,
               terms > 0 ? fmt::format(" ({} terms, {} coefficients)", terms, coefficients) : "", v.eps,
               v.one_minus_eps);
  }
  return 0;
}

void add_coefficients(CLI::App& parent, Action& chosen) {
  auto o = std::make_shared<CoefficientsOptions>();
  CLI::App* cmd = parent.add_subcommand("coefficients", "recomputed series coefficients (__float128)");
  cmd->add_option("--kind", o->kind, "naive (c_1..c_N), delayed-recovery (h_0..h_N), max-compression (a, b)")
      ->required()
      ->check(CLI::IsMember(series::coefficient_kinds()));
  cmd->add_option("--count", o->count, "N: how many coefficients")->required();
  cmd->add_flag("--json", o->json,
                "print one JSON object (numbers in the shortest form that reads back to the same double)");
  cmd->callback([o, &chosen] { chosen = [o] { return run_coefficients(*o); }; });
}

void add_eval(CLI::App& parent, Action& chosen) {
  auto o = std::make_shared<EvalOptions>();
  CLI::App* cmd = parent.add_subcommand("eval", "evaluate one series or approximation at zeta");
  cmd->add_option(
         "--kind", o->kind,
         fmt::format("{} (the names scenes and `series validate` use; naive and delayed-recovery are "
                     "aliases of the two series, and NAME:published or NAME:computed-N choose a "
                     "series' coefficients)",
                     fmt::join(series::evaluation_kinds(), ", ")))
      ->required();
  cmd->add_option("--zeta", o->zeta,
                  "zeta = beta v^{1/5} >= 0; the series only below their radius of convergence (naive 1.39, "
                  "delayed-recovery 1.10)")
      ->required();
  cmd->add_option(
      "--terms", o->terms,
      "series terms: c_1..c_N or h_0..h_N (default: 40 naive-series, 60 delayed-recovery-series)");
  cmd->add_option("--coefficients", o->coefficients, "computed (default) or published (2008 Tables III, V)")
      ->check(CLI::IsMember({"computed", "published"}));
  cmd->add_flag("--json", o->json,
                "print one JSON object (numbers in the shortest form that reads back to the same double)");
  cmd->callback([o, &chosen] { chosen = [o] { return run_eval(*o); }; });
}

void add_validate(CLI::App& parent, Action& chosen) {
  auto o = std::make_shared<std::pair<std::string, std::string>>("out/series", "png");  // folder, formats
  CLI::App* cmd = parent.add_subcommand("validate", "every approximation against the solver: CSV, JSON, PNG");
  cmd->add_option("--out", o->first, "output folder")->capture_default_str()->check(non_empty_path());
  add_figure_format_option(cmd, o->second);
  cmd->callback([o, &chosen] {
    chosen = [o] { return run_series_validation(o->first, scene::figure_formats_from_list(o->second)); };
  });
}

void add_certify(CLI::App& parent, Action& chosen) {
  auto o = std::make_shared<std::pair<int, std::string>>(40, "");
  CLI::App* cmd = parent.add_subcommand(
      "certify", "coefficients in two precisions with their certified digits, against the published tables");
  cmd->add_option("--order", o->first, "largest power of zeta (h up to zeta^{order})")->capture_default_str();
  cmd->add_option("--out", o->second, "CSV file to write (default: stdout)")->check(non_empty_path());
  cmd->callback([o, &chosen] { chosen = [o] { return run_series_certify(o->first, o->second); }; });
}

}  // namespace

void add_series_command(CLI::App& app, Action& chosen) {
  CLI::App* cmd = app.add_subcommand("series", "analytic series and approximations of eps(zeta)");
  cmd->require_subcommand(1);
  add_coefficients(*cmd, chosen);
  add_eval(*cmd, chosen);
  add_validate(*cmd, chosen);
  add_certify(*cmd, chosen);
}

}  // namespace restitution::cli
