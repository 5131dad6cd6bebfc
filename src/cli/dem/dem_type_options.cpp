// SPDX-License-Identifier: BSD-3-Clause
#include "cli/dem/dem_type_options.hpp"

#include <fmt/core.h>

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

#include "cli/common/deprecated_alias.hpp"
#include "cli/common/range_option.hpp"
#include "dem/particle_types.hpp"
#include "restitution/errors.hpp"

namespace restitution::cli {
namespace {

// The numbers of a comma-separated list (empty text: none).
std::vector<double> numbers(const std::string& text, const char* option) {
  std::vector<double> out;
  if (text.empty()) return out;
  std::stringstream items(text);
  for (std::string item; std::getline(items, item, ',');) {
    char* end = nullptr;
    const double x = std::strtod(item.c_str(), &end);
    if (item.empty() || end != item.c_str() + item.size() || !std::isfinite(x)) {
      throw InvalidInput(fmt::format("{} expects a number, got '{}'", option, item));
    }
    out.push_back(x);
  }
  if (text.back() == ',') throw InvalidInput(fmt::format("{}: empty value after the last comma", option));
  return out;
}

std::optional<double> single(const std::string& text, const char* option) {
  const std::vector<double> values = numbers(text, option);
  if (values.empty()) return std::nullopt;
  if (values.size() > 1) {
    throw InvalidInput(fmt::format("{} has {} values for 1 radius: give one value or one per radius", option,
                                   values.size()));
  }
  return values[0];
}

// The codes that take several atom types, for the help texts.
std::string polydisperse_codes() {
  return dem::code_list(", ", [](const dem::CodeEntry& e) { return e.polydisperse != nullptr; });
}

// An option taking one number or a comma-separated list.
void add_list_option(CLI::App& command, const std::string& name, std::string& target, const std::string& help,
                     const char* type_name = "FLOAT[,...]") {
  command.add_option(name, target, help)->type_name(type_name);
}

// --radius-range RMIN:RMAX:N, or the old RMIN,RMAX with --classes N.
dem::SizeClasses size_classes(const DemTypeOptions& o) {
  if (o.radius_range.find(':') != std::string::npos) {
    if (o.classes)
      throw InvalidInput("--radius-range RMIN:RMAX:N gives the number of classes: drop --classes");
    const RangeText range =
        parse_range(o.radius_range, "--radius-range", "m, N log-spaced size classes", 1, 100);
    return dem::log_size_classes(range.from, range.to, static_cast<int>(range.count));
  }
  const std::vector<double> range = numbers(o.radius_range, "--radius-range");
  if (range.size() != 2 || !o.classes) {
    throw InvalidInput(
        "a size range needs --radius-range RMIN:RMAX:N (or the old RMIN,RMAX with --classes N)");
  }
  return dem::log_size_classes(range[0], range[1], *o.classes);
}

}  // namespace

void add_dem_type_options(CLI::App& command, DemTypeOptions& o) {
  add_list_option(command, "--young-modulus", o.young_modulus,
                  "material: Young's modulus Y in Pa; Y1,Y2,...: one per --radius");
  add_list_option(command, "--poisson-ratio", o.poisson_ratio,
                  "material: Poisson ratio in (-1, 0.5); nu1,nu2,...: one per --radius");
  add_list_option(command, "--radius", o.radius,
                  "material: sphere radius in m (both spheres unless --radius2); R1,R2,...: atom types 1, 2, "
                  "... (" +
                      polydisperse_codes() + ")");
  command.add_option("--radius2", o.radius2, "material: radius of the second sphere in m");
  add_list_option(command, "--density", o.density,
                  "material: density in kg/m^3 (gives the masses); d1,d2,...: one per --radius");
  command.add_option("--mass", o.mass, "material: sphere mass in kg (instead of --density)");
  command.add_option("--mass2", o.mass2, "material: mass of the second sphere in kg");
  add_list_option(
      command, "--radius-range", o.radius_range,
      "RMIN:RMAX:N, RMIN and RMAX in m: a size range binned into N (1..100) log-spaced atom types (" +
          polydisperse_codes() + "), with the worst eps error the binning causes",
      "RMIN:RMAX:N");
  deprecate_old_form({command.add_option("--classes", o.classes)}, "--radius-range RMIN,RMAX --classes N",
                     "--radius-range RMIN:RMAX:N");
}

bool several_types(const DemTypeOptions& o) {
  return o.radius.find(',') != std::string::npos || !o.radius_range.empty() || o.classes.has_value();
}

MaterialOptions one_pair_material(const DemTypeOptions& o) {
  MaterialOptions m;
  m.radius = single(o.radius, "--radius");
  m.density = single(o.density, "--density");
  m.young_modulus = single(o.young_modulus, "--young-modulus");
  m.poisson_ratio = single(o.poisson_ratio, "--poisson-ratio");
  m.radius2 = o.radius2;
  m.mass = o.mass;
  m.mass2 = o.mass2;
  return m;
}

void set_types(const DemTypeOptions& o, dem::PolydisperseRequest& request) {
  if (o.radius2 || o.mass || o.mass2) {
    throw InvalidInput(
        "several atom types take --density (one or one per type), not --radius2, --mass or --mass2");
  }
  if (o.young_modulus.empty() || o.poisson_ratio.empty() || o.density.empty()) {
    throw InvalidInput("several atom types need --young-modulus, --poisson-ratio and --density");
  }
  std::vector<double> radii;
  if (!o.radius_range.empty() || o.classes) {
    if (!o.radius.empty()) throw InvalidInput("give either --radius or --radius-range, not both");
    request.classes = size_classes(o);
    radii = request.classes->radii_m;
  } else {
    radii = numbers(o.radius, "--radius");
  }
  request.types =
      dem::particle_types(radii, numbers(o.density, "--density"), numbers(o.young_modulus, "--young-modulus"),
                          numbers(o.poisson_ratio, "--poisson-ratio"));
}

}  // namespace restitution::cli
