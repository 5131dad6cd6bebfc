// SPDX-License-Identifier: BSD-3-Clause
// The table of engines: adding one is its folder plus an entry here and its include (docs/design.md,
// "Engines").
#include "solver/engine_registry.hpp"

#include <fmt/core.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cvode/cvode_engine.hpp"
#include "restitution/errors.hpp"
#include "taylor/taylor_engine.hpp"

namespace restitution {
namespace {

struct Entry {
  EngineInfo info;
  std::vector<Method> methods;  // the methods it computes
  std::unique_ptr<Engine> (*make)();
};

template <typename E>
std::unique_ptr<Engine> make_engine() {
  return std::make_unique<E>();
}

const std::vector<Entry>& entries() {
  static const std::vector<Entry> table = {
      {{"CVODE", kMinTolerance}, {Method::bdf, Method::adams, Method::automatic}, &make_engine<CvodeEngine>},
      {{"Taylor", kMinTaylorTolerance}, {Method::taylor}, &make_engine<TaylorEngine>},
  };
  return table;
}

std::size_t index_of(Method method) {
  const std::vector<Entry>& table = entries();
  for (std::size_t i = 0; i < table.size(); ++i) {
    if (std::find(table[i].methods.begin(), table[i].methods.end(), method) != table[i].methods.end())
      return i;
  }
  throw InvalidInput(fmt::format("no engine computes method {}", method_name(method)));
}

// A power of ten as 1e-2 (not {:g}'s 0.01), so that the ranges read as in --help.
std::string power_of_ten(double x) {
  return fmt::format("1e{}", std::lround(std::log10(x)));
}

}  // namespace

const EngineInfo& engine_of(Method method) {
  return entries()[index_of(method)].info;
}

double min_tolerance(Method method) {
  return engine_of(method).min_tolerance;
}

std::vector<std::string> tolerance_ranges(bool name_engines) {
  std::vector<std::string> out;
  for (const Entry& entry : entries()) {
    std::vector<std::string> names;
    for (const Method method : entry.methods) names.emplace_back(method_name(method));
    const bool named = name_engines && names.size() > 1;
    out.push_back(fmt::format("[{}, {}] for {}{}", power_of_ten(entry.info.min_tolerance),
                              power_of_ten(kMaxTolerance), fmt::join(names, ", "),
                              named ? fmt::format(" ({})", entry.info.name) : std::string()));
  }
  return out;
}

Engines::Engines() : engines_(entries().size()) {}
Engines::~Engines() = default;

Engine& Engines::operator()(Method method) {
  const std::size_t i = index_of(method);
  if (!engines_.at(i)) engines_.at(i) = entries()[i].make();
  return *engines_.at(i);
}

}  // namespace restitution
