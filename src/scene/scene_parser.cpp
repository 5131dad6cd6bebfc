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
#include "scene/figure_formats.hpp"
#include "scene/scene.hpp"
#include "scene/scene_sections.hpp"
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
  for (SectionTask& s : scene.sections) find_section_kind(s.kind)->quick(s.task, points);
}

}  // namespace restitution::scene
