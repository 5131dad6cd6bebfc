// SPDX-License-Identifier: BSD-3-Clause
#include "sweep/sweep_table.hpp"

#include <fmt/core.h>

#include "sweep/csv_field.hpp"
#include "sweep/number_text.hpp"
#include "sweep/physical_columns.hpp"

namespace restitution {
namespace {

constexpr std::size_t kNumbersPerEnd = 4;
constexpr std::size_t kTrailingNumbers = 3;  // max_compression tau and x, steps

// Columns after the maximal compression's for a material: its SI durations and maximal compression.
std::vector<std::string> si_columns(EndSet ends, const SweepColumns* velocity) {
  std::vector<std::string> columns;
  if (velocity == nullptr || velocity->scales.empty()) return columns;
  for (const CollisionEnd end : ends.members()) columns.push_back(duration_column(end));
  for (const std::string& c : si_max_compression_columns()) columns.push_back(c);
  return columns;
}

}  // namespace

std::string sweep_header(EndSet ends, const SweepColumns* velocity) {
  std::string header = "zeta";
  if (velocity != nullptr) {
    header += ",velocity_m_s";
    if (velocity->beta) header += ",beta";
  }
  for (const CollisionEnd end : ends.members()) {
    for (const char* column : {"eps", "one_minus_eps", "tau", "x"})
      header += fmt::format(",{}_{}", end_key(end), column);
  }
  header += ",max_compression_tau,max_compression_x";
  for (const std::string& c : si_columns(ends, velocity)) header += "," + c;
  return header + ",steps,status,error";
}

std::string sweep_row(const SweepPoint& point, EndSet ends, const SweepColumns* velocity) {
  std::string row = number17(point.zeta);
  if (velocity != nullptr) {
    row += fmt::format(",{}", number17(velocity->velocity_m_s.at(point.index)));
    if (velocity->beta) row += fmt::format(",{}", number17(*velocity->beta));
  }
  if (!point.result) {
    const std::size_t empty =
        kTrailingNumbers + kNumbersPerEnd * ends.members().size() + si_columns(ends, velocity).size();
    row += std::string(empty, ',');
    row += ",failed,";
    row += quoted_field(point.error);
    return row;
  }
  const CollisionResult& r = *point.result;
  const auto add = [&row](double value) {
    row += ',';
    row += number17(value);
  };
  for (const CollisionEnd end : ends.members()) {
    const EndResult& e = *r[end];
    for (const double value : {e.eps, e.one_minus_eps, e.tau, e.x}) add(value);
  }
  add(r.max_compression.tau);
  add(r.max_compression.x);
  if (velocity != nullptr && !velocity->scales.empty()) {
    const NaturalScales& scales = velocity->scales.at(point.index);
    for (const CollisionEnd end : ends.members()) add(duration_s(*r[end], scales));
    for (const double value : si_max_compression(r.max_compression, scales)) add(value);
  }
  row += fmt::format(",{},ok,", r.stats.steps);
  return row;
}

}  // namespace restitution
