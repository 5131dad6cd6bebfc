// SPDX-License-Identifier: BSD-3-Clause
#include "cli/scene/scene_outputs.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "cli/common/build_json.hpp"
#include "cli/common/json_writer.hpp"
#include "cli/common/plot_script.hpp"
#include "cli/common/result_json.hpp"
#include "cli/common/stop_signals.hpp"
#include "cli/scene/scene_section_writers.hpp"
#include "cli/scene/scene_tables.hpp"
#include "cli/scene/scene_text.hpp"
#include "files/output_files.hpp"
#include "restitution/series.hpp"
#include "restitution/units.hpp"
#include "scene/figure_formats.hpp"
#include "sweep/physical_columns.hpp"

namespace restitution::cli {
namespace {

namespace fs = std::filesystem;

std::string g(double v) {
  return std::isfinite(v) ? fmt::format("{:.10g}", v) : "—";
}

std::string join(const std::vector<std::string>& items, const char* separator = ",") {
  std::string out;
  for (const auto& item : items) {
    if (!out.empty()) out += separator;
    out += item;
  }
  return out;
}

// A markdown table of up to `limit` rows spread evenly over the table (first and last included).
std::string markdown_rows(const Table& t, const std::vector<std::string>& columns, std::size_t limit) {
  std::string out = "| " + join(columns, " | ") + " |";
  out += "\n|";
  for (std::size_t i = 0; i < columns.size(); ++i) out += "---|";
  out += "\n";
  const std::size_t n = t.rows.size();
  const std::size_t shown = std::min(n, limit);
  for (std::size_t k = 0; k < shown; ++k) {
    const std::size_t i = shown == 1 ? 0 : k * (n - 1) / (shown - 1);
    std::vector<std::string> cells;
    cells.reserve(columns.size());
    for (const auto& c : columns) cells.push_back(g(t.rows[i][t.column(c)]));
    out += "| " + join(cells, " | ") + " |\n";
  }
  if (shown < n) {
    out += fmt::format(
        "\n{} of {} rows shown, spread evenly from the first to the last; every row is in the CSV.\n", shown,
        n);
  }
  return out;
}

class SceneWriter : private SectionOutput {
 public:
  SceneWriter(const scene::Scene& s, const scene::SceneResults& r, fs::path folder)
      : scene_(s), results_(r), folder_(std::move(folder)) {}

  WrittenOutputs write(double seconds) {
    out_.warnings = scene_.warnings;
    report_ = fmt::format("# {}\n\n", scene_.title.empty() ? scene_.file_name : scene_.title);
    json_.begin_object();
    json_.field("scene", scene_.file_name).field("title", scene_.title);
    json_.field("tolerance", scene_.tolerance).field("method", method_name(scene_.method));
    // Sections in the order the scene file lists them, the planner's by their member functions, the
    // table's by their rows; then the calibrations and the rows written together.
    std::vector<SectionEntry> order;
    collect(order, scene_.sweeps, &SceneWriter::sweep);
    collect(order, scene_.trajectories, &SceneWriter::trajectory);
    collect(order, scene_.dashpots, &SceneWriter::dashpot);
    for (std::size_t i = 0; i < scene_.sections.size(); ++i) {
      if (find_section_writer(scene_.sections[i].kind)->write != nullptr)
        order.push_back({scene_.sections[i].line, &SceneWriter::section, i});
    }
    std::stable_sort(order.begin(), order.end(),
                     [](const SectionEntry& a, const SectionEntry& b) { return a.line < b.line; });
    for (const SectionEntry& entry : order) (this->*entry.write)(entry.index);
    calibrations();
    sections_together();
    footer(seconds);
    write_file("summary.json", finish_json_document(json_) + "\n");
    write_file("report.md", report_);  // last: its presence says the folder is complete
    return std::move(out_);
  }

 private:
  using MemberWriter = void (SceneWriter::*)(std::size_t);
  struct SectionEntry {
    int line = 0;  // of the section's header in the scene file
    MemberWriter write = nullptr;
    std::size_t index = 0;
  };
  template <class Section>
  static void collect(std::vector<SectionEntry>& order, const std::vector<Section>& sections,
                      MemberWriter write) {
    for (std::size_t i = 0; i < sections.size(); ++i) order.push_back({sections[i].line, write, i});
  }

  void write_file(const std::string& name, const std::string& content) {
    throw_if_interrupted();  // Ctrl-C stops the run here, between files, never inside one
    files::write_file_atomically(folder_ / name, content);
    out_.files.push_back(name);
  }

  // A section of the table of kinds (scene/scene_sections.hpp), written by its row of section_writers().
  void section(std::size_t i) {
    const scene::SectionTask& s = scene_.sections[i];
    find_section_writer(s.kind)->write(scene_, s, results_.sections[i], *this);
  }
  // The sections whose rows share a write_together function, each function once with all of them.
  void sections_together() {
    std::vector<decltype(cli::SectionWriter::write_together)> done;
    for (const cli::SectionWriter& writer : section_writers()) {
      const auto together = writer.write_together;
      if (together == nullptr || std::find(done.begin(), done.end(), together) != done.end()) continue;
      done.push_back(together);
      std::vector<SectionResult> sections;
      for (std::size_t i = 0; i < scene_.sections.size(); ++i) {
        if (find_section_writer(scene_.sections[i].kind)->write_together == together)
          sections.push_back({&scene_.sections[i], &results_.sections[i]});
      }
      together(scene_, sections, *this);
    }
  }
  void file(const std::string& name, const std::string& content) override { write_file(name, content); }
  const fs::path& folder() const override { return folder_; }
  void written(const std::vector<std::string>& names) override {
    out_.files.insert(out_.files.end(), names.begin(), names.end());
  }
  void report(const std::string& markdown) override { report_ += markdown; }
  JsonWriter& summary() override { return json_; }
  void warn(const std::string& line) override { out_.warnings.push_back(line); }

  // Runs a plot script; returns the markdown image link, or a note saying why there is no plot.
  std::string plot(const std::string& script, const std::string& name,
                   const std::vector<std::string>& arguments) override {
    const std::vector<std::string>& formats = scene_.figure_formats;
    const std::string why =
        run_plot_script(script, folder_ / (name + ".csv"), folder_ / (name + ".png"), arguments, formats);
    if (!why.empty()) {
      out_.warnings.push_back(fmt::format("{}: {}", name, why));
      return fmt::format("*({}; the data are in `{}.csv`)*\n\n", why, name);
    }
    for (const std::string& figure : figure_file_names(name, formats)) out_.files.push_back(figure);
    return fmt::format("![{}]({}.{})\n\n", name, name, scene::linked_figure_format(formats));
  }

  void sweep(std::size_t i) {
    const scene::Sweep& s = scene_.sweeps[i];
    const scene::SweepExtras& extras = results_.sweeps[i];
    const Table t = sweep_table(scene_, results_, i);
    write_file(s.name + ".csv", t.csv());
    const bool physical = !s.velocity_m_s.empty();
    const std::string x = physical ? "velocity_m_s" : "zeta";
    std::vector<std::string> eps_columns;
    for (const CollisionEnd e : s.ends.members()) {
      if (s.quantities.eps) eps_columns.push_back(std::string(end_key(e)) + "_eps");
    }
    std::vector<std::string> dashed;
    std::vector<std::string> differences;
    for (const auto& a : extras.approximations) {
      dashed.push_back(a.label + "_eps");
      differences.push_back(a.label + "_rel_diff");
    }
    if (s.empirical) dashed.emplace_back("empirical_eps");
    report_ += fmt::format("## {}\n\n", s.title);
    if (!eps_columns.empty()) {
      // No title in the figure: the section's heading carries it. x: scripts/plots/style.py names it.
      std::vector<std::string> args = {"--x", x, "--y", join(eps_columns), "--ylabel", R"($\varepsilon$)"};
      if (!dashed.empty()) args.insert(args.end(), {"--dashed", join(dashed)});
      if (!differences.empty()) args.insert(args.end(), {"--error", join(differences)});
      if (s.axes != scene::Axes::linear) args.insert(args.end(), {"--xscale", "log"});
      if (s.axes == scene::Axes::log_log) args.insert(args.end(), {"--yscale", "log"});
      report_ += plot("scene_xy", s.name, args);
    }
    report_ += describe_sweep(s, t);
    if (!s.note.empty()) report_ += s.note + "\n\n";
    std::vector<std::string> shown = {"zeta"};
    if (physical) shown.emplace_back("velocity_m_s");
    shown.insert(shown.end(), eps_columns.begin(), eps_columns.end());
    for (std::size_t k = 0; k < differences.size(); ++k) {  // each approximation with its difference
      shown.push_back(dashed[k]);
      shown.push_back(differences[k]);
    }
    if (s.empirical) shown.emplace_back("empirical_eps");
    for (const CollisionEnd e : s.ends.members()) {
      const std::string c = duration_column(e);
      if (std::find(t.columns.begin(), t.columns.end(), c) != t.columns.end()) shown.push_back(c);
    }
    if (std::find(t.columns.begin(), t.columns.end(), "max_compression_m") != t.columns.end()) {
      shown.emplace_back("max_compression_m");
    }
    report_ += markdown_rows(t, shown, 9) + "\n";
    for (const auto& f : extras.fits) {
      report_ +=
          fmt::format("Power-law fit at the {} end: eps ≈ {} · zeta^({} ± {}) over {} points.\n\n",
                      end_name(f.end), g(f.prefactor), g(f.exponent), g(f.exponent_uncertainty), f.points);
    }
    for (const auto& a : extras.approximations) {
      report_ += fmt::format("* `{}`: {}; {}\n", a.label, approximation_source(a),
                             comparison_text(a.comparison, t.rows.size()));
    }
    if (!extras.approximations.empty()) report_ += "\n";
    std::vector<std::string> notes;
    for (const auto& f : extras.fit_shortfalls) notes.push_back(fit_shortfall_text(f));
    for (const auto& n : notes) report_ += "*" + n + "*\n\n";

    json_.key(s.name).begin_object();
    json_.field("kind", "sweep")
        .field("points", static_cast<long>(t.rows.size()))
        .field("table", s.name + ".csv");
    json_.key("notes").begin_array();
    for (const auto& n : notes) json_.value(n);
    json_.end_array();
    json_.key("fits").begin_array();
    for (const auto& f : extras.fits) {
      json_.begin_object();
      json_.field("end", end_name(f.end)).field("prefactor", f.prefactor).field("exponent", f.exponent);
      json_.field("exponent_uncertainty", f.exponent_uncertainty)
          .field("points", static_cast<long>(f.points));
      json_.end_object();
    }
    json_.end_array();
    if (extras.empirical_deviation) empirical_summary(s, *extras.empirical_deviation);
    json_.end_object();
  }

  std::string describe_sweep(const scene::Sweep& s, const Table& t) {
    std::vector<std::string> names;
    for (const CollisionEnd e : s.ends.members()) names.emplace_back(end_name(e));
    const std::string ends = join(names, " and ");
    const auto& points = results_.plan.sweeps[&s - scene_.sweeps.data()];
    std::string what;
    if (s.velocity_m_s.empty()) {
      what = fmt::format("ε at the {} end for {} values of ζ from {} to {}", ends, t.rows.size(),
                         g(s.zeta.front()), g(s.zeta.back()));
      if (s.law != LawKind::viscoelastic_hertz) {
        what += fmt::format(" (law {}: x'' + ζ x^{} x' + x^{} = 0)", law_name(s.law),
                            g(law_exponents(s.law).damping), g(law_exponents(s.law).elastic));
      }
    } else {
      std::string subject;
      if (s.beta) subject = fmt::format("β = {} s^(1/5) m^(-1/5)", g(*s.beta));
      if (s.characteristic_velocity_m_s) {
        subject = fmt::format(
            "the 1999 paper's characteristic velocity g* = {} m/s, i.e. β = (g*)^(-1/5)/C1 = {} "
            "s^(1/5) m^(-1/5) (C1 = {})",
            g(*s.characteristic_velocity_m_s), g(*points.front().beta), g(series::c1_closed_form()));
      }
      if (s.material) {
        const MaterialConstants c = material_constants(scene_.materials.at(*s.material));
        subject = fmt::format(
            "material `{}`: R_eff = {} m, m_eff = {} kg, k = ρ/m_eff = {} s^-2 m^-1/2, A = {} s, "
            "β = {} s^(1/5) m^(-1/5), 1999 g* = {} m/s",
            *s.material, g(c.elastic.effective_radius_m), g(c.elastic.effective_mass_kg), g(c.hertz.k),
            g(c.dissipative_constant_s), g(c.hertz.beta), g(characteristic_velocity_m_s(c.hertz.beta)));
      }
      what = fmt::format("ε at the {} end for {} impact speeds from {} to {} m/s with {}; ζ = β v^(1/5)",
                         ends, t.rows.size(), g(s.velocity_m_s.front()), g(s.velocity_m_s.back()), subject);
    }
    return fmt::format(
        "Computed: {}. Table `{}.csv` (times τ and compressions x in natural units, x'(0) = 1; columns "
        "ending "
        "in _s and _m are seconds and metres).\n\n",
        what, s.name);
  }

  void empirical_summary(const scene::Sweep& s, const scene::EmpiricalDeviation& d) {
    report_ += fmt::format(
        "Empirical law ε = {} (v / {} m/s)^{}: where it is below 1, the computed ε at the {} end deviates "
        "from "
        "it by at most {:.1f}% (at v = {} m/s).\n\n",
        g(s.empirical->coefficient), g(s.empirical->velocity_unit_m_s), g(s.empirical->exponent),
        end_name(d.end), 100.0 * d.max_relative_deviation, g(d.at_velocity_m_s));
    json_.field("max_relative_deviation_from_empirical", d.max_relative_deviation)
        .field("at_velocity_m_s", d.at_velocity_m_s);
  }

  void trajectory(std::size_t i) {
    const scene::Trajectory& tr = scene_.trajectories[i];
    const scene::PlannedPoint& p = results_.plan.trajectories[i];
    const CollisionResult& r = *scene::result_of(results_, p);
    const Table t = trajectory_table(results_, i);
    write_file(tr.name + ".csv", t.csv());
    std::vector<std::string> marks;
    for (const CollisionEnd e : tr.ends.members()) {
      const auto& end = r[e];
      marks.push_back(fmt::format("{}:{:.17g}", end_name(e), end->tau));
    }
    report_ += fmt::format("## {}\n\n", tr.title);
    report_ += plot("scene_trajectory", tr.name, {"--ends", join(marks)});
    report_ += fmt::format(
        "Computed: the trajectory x, x', x'' of one {} collision at ζ = {} ({} points in `{}.csv`, natural "
        "units). "
        "Maximal compression x = {} at τ = {}.\n\n",
        law_name(tr.law), g(p.parameter), t.rows.size(), tr.name, g(r.max_compression.x),
        g(r.max_compression.tau));
    report_ += "| end | τ_c | ε | x(τ_c) |\n|---|---|---|---|\n";
    json_.key(tr.name).begin_object();
    json_.field("kind", "trajectory");
    if (tr.law != LawKind::viscoelastic_hertz) json_.field("law", law_name(tr.law));
    json_.field("zeta", p.parameter).field("points", static_cast<long>(t.rows.size()));
    for (const CollisionEnd e : tr.ends.members()) {
      const EndResult& end = *r[e];
      report_ += fmt::format("| {} | {} | {} | {} |\n", end_name(e), g(end.tau), g(end.eps), g(end.x));
      json_.key(end_key(e)).begin_object();
      json_.field("tau", end.tau).field("eps", end.eps).field("x", end.x);
      json_.end_object();
    }
    json_.end_object();
    report_ +=
        "\nThe delayed-recovery end (force zero, ζx' + x = 0) comes first; integrating on to the naive end "
        "(x = 0) lets the formula's attractive force act (x'' > 0), the 2008 paper's Fig. 3.\n\n";
  }

  void dashpot(std::size_t i) {
    const scene::DashpotCheck& d = scene_.dashpots[i];
    const Table t = dashpot_table(scene_, results_, i);
    write_file(d.name + ".csv", t.csv());
    report_ += fmt::format("## {}\n\n", d.title);
    std::vector<std::string> numeric;
    std::vector<std::string> exact;
    std::vector<std::string> errors;
    for (const CollisionEnd e : d.ends.members()) {
      numeric.push_back(std::string(end_key(e)) + "_eps");
      exact.push_back(std::string(end_key(e)) + "_eps_exact");
      errors.push_back(std::string(end_key(e)) + "_relative_error");
    }
    report_ += plot("scene_xy", d.name,
                    {"--x", "damping_ratio", "--points", join(numeric), "--y", join(exact), "--error",
                     join(errors), "--error-label",
                     R"($|\varepsilon - \varepsilon_\mathrm{exact}| / \min(\varepsilon, 1 - \varepsilon)$)",
                     "--ylabel", R"($\varepsilon$)", "--yscale", "log"});
    report_ += fmt::format(
        "Computed: the linear dash-pot x'' + 2r x' + x = 0 at {} damping ratios against its closed forms "
        "(ε = exp(-r τ_c); naive ωτ_c = π for r < 1, delayed recovery tan ωτ_c = 2rω/(2r²-1)). The error is "
        "|ε - ε_exact| / min(ε_exact, 1 - ε_exact), which the tolerance {} bounds.\n\n",
        t.rows.size(), g(scene_.tolerance));
    json_.key(d.name).begin_object();
    json_.field("kind", "dashpot");
    for (const CollisionEnd e : d.ends.members()) {
      const std::string c = std::string(end_key(e)) + "_relative_error";  // the CSV column
      const double worst = results_.dashpots[i].max_relative_error[e];
      report_ += fmt::format("* largest {}: {:.3g}\n", c, worst);
      json_.field("max_" + c, worst);
    }
    json_.end_object();
    report_ += "\n";
  }

  void calibrations() {
    if (scene_.calibrations.empty()) return;
    report_ +=
        "## Calibration\n\n"
        "β from a measured ε at one impact speed (root finding on ζ with the solver); A = β / ((3/2) "
        "k^(2/5)) "
        "for a material; the 1999 paper's g* = (C1 β)^(-5).\n\n"
        "| name | ε | v [m/s] | end | ζ | β [s^(1/5) m^(-1/5)] | ε(ζ) re-solved | g* [m/s] | A [s] |\n"
        "|---|---|---|---|---|---|---|---|---|\n";
    json_.key("calibrations").begin_array();
    for (std::size_t i = 0; i < scene_.calibrations.size(); ++i) {
      const scene::CalibrationTask& task = scene_.calibrations[i];
      const Calibration& c = results_.calibrations[i].calibration;
      const bool hertz = task.law == LawKind::viscoelastic_hertz;
      const std::string name = hertz ? task.name : fmt::format("{} ({})", task.name, law_name(task.law));
      report_ += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", name, g(task.eps),
                             g(task.velocity_m_s), end_name(task.end), g(c.zeta), hertz ? g(c.beta) : "—",
                             g(c.eps_at_zeta), hertz ? g(c.characteristic_velocity_m_s) : "—",
                             c.dissipative_constant_s ? g(*c.dissipative_constant_s) : "—");
      json_.begin_object();
      json_.field("name", task.name).field("eps", task.eps).field("velocity_m_s", task.velocity_m_s);
      if (!hertz) json_.field("law", law_name(task.law)).field(parameter_key(task.law), c.parameter);
      json_.field("end", end_name(task.end)).field("zeta", c.zeta);
      if (hertz) json_.field("beta", c.beta);
      json_.field("eps_at_zeta", c.eps_at_zeta);
      if (hertz) json_.field("characteristic_velocity_m_s", c.characteristic_velocity_m_s);
      if (c.dissipative_constant_s) json_.field("dissipative_constant_s", *c.dissipative_constant_s);
      json_.end_object();
    }
    json_.end_array();
    report_ += "\n";
  }

  void footer(double seconds) {
    const SolverStats& s = results_.total;
    const std::size_t distinct = results_.plan.jobs.size();
    const std::string elsewhere = own_collisions_text(scene_);
    // A scene of [[gas]] or [[oblique]] sections alone integrates nothing of the shared plan: the report says
    // so rather than "0 distinct collisions integrated".
    const std::string work =
        results_.collisions == 0 && !elsewhere.empty()
            ? fmt::format("no collision of the shared plan integrated ({}), in {:.2f} s", elsewhere, seconds)
            : fmt::format(
                  "{} distinct collisions integrated once each (every output that needs a collision shares "
                  "its solve) plus {} for calibrations, in {:.2f} s; tolerance {} on ε relative to "
                  "min(ε, 1 - ε), method {}; {} steps, {} right-hand-side evaluations in total{}",
                  distinct, results_.collisions - distinct, seconds, g(scene_.tolerance),
                  method_name(scene_.method), s.steps, s.rhs_evaluations,
                  elsewhere.empty() ? "" : " (" + elsewhere + ")");
    report_ += fmt::format("## How this was computed\n\nScene `{}`; {}. {}\n", scene_.file_name, work,
                           scene_.description.empty() ? "" : "\n\n" + scene_.description + "\n");
    // The code that computed the numbers, as summary.json names it (docs/release.md).
    report_ += fmt::format("\nComputed by {}.\n", build_description());
    json_.field("collisions", static_cast<long>(results_.collisions));
    json_.field("distinct_collisions", static_cast<long>(results_.plan.jobs.size()));
    json_.field("seconds", seconds);
    json_.key("stats").begin_object();
    json_.field("steps", s.steps).field("rhs_evaluations", s.rhs_evaluations);
    json_.field("jacobian_evaluations", s.jacobian_evaluations).field("root_evaluations", s.root_evaluations);
    json_.end_object();
  }

  const scene::Scene& scene_;
  const scene::SceneResults& results_;
  fs::path folder_;
  std::string report_;
  JsonWriter json_;
  WrittenOutputs out_;
};

}  // namespace

WrittenOutputs write_scene_outputs(const scene::Scene& scene, const scene::SceneResults& results,
                                   const fs::path& folder, double seconds) {
  files::check_output_folder(folder);
  // A write that fails half-way must not leave a folder that looks like a result (item 11 of issue 12).
  const bool existed = fs::exists(folder);
  // The report and summary of an earlier run would describe files this run replaces: gone until the new ones
  // are written (the summary's numbers beside the new tables would read as this run's), so that a run that
  // stops half-way leaves no folder that looks complete.
  std::error_code ignored;
  if (existed) {
    for (const char* name : {"report.md", "summary.json"}) fs::remove(folder / name, ignored);
  }
  try {
    return SceneWriter(scene, results, folder).write(seconds);
  } catch (...) {
    if (!existed) fs::remove_all(folder, ignored);
    throw;
  }
}

}  // namespace restitution::cli
