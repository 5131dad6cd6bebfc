// SPDX-License-Identifier: BSD-3-Clause
#include "restitution/fit_csv.hpp"

#include <fmt/core.h>

#include <array>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <vector>

#include "restitution/errors.hpp"

namespace restitution {
namespace {

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream stream(line);
  std::string field;
  while (std::getline(stream, field, ',')) out.push_back(trimmed(field));
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

enum Column { kV, kEps, kSigma };
constexpr std::array<const char*, 3> kColumnNames{"v", "eps", "sigma"};

// The column index of each name in the header.
std::array<std::optional<std::size_t>, 3> header_columns(const std::vector<std::string>& names,
                                                         const std::string& where) {
  std::array<std::optional<std::size_t>, 3> at;
  for (std::size_t i = 0; i < names.size(); ++i) {
    std::size_t k = 0;
    while (k < kColumnNames.size() && names[i] != kColumnNames[k]) ++k;
    if (k == kColumnNames.size()) {
      throw InvalidInput(fmt::format(
          "{}: unknown column '{}' in the header (expected v, eps and optionally sigma)", where, names[i]));
    }
    if (at[k]) throw InvalidInput(fmt::format("{}: column '{}' named twice in the header", where, names[i]));
    at[k] = i;
  }
  if (!at[kV] || !at[kEps]) {
    throw InvalidInput(
        fmt::format("{}: the header must name the columns v and eps (and optionally sigma)", where));
  }
  return at;
}

double number(const std::string& text, const std::string& where, const char* column) {
  double value = 0.0;
  std::size_t used = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || std::isnan(value)) {
    throw InvalidInput(fmt::format("{}: column '{}': '{}' is not a number", where, column, text));
  }
  return value;
}

}  // namespace

FitData parse_fit_csv(const std::string& text, const std::string& name) {
  std::istringstream in(text);
  std::string line;
  int line_number = 0;
  std::optional<std::array<std::optional<std::size_t>, 3>> columns;
  std::size_t width = 0;
  FitData data;
  while (std::getline(in, line)) {
    ++line_number;
    // A spreadsheet's UTF-8 byte-order mark before the header is not part of the first column's name.
    if (line_number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
    const std::string content = trimmed(line);
    if (content.empty() || content.front() == '#') continue;
    const std::string where = fmt::format("{}:{}", name, line_number);
    const std::vector<std::string> row = fields(content);
    if (!columns) {
      columns = header_columns(row, where);
      width = row.size();
      continue;
    }
    if (row.size() != width) {
      throw InvalidInput(fmt::format("{}: {} fields, the header names {}", where, row.size(), width));
    }
    const double v = number(row[*(*columns)[kV]], where, "v");
    const double eps = number(row[*(*columns)[kEps]], where, "eps");
    if (!std::isfinite(v) || v <= 0.0) {
      throw InvalidInput(
          fmt::format("{}: column 'v': the speed must be finite and > 0 m/s, got {}", where, v));
    }
    if (eps <= 0.0 || eps >= 1.0) {
      throw InvalidInput(fmt::format("{}: column 'eps': must be in (0, 1), got {}", where, eps));
    }
    data.velocity_m_s.push_back(v);
    data.eps.push_back(eps);
    if ((*columns)[kSigma]) {
      const double sigma = number(row[*(*columns)[kSigma]], where, "sigma");
      if (!std::isfinite(sigma) || sigma <= 0.0) {
        throw InvalidInput(fmt::format("{}: column 'sigma': must be finite and > 0, got {}", where, sigma));
      }
      data.sigma.push_back(sigma);
    }
  }
  if (!columns) throw InvalidInput(fmt::format("{}: empty: no header and no measurements", name));
  if (data.eps.empty()) throw InvalidInput(fmt::format("{}: a header but no measurements", name));
  return data;
}

FitData read_fit_csv(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in || std::filesystem::is_directory(path)) {
    throw InvalidInput(fmt::format("{}: cannot be read", path.string()));
  }
  std::stringstream buffer;
  buffer << in.rdbuf();
  return parse_fit_csv(buffer.str(), path.string());
}

}  // namespace restitution
