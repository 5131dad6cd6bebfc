// SPDX-License-Identifier: BSD-3-Clause
#include "cli/sweep_table.hpp"

#include <fmt/core.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "cli/output_files.hpp"
#include "cli/physical_columns.hpp"
#include "restitution/errors.hpp"

namespace restitution::cli {
namespace {

constexpr std::size_t kNumbersPerEnd = 4;
constexpr std::size_t kTrailingNumbers = 3;  // max_compression tau and x, steps

// A CSV field: quoted, inner quotes doubled, line breaks flattened so that one row stays one line.
std::string quoted_field(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"') {
      out += "\"\"";
    } else {
      out += (c == '\n' || c == '\r') ? ' ' : c;
    }
  }
  return out + "\"";
}

// Columns after the maximal compression's for a material: its SI durations and maximal compression.
std::vector<std::string> si_columns(EndSet ends, const VelocityAxis* velocity) {
  std::vector<std::string> columns;
  if (velocity == nullptr || velocity->scales.empty()) return columns;
  for (const CollisionEnd end : ends.members()) columns.push_back(duration_column(end));
  for (const std::string& c : si_max_compression_columns()) columns.push_back(c);
  return columns;
}

[[noreturn]] void damaged(const std::filesystem::path& path, std::size_t line, const std::string& why) {
  throw InvalidInput(
      fmt::format("--resume: {}:{}: {}; delete it to start the sweep afresh", path.string(), line, why));
}

}  // namespace

std::string sweep_header(EndSet ends, const VelocityAxis* velocity) {
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

std::string sweep_row(const SweepPoint& point, EndSet ends, const VelocityAxis* velocity) {
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

PartialSweep read_partial_sweep(const std::filesystem::path& path, const std::string& settings,
                                const std::string& header, const std::vector<double>& zetas) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InvalidInput(fmt::format("--resume: cannot read '{}'", path.string()));
  std::stringstream buffer;
  buffer << in.rdbuf();
  return parse_partial_sweep(buffer.str(), path, settings, header, zetas);
}

PartialSweep parse_partial_sweep(const std::string& text, const std::filesystem::path& path,
                                 const std::string& settings, const std::string& header,
                                 const std::vector<double>& zetas) {
  PartialSweep partial;
  std::size_t line_number = 0;
  std::size_t begin = 0;
  while (begin < text.size()) {
    const std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) break;  // cut off while being written: computed again
    const std::string line = text.substr(begin, end - begin);
    ++line_number;
    if (line_number == 1 && line != settings) {
      damaged(path, 1, fmt::format("written by another sweep ('{}', this one is '{}')", line, settings));
    }
    if (line_number == 2 && line != header) damaged(path, 2, "its CSV header differs from this sweep's");
    if (line_number > 2) {
      const std::size_t comma = line.find(',');
      char* parsed_end = nullptr;
      const unsigned long long index = std::strtoull(line.c_str(), &parsed_end, 10);
      if (comma == std::string::npos || parsed_end != line.c_str() + comma || index >= zetas.size()) {
        damaged(path, line_number, "not a row of this sweep");
      }
      const std::string row = line.substr(comma + 1);
      if (std::strtod(row.c_str(), nullptr) != zetas[index])
        damaged(path, line_number, "its zeta differs from the grid's");
      if (row.find(",failed,") != std::string::npos) ++partial.failed;
      if (!partial.rows.emplace(index, row).second) damaged(path, line_number, "point listed twice");
    }
    begin = end + 1;
  }
  if (line_number < 2) damaged(path, line_number, "no settings line and header");
  partial.valid_bytes = begin;
  return partial;
}

}  // namespace restitution::cli
