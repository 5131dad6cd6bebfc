// SPDX-License-Identifier: BSD-3-Clause
// Files of `restitution series validate` and `restitution series certify`.
#include "cli/series/series_reports.hpp"

#include <fmt/core.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "cli/common/json_writer.hpp"
#include "cli/common/plot_script.hpp"
#include "files/output_files.hpp"
#include "restitution_series_study/series_coefficients.hpp"
#include "restitution_series_study/series_validation.hpp"
#include "sweep/number_text.hpp"

namespace restitution::cli {
namespace {

std::string validation_csv(const series::ValidationReport& r) {
  std::string csv = "zeta,naive_eps,naive_one_minus_eps,delayed_recovery_eps,delayed_recovery_one_minus_eps";
  for (const auto& c : r.candidates)
    csv += fmt::format(",{0}_eps,{0}_one_minus_eps,{0}_rel_err_eps,{0}_rel_err_one_minus_eps", c.name);
  csv += "\n";
  for (const auto& row : r.rows) {
    std::vector<double> fields{row.zeta, row.solver[CollisionEnd::naive].eps,
                               row.solver[CollisionEnd::naive].one_minus_eps,
                               row.solver[CollisionEnd::delayed_recovery].eps,
                               row.solver[CollisionEnd::delayed_recovery].one_minus_eps};
    for (const auto& e : row.errors)
      fields.insert(fields.end(),
                    {e.value.eps, e.value.one_minus_eps, e.relative_error_eps, e.relative_error_one_minus});
    for (std::size_t i = 0; i < fields.size(); ++i) {
      if (i > 0) csv += ',';
      csv += number17(fields[i]);
    }
    csv += '\n';
  }
  return csv;
}

std::string validation_json(const series::ValidationReport& r) {
  JsonWriter j;
  j.begin_object();
  j.key("options")
      .begin_object()
      .field("zeta_min", r.options.zeta_min)
      .field("zeta_max", r.options.zeta_max)
      .field("points_per_decade", r.options.points_per_decade)
      .field("solver_tolerance", r.options.tolerance)
      .end_object();
  j.key("approximations").begin_array();
  for (std::size_t i = 0; i < r.candidates.size(); ++i) {
    const auto& c = r.candidates[i];
    const auto& s = r.summaries[i];
    j.begin_object().field("name", c.name).field("end", end_name(c.end)).field("description", c.description);
    j.key("first_zeta_exceeding").begin_array();
    for (const auto& x : s.crossings)
      j.begin_object()
          .field("threshold", x.threshold)
          .field("eps", x.zeta_eps)
          .field("one_minus_eps", x.zeta_one_minus_eps)
          .end_object();
    j.end_array();
    j.key("large_zeta")
        .begin_object()
        .field("slope_at_1e3", s.large_zeta.approximation_slope)
        .field("solver_slope_at_1e3", s.large_zeta.solver_slope)
        .field("implied_exponent", s.large_zeta.implied_exponent)
        .end_object();
    j.end_object();
  }
  j.end_array();
  j.key("radii").begin_array();
  for (const auto& x : r.radii)
    j.begin_object()
        .field("series", x.series)
        .field("terms", x.terms)
        .field("ratio", x.ratio)
        .field("root", x.root)
        .field("domb_sykes", x.domb_sykes)
        .field("domb_sykes_slope", x.domb_sykes_slope)
        .end_object();
  j.end_array();
  j.end_object();
  return j.str() + "\n";
}

std::string crossing_text(double zeta) {
  return std::isnan(zeta) ? "never" : fmt::format("{:.3g}", zeta);
}

void print_validation_summary(const series::ValidationReport& r) {
  fmt::print("first zeta on the grid [{:g}, {:g}] where the relative error exceeds 1e-3 / 1e-6 / 1e-10\n",
             r.options.zeta_min, r.options.zeta_max);
  fmt::print("  {:<26} {:<17} {:>26} {:>26}\n", "approximation", "end", "eps", "1 - eps");
  for (std::size_t i = 0; i < r.candidates.size(); ++i) {
    std::string eps;
    std::string one_minus;
    for (const auto& x : r.summaries[i].crossings) {
      if (!eps.empty()) {
        eps += " / ";
        one_minus += " / ";
      }
      eps += crossing_text(x.zeta_eps);
      one_minus += crossing_text(x.zeta_one_minus_eps);
    }
    fmt::print("  {:<26} {:<17} {:>26} {:>26}\n", r.candidates[i].name, end_name(r.candidates[i].end), eps,
               one_minus);
  }
  fmt::print("convergence radius in zeta (ratio / root / Domb-Sykes):\n");
  for (const auto& x : r.radii)
    fmt::print("  {} ({} terms): {:.4g} / {:.4g} / {:.4g}\n", x.series, x.terms, x.ratio, x.root,
               x.domb_sykes);
}

}  // namespace

int run_series_validation(const std::string& folder_name, const std::vector<std::string>& formats) {
  const std::filesystem::path folder(folder_name);
  files::check_output_folder(folder);
  const series::ValidationReport report = series::validate(series::ValidationOptions{});
  const auto csv = folder / "series_validation.csv";
  const auto json = folder / "series_validation.json";
  const auto png = folder / "series_validation.png";
  files::write_file_atomically(csv, validation_csv(report));
  files::write_file_atomically(json, validation_json(report));
  print_validation_summary(report);
  const std::string why = run_plot_script("series_validation", csv, png, {}, formats);
  if (!why.empty()) std::fprintf(stderr, "restitution: warning: %s\n", why.c_str());
  fmt::print("wrote {}, {}", csv.string(), json.string());
  if (why.empty()) {
    for (const std::string& figure : figure_file_names("series_validation", formats))
      fmt::print(", {}", (folder / figure).string());
  }
  fmt::print("\n");
  return 0;
}

int run_series_certify(int order, const std::string& file) {
  if (!file.empty()) files::check_output_file(file);  // before the work, not after
  const series::CertifiedCoefficients k = series::certify_coefficients(order);
  std::string csv = "series,k,value,certified_digits\n";
  auto rows = [&csv](const char* name, const std::vector<series::CertifiedValue>& values) {
    for (std::size_t i = 0; i < values.size(); ++i)
      csv += fmt::format("{},{},{},{}\n", name, i, values[i].value, values[i].digits);
  };
  rows("a", k.a);
  rows("b", k.b);
  rows("c", k.c);
  rows("h", k.h);
  std::string published = "source,symbol,k,published,recomputed,printed_digits,correct_digits\n";
  if (order >= 10)
    for (const auto& p : series::check_published_tables(k))
      published += fmt::format("{},{},{},{},{},{},{}\n", p.source, p.symbol, p.index, p.published,
                               number17(p.recomputed), p.digits.printed, p.digits.correct);
  if (file.empty()) {
    fmt::print("{}\n{}", csv, published);
    return 0;
  }
  const std::filesystem::path path(file);
  files::write_file_atomically(path, csv);
  const std::filesystem::path published_path =
      path.parent_path() / (path.stem().string() + "_published_check" + path.extension().string());
  files::write_file_atomically(published_path, published);
  fmt::print("wrote {} and {}\n", path.string(), published_path.string());
  return 0;
}

}  // namespace restitution::cli
