// SPDX-License-Identifier: BSD-3-Clause
// The scene file -> Scene values. Only this file (with toml_reader) knows TOML.
#include <fmt/core.h>
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "damping_check/recipes.hpp"
#include "restitution/errors.hpp"
#include "restitution_series_study/series_named.hpp"
#include "scene/figure_formats.hpp"
#include "scene/scene.hpp"
#include "scene/scene_approximations.hpp"
#include "scene/scene_sections.hpp"
#include "scene/section_keys.hpp"
#include "scene/section_material.hpp"
#include "scene/toml_ascii.hpp"
#include "scene/toml_reader.hpp"

namespace restitution::scene {
namespace {

using detail::TomlReader;

constexpr std::size_t kMaxNameLength = 100;  // well below the 255 bytes a file name may have

bool is_name(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '-' || c == '_';
  });
}

EndSet read_ends(TomlReader& r, EndSet fallback = EndSet::both()) {
  const auto words = r.words("ends");
  if (!words) return fallback;
  EndSet ends;
  for (const std::string& w : *words) {
    try {
      ends = ends | end_set_from_name(w);
    } catch (const InvalidInput& e) {
      r.fail("ends", e.what());
    }
  }
  if (ends.empty()) r.fail("ends", "no end requested");
  return ends;
}

series::Approximation approximation_from(const TomlReader& r, const std::string& name) {
  if (const auto kind = series::approximation_named(name)) return *kind;
  r.fail("approximations", fmt::format("unknown approximation \"{}\" (known: {})", name,
                                       fmt::join(series::evaluation_kinds(), ", ")));
}

// `law = "NAME"` (law_names()); viscoelastic Hertz when absent.
LawKind read_law(TomlReader& r) {
  const auto name = r.text("law");
  if (!name) return LawKind::viscoelastic_hertz;
  try {
    return law_from_name(*name);
  } catch (const InvalidInput& e) {
    r.fail("law", e.what());
  }
}

// The ζ values of a law other than viscoelastic Hertz: the forms and comparisons that belong to Hertz are
// refused, and a requested naive end must exist at every ζ (below the critical ζ of Tsuji and the dash-pot).
void check_law_zeta(TomlReader& r, LawKind law, EndSet ends, const std::vector<double>& zeta) {
  if (law == LawKind::viscoelastic_hertz || !ends.contains(CollisionEnd::naive)) return;
  r.check_each(
      "zeta", zeta, [law](double z) { return ContactLaw::natural(law, z).naive_end_may_exist(); },
      fmt::format("zeta < {:.17g}, where the naive end of {} exists (or ends = \"delayed-recovery\")",
                  naive_end_critical_zeta(law), law_name(law)));
}

Material read_material(TomlReader& r) {
  MaterialFields f;
  f.young_modulus_pa = r.number("young_modulus");
  f.poisson_ratio = r.number("poisson_ratio");
  f.radius_m = r.number("radius");
  if (const auto radii = r.numbers("radii")) {
    if (radii->size() != 2) r.fail("radii", "expected [R1, R2] in m");
    f.radii_m = std::array<double, 2>{(*radii)[0], (*radii)[1]};
  }
  f.density_kg_m3 = r.number("density");
  f.mass_kg = r.number("mass");
  if (const auto masses = r.numbers("masses")) {
    if (masses->size() != 2) r.fail("masses", "expected [m1, m2] in kg");
    f.masses_kg = std::array<double, 2>{(*masses)[0], (*masses)[1]};
  }
  f.dissipative_constant_s = r.number("dissipative_constant");
  if (const auto eta = r.numbers("viscosities")) {
    if (eta->size() != 2) r.fail("viscosities", "expected [eta1, eta2] in Pa s");
    f.viscosities = Viscosities{(*eta)[0], (*eta)[1]};
  }
  if (const auto problem = material_fields_problem(f)) r.fail(problem->field, problem->message);
  const Material m = material_from_fields(f);
  r.finish();
  try {
    check_material(m);
  } catch (const InvalidInput& e) {
    r.fail("", e.what());
  }
  return m;
}

class Parser {
 public:
  // A scene file received from someone else must not write outside the folder it is run from: `output` is
  // relative and never climbs (`..`); `run --out DIR` names any folder (the user's own choice).
  void check_output_folder(const std::filesystem::path& output) {
    if (output.is_absolute() || output.has_root_name() || output.has_root_directory()) {
      root_.fail("output", fmt::format("\"{}\" is absolute: a scene writes under the working directory "
                                       "(give a relative folder, or `restitution run FILE --out DIR`)",
                                       output.string()));
    }
    for (const std::filesystem::path& part : output) {
      if (part == "..") {
        root_.fail("output", fmt::format("\"{}\" climbs out with '..': a scene writes under the working "
                                         "directory (or `restitution run FILE --out DIR`)",
                                         output.string()));
      }
    }
  }

  Parser(const toml::table& root, std::string_view file_name) : root_(root, "", file_name) {}

  Scene parse() {
    scene_.file_name = std::string(root_.file_name());
    scene_.title = root_.text("title").value_or("");
    scene_.description = root_.text("description").value_or("");
    const auto output = root_.text("output");
    if (!output || output->empty()) root_.fail("output", "missing: the folder to write to");
    scene_.output = *output;
    check_output_folder(scene_.output);
    scene_.tolerance = root_.number("tolerance").value_or(SolveOptions{}.tolerance);
    if (scene_.tolerance < kMinTolerance || scene_.tolerance > kMaxTolerance) {
      root_.fail("tolerance", fmt::format("expected a value in [{:g}, {:g}]", kMinTolerance, kMaxTolerance));
    }
    if (const auto method = root_.text("method")) {
      try {
        scene_.method = method_from_name(*method);
      } catch (const InvalidInput& e) {
        root_.fail("method", e.what());
      }
    }
    if (const auto formats = root_.words("format")) {
      try {
        scene_.figure_formats = figure_formats(*formats);
      } catch (const InvalidInput& e) {
        root_.fail("format", e.what());
      }
    }
    if (const toml::table* materials = root_.table("materials")) {
      for (const auto& [key, node] : *materials) {
        const std::string path = root_.child_path("materials") + "." + std::string(key.str());
        const auto* t = node.as_table();
        if (t == nullptr)
          TomlReader(*materials, "materials", root_.file_name()).fail(key.str(), "expected a table");
        TomlReader r(*t, path, root_.file_name());
        scene_.materials.emplace(std::string(key.str()), read_material(r));
      }
    }
    each("sweep", [this](TomlReader& r) { scene_.sweeps.push_back(read_sweep(r)); });
    each("trajectory", [this](TomlReader& r) { scene_.trajectories.push_back(read_trajectory(r)); });
    each("calibration", [this](TomlReader& r) { scene_.calibrations.push_back(read_calibration(r)); });
    each("dashpot", [this](TomlReader& r) { scene_.dashpots.push_back(read_dashpot(r)); });
    // The table's sections (scene_sections.hpp), in its order: unnamed sections are numbered in it.
    for (const SectionKind& kind : section_kinds()) {
      each(kind.name, [this, &kind](TomlReader& r) {
        SectionTask section{kind.name, read_name(r, kind.name), r.line(), {}};
        section.task = kind.parse(r, SectionContext{section.name, scene_.materials, scene_.warnings});
        scene_.sections.push_back(std::move(section));
      });
    }
    root_.finish();
    return std::move(scene_);
  }

 private:
  template <typename F>
  void each(const char* key, F&& read) {
    const toml::array* list = root_.array_of_tables(key);
    if (list == nullptr) return;
    for (std::size_t i = 0; i < list->size(); ++i) {
      TomlReader r(*list->get(i)->as_table(), fmt::format("{}[{}]", key, i), root_.file_name());
      read(r);
      r.finish();
    }
  }

  std::string read_name(TomlReader& r, const char* kind) {
    std::string name = r.text("name").value_or(fmt::format("{}{}", kind, ++unnamed_));
    if (!is_name(name)) r.fail("name", "use letters, digits, '-' and '_' only (it names output files)");
    if (name.size() > kMaxNameLength) {
      r.fail("name", fmt::format("at most {} characters (it names output files), got {}", kMaxNameLength,
                                 name.size()));
    }
    if (!names_.insert(name).second) r.fail("name", fmt::format("\"{}\" is used twice", name));
    // Two tasks must not write the same file: a work-precision study also writes NAME_summary.csv.
    std::vector<std::string> stems = {name};
    if (std::string_view(kind) == "work_precision") stems.push_back(name + "_summary");
    // A fit also writes its model curves with their bands, NAME_curves.csv.
    if (std::string_view(kind) == "fit") stems.push_back(name + "_curves");
    // A damping check may write an error map NAME_<recipe>_error.csv per recipe.
    if (std::string_view(kind) == "damping_check") {
      for (damping_check::Recipe recipe : damping_check::kRecipes) {
        stems.push_back(fmt::format("{}_{}_error", name, damping_check::recipe_name(recipe)));
      }
    }
    for (const std::string& stem : stems) {
      const auto [at, inserted] = stems_.emplace(stem, fmt::format("{} \"{}\"", kind, name));
      if (!inserted) {
        r.fail("name", fmt::format("{} \"{}\" would write {}.csv, which {} writes too", kind, name, stem,
                                   at->second));
      }
    }
    return name;
  }

  // The keys every plotted task has: name, title, ends; and where it starts.
  template <typename Task>
  void read_heading(TomlReader& r, const char* kind, Task& task) {
    task.line = r.line();
    task.name = read_name(r, kind);
    task.title = r.text("title").value_or(task.name);
    task.ends = read_ends(r);
  }

  Sweep read_sweep(TomlReader& r) {
    Sweep s;
    read_heading(r, "sweep", s);
    s.note = r.text("note").value_or("");
    if (const auto q = r.words("quantities")) {
      s.quantities = {false, false, false, false};
      for (const std::string& w : *q) {
        if (w == "eps")
          s.quantities.eps = true;
        else if (w == "one_minus_eps")
          s.quantities.one_minus_eps = true;
        else if (w == "duration")
          s.quantities.duration = true;
        else if (w == "max_compression")
          s.quantities.max_compression = true;
        else
          r.fail("quantities",
                 fmt::format("unknown quantity \"{}\" (eps, one_minus_eps, duration, max_compression)", w));
      }
    }
    s.law = read_law(r);
    const auto zeta = r.numbers("zeta");
    const auto velocity = r.numbers("velocity");
    if (velocity && !has_dissipative_constant(s.law)) {
      r.fail("velocity",
             fmt::format("a sweep over impact speeds is for law \"viscoelastic-hertz\"; law \"{}\" "
                         "sweeps zeta (`restitution sweep --law {} --stiffness ...` sweeps its "
                         "impact speeds)",
                         law_name(s.law), law_name(s.law)));
    }
    s.beta = r.number("beta");
    s.material = detail::read_optional_material(r, scene_.materials);
    detail::require_dissipation(r, scene_.materials, s.material, "a sweep");
    s.characteristic_velocity_m_s = r.number("characteristic_velocity");
    const int subjects = static_cast<int>(s.beta.has_value()) + static_cast<int>(s.material.has_value()) +
                         static_cast<int>(s.characteristic_velocity_m_s.has_value());
    if (zeta) {
      if (velocity || subjects > 0)
        r.fail("zeta", "give zeta alone, or velocity with one of beta, material, characteristic_velocity");
      detail::check_zeta(r, *zeta);
      check_law_zeta(r, s.law, s.ends, *zeta);
      s.zeta = *zeta;
    } else {
      if (!velocity) r.fail("", "give zeta, or velocity with one of beta, material, characteristic_velocity");
      if (subjects != 1) r.fail("velocity", "needs exactly one of beta, material, characteristic_velocity");
      detail::check_positive(r, "velocity", *velocity);
      s.velocity_m_s = *velocity;
      if (s.beta && *s.beta < 0.0) r.fail("beta", "expected a value >= 0");
      if (s.characteristic_velocity_m_s && *s.characteristic_velocity_m_s <= 0.0) {
        r.fail("characteristic_velocity", "expected a value > 0 (m/s)");
      }
    }
    if (const auto names = r.words("approximations")) {
      for (const std::string& name : *names) s.approximations.push_back(approximation_from(r, name));
    }
    s.asymptotics = r.flag("asymptotics").value_or(false);
    const bool compare_series = r.flag("compare_series").value_or(false);
    if (s.law != LawKind::viscoelastic_hertz) {
      const char* hertz_only = !s.approximations.empty() ? "approximations"
                               : s.asymptotics           ? "asymptotics"
                               : compare_series          ? "compare_series"
                                                         : nullptr;
      if (hertz_only != nullptr) {
        r.fail(hertz_only, fmt::format("the series and asymptotics are those of viscoelastic Hertz, not of "
                                       "law \"{}\"",
                                       law_name(s.law)));
      }
    }
    if (compare_series) {
      if (s.ends.contains(CollisionEnd::naive))
        s.approximations.push_back(series::Approximation::naive_series);
      if (s.ends.contains(CollisionEnd::delayed_recovery))
        s.approximations.push_back(series::Approximation::delayed_recovery_series);
    }
    if (const toml::table* e = r.table("empirical")) {
      TomlReader er(*e, r.child_path("empirical"), r.file_name());
      EmpiricalLaw law;
      law.coefficient = er.number("coefficient").value_or(0.0);
      law.exponent = er.number("exponent").value_or(0.0);
      law.velocity_unit_m_s = er.number("velocity_unit").value_or(1.0);
      er.finish();
      if (law.coefficient <= 0.0) er.fail("coefficient", "expected a value > 0");
      if (law.velocity_unit_m_s <= 0.0) er.fail("velocity_unit", "expected a value > 0 (m/s)");
      if (s.velocity_m_s.empty()) r.fail("empirical", "needs a sweep over velocity");
      s.empirical = law;
    }
    if (const toml::table* f = r.table("fit")) {
      TomlReader fr(*f, r.child_path("fit"), r.file_name());
      PowerLawFitRequest fit;
      fit.zeta_min = fr.number("zeta_min").value_or(0.0);
      fr.finish();
      if (fit.zeta_min <= 0.0) fr.fail("zeta_min", "expected a value > 0");
      s.fit = fit;
    }
    const std::string axes = r.text("axes").value_or("linear");
    if (axes == "linear")
      s.axes = Axes::linear;
    else if (axes == "log-log")
      s.axes = Axes::log_log;
    else if (axes == "log-x")
      s.axes = Axes::log_x;
    else
      r.fail("axes", R"(expected "linear", "log-x" or "log-log")");
    return s;
  }

  Trajectory read_trajectory(TomlReader& r) {
    Trajectory t;
    read_heading(r, "trajectory", t);
    t.law = read_law(r);
    t.zeta = r.number("zeta");
    t.velocity_m_s = r.number("velocity");
    t.beta = r.number("beta");
    t.material = detail::read_optional_material(r, scene_.materials);
    detail::require_dissipation(r, scene_.materials, t.material, "a trajectory");
    if (t.zeta) {
      if (t.velocity_m_s || t.beta || t.material)
        r.fail("zeta", "give zeta alone, or velocity with beta or material");
      detail::check_zeta(r, {*t.zeta});
      check_law_zeta(r, t.law, t.ends, {*t.zeta});
    } else {
      if (!has_dissipative_constant(t.law))
        r.fail("law", "a trajectory of a law other than viscoelastic-hertz takes zeta (its natural form)");
      if (!t.velocity_m_s) r.fail("", "give zeta, or velocity with beta or material");
      if (t.beta.has_value() == t.material.has_value())
        r.fail("velocity", "needs exactly one of beta, material");
      detail::check_positive(r, "velocity", {*t.velocity_m_s});
      if (t.beta && *t.beta < 0.0) r.fail("beta", "expected a value >= 0");
    }
    return t;
  }

  CalibrationTask read_calibration(TomlReader& r) {
    CalibrationTask c;
    c.line = r.line();
    c.name = read_name(r, "calibration");
    c.law = read_law(r);
    const auto eps = r.number("eps");
    const auto velocity = r.number("velocity");
    if (!eps) r.fail("eps", "missing");
    if (!velocity) r.fail("velocity", "missing (m/s)");
    detail::check_eps(r, "eps", {*eps});
    detail::check_positive(r, "velocity", {*velocity});
    c.eps = *eps;
    c.eps_line = r.line_of("eps");
    c.velocity_m_s = *velocity;
    c.end = detail::read_end(r);
    c.material = detail::read_optional_material(r, scene_.materials);
    if (c.material && !has_dissipative_constant(c.law))
      r.fail("material", "a material gives the dissipative constant A of law \"viscoelastic-hertz\" only");
    return c;
  }

  DashpotCheck read_dashpot(TomlReader& r) {
    DashpotCheck d;
    read_heading(r, "dashpot", d);
    const auto ratios = r.numbers("damping_ratio");
    if (!ratios) r.fail("damping_ratio", "missing");
    detail::check_positive(r, "damping_ratio", *ratios);
    d.damping_ratio = *ratios;
    return d;
  }

  TomlReader root_;
  Scene scene_;
  std::set<std::string> names_;
  std::map<std::string, std::string> stems_;  // output file stem -> the task that writes it
  int unnamed_ = 0;
};

}  // namespace

Scene parse_scene(std::string_view toml_text, std::string_view file_name) {
  const std::string ascii_text = ascii_toml_text(toml_text, file_name);
  toml::table root;
  try {
    root = toml::parse(ascii_text, file_name);
  } catch (const toml::parse_error& e) {
    throw InvalidInput(fmt::format("{}:{}: {}", file_name, e.source().begin.line, e.description()));
  }
  detail::refuse_underflowing_floats(root, ascii_text, file_name);
  return Parser(root, file_name).parse();
}

Scene load_scene(const std::filesystem::path& path) {
  // A folder opens as an empty stream on Linux: say what it is rather than report missing keys.
  if (std::filesystem::is_directory(path)) {
    throw InvalidInput(fmt::format("cannot read scene file '{}': it is a folder", path.string()));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InvalidInput(fmt::format("cannot read scene file '{}'", path.string()));
  std::stringstream buffer;
  buffer << in.rdbuf();
  return parse_scene(buffer.str(), path.string());
}

void thin_values(std::vector<double>& values, std::size_t points) {
  if (points < 2 || values.size() <= points) return;
  std::vector<double> kept;
  for (std::size_t i = 0; i < points; ++i) kept.push_back(values[i * (values.size() - 1) / (points - 1)]);
  values = kept;
}

void make_quick(Scene& scene, std::size_t points) {
  for (Sweep& s : scene.sweeps) {
    thin_values(s.zeta, points);
    thin_values(s.velocity_m_s, points);
  }
  for (DashpotCheck& d : scene.dashpots) thin_values(d.damping_ratio, points);
  for (SectionTask& s : scene.sections) find_section_kind(s.kind)->quick(s.task, points);
}

}  // namespace restitution::scene
