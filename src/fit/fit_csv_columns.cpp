// SPDX-License-Identifier: BSD-3-Clause
#include "fit/fit_csv_columns.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <string_view>

#include "restitution/errors.hpp"
#include "restitution/fit.hpp"

namespace restitution::fit_detail {
namespace {

enum class Role { speed, eps, sigma };

constexpr std::array<std::string_view, 16> kSpeedNames{"v",
                                                       "velocity",
                                                       "speed",
                                                       "impact_speed",
                                                       "impact_velocity",
                                                       "v_impact",
                                                       "v_i",
                                                       "v0",
                                                       "vel",
                                                       "normal_velocity",
                                                       "v_n",
                                                       "vn",
                                                       "impact_vel",
                                                       "approach_velocity",
                                                       "approach_speed",
                                                       "relative_velocity"};
constexpr std::array<std::string_view, 12> kEpsNames{
    "eps",      "e",  "cor",   "epsilon", "restitution", "coefficient_of_restitution", "coeff_of_restitution",
    "e_n",      "en", "eps_n",
    "\xCE\xB5",  // ε
    "cr"};
constexpr std::array<std::string_view, 26> kSigmaNames{
    "sigma",     "eps_err", "eps_error", "eps_std", "eps_sigma", "eps_uncertainty", "sigma_eps",
    "e_err",     "e_std",   "cor_err",   "cor_std", "err",       "error",           "uncertainty",
    "std",       "stdev",   "std_dev",   "sd",      "stderr",    "std_err",         "standard_deviation",
    "delta_eps", "d_eps",   "deps",      "u_eps",   "\xCF\x83"};  // σ
// Units of the speed that are not m/s, as suffixes (v_cm_s) or in brackets: refused by name.
constexpr std::array<std::string_view, 8> kOtherSpeedSuffixes{"_cm_s", "_mm_s", "_km_s", "_km_h",
                                                              "_kmh",  "_mph",  "_ft_s", "_in_s"};
constexpr std::array<std::string_view, 4> kMetrePerSecondSuffixes{"_m_s", "_mps", "_m_per_s", "_m_sec"};

std::string lowercase(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; });
  return out;
}

std::string_view trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

// "Impact speed" -> "impact_speed": blanks, '-' and '.' read as one '_'.
std::string underscored(std::string_view text) {
  std::string out;
  for (const char c : text) {
    const bool separator = c == ' ' || c == '\t' || c == '-' || c == '.' || c == '_';
    if (separator) {
      if (!out.empty() && out.back() != '_') out += '_';
    } else {
      out += c;
    }
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out;
}

bool ends_with(std::string_view text, std::string_view suffix) {
  return text.size() > suffix.size() && text.substr(text.size() - suffix.size()) == suffix;
}

struct SplitName {
  std::string base;
  std::optional<std::string> unit;  // as written, without the brackets or the leading '_'
};

// "velocity [m/s]", "v (m/s)", "v_m_s": the name and its unit.
SplitName split_unit(std::string_view raw) {
  const std::string name = lowercase(trimmed(raw));
  SplitName out;
  const char close = name.empty() ? '\0' : name.back();
  if (close == ']' || close == ')') {
    const auto open = name.rfind(close == ']' ? '[' : '(');
    if (open != std::string::npos) {
      out.unit = std::string(trimmed(std::string_view(name).substr(open + 1, name.size() - open - 2)));
      out.base = underscored(trimmed(std::string_view(name).substr(0, open)));
      return out;
    }
  }
  out.base = underscored(name);
  for (const auto suffix : kMetrePerSecondSuffixes) {
    if (ends_with(out.base, suffix)) {
      out.base.resize(out.base.size() - suffix.size());
      out.unit = "m/s";
      return out;
    }
  }
  for (const auto suffix : kOtherSpeedSuffixes) {
    if (ends_with(out.base, suffix)) {
      out.unit.emplace(suffix.begin() + 1, suffix.end());
      out.base.resize(out.base.size() - suffix.size());
      return out;
    }
  }
  return out;
}

bool is_metre_per_second(std::string unit) {
  unit.erase(std::remove(unit.begin(), unit.end(), ' '), unit.end());
  return unit == "m/s" || unit == "ms^-1" || unit == "ms-1" || unit == "m*s^-1" || unit == "mps" ||
         unit == "m/sec" || unit == "m_s";
}

bool is_dimensionless(const std::string& unit) {
  return unit.empty() || unit == "-" || unit == "1";
}

template <std::size_t N>
bool among(const std::array<std::string_view, N>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

template <std::size_t N>
std::string listed(const std::array<std::string_view, N>& names) {
  std::string out;
  for (const auto name : names) (out += out.empty() ? "" : " ") += name;
  return out;
}

std::string accepted_names() {
  return fmt::format(
      "speed [m/s]: {} (with a unit only m/s: 'v [m/s]', 'v (m/s)', v_m_s); eps: {}; sigma: {}; case and "
      "blanks do not matter",
      listed(kSpeedNames), listed(kEpsNames), listed(kSigmaNames));
}

const char* role_name(Role role) {
  switch (role) {
    case Role::speed:
      return "speed";
    case Role::eps:
      return "eps";
    case Role::sigma:
      break;
  }
  return "sigma";
}

// The header's names for a message: the first ten (a line of 4096 commas would otherwise make a page).
std::string found(const std::vector<HeaderField>& header) {
  constexpr std::size_t kShown = 10;
  std::string out;
  for (std::size_t i = 0; i < header.size() && i < kShown; ++i) {
    out += (out.empty() ? "'" : ", '") + quoted_excerpt(header[i].text) + "'";
  }
  if (header.size() > kShown) out += fmt::format(" and {} more", header.size() - kShown);
  return out;
}

// The role of one header name, nullopt when it is none of the accepted ones.
std::optional<Role> role_of(const HeaderField& field, const std::string& where) {
  const SplitName name = split_unit(field.text);
  if (among(kSpeedNames, name.base)) {
    if (name.unit && !is_metre_per_second(*name.unit)) {
      throw InvalidInput(fmt::format(
          "{}:{}: column '{}': a speed in '{}': give the speed in m/s (name it e.g. 'v [m/s]' or v)", where,
          field.column, quoted_excerpt(field.text), quoted_excerpt(*name.unit)));
    }
    return Role::speed;
  }
  const bool plain = !name.unit || is_dimensionless(*name.unit);
  if (among(kEpsNames, name.base)) {
    if (!plain) {
      throw InvalidInput(fmt::format("{}:{}: column '{}': eps is a ratio without unit, not in '{}'", where,
                                     field.column, quoted_excerpt(field.text), quoted_excerpt(*name.unit)));
    }
    return Role::eps;
  }
  if (among(kSigmaNames, name.base)) {
    if (!plain) {
      throw InvalidInput(fmt::format(
          "{}:{}: column '{}': sigma is the standard deviation of eps, a ratio without unit, not in '{}'",
          where, field.column, quoted_excerpt(field.text), quoted_excerpt(*name.unit)));
    }
    return Role::sigma;
  }
  return std::nullopt;
}

// pandas writes its index as a first column named "" or "Unnamed: 0".
bool is_index_name(const std::string& text) {
  const std::string name = lowercase(trimmed(text));
  return name.empty() || name == "unnamed: 0" || name == "index";
}

}  // namespace

FitColumns fit_columns(const std::vector<HeaderField>& header, const std::string& where) {
  FitColumns out;
  out.width = header.size();
  std::array<std::optional<std::size_t>, 3> at;
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (i == 0 && header.size() > 1 && is_index_name(header[i].text)) {
      out.index = 0;
      continue;
    }
    const auto role = role_of(header[i], where);
    if (!role) {
      throw InvalidInput(fmt::format(
          "{}:{}: unknown column '{}' in the header (columns found: {}; names accepted: {})", where,
          header[i].column, quoted_excerpt(header[i].text), found(header), accepted_names()));
    }
    auto& slot = at[static_cast<std::size_t>(*role)];
    if (slot) {
      throw InvalidInput(fmt::format(
          "{}:{}: columns '{}' and '{}' both name the {}: keep one (columns found: {}; names accepted: {})",
          where, header[i].column, quoted_excerpt(header[*slot].text), quoted_excerpt(header[i].text),
          role_name(*role), found(header), accepted_names()));
    }
    slot = i;
  }
  for (const Role role : {Role::speed, Role::eps}) {
    if (!at[static_cast<std::size_t>(role)]) {
      throw InvalidInput(
          fmt::format("{}: the header names no {} column (columns found: {}; names accepted: {})", where,
                      role_name(role), found(header), accepted_names()));
    }
  }
  out.speed = *at[0];
  out.eps = *at[1];
  out.sigma = at[2];
  return out;
}

}  // namespace restitution::fit_detail
