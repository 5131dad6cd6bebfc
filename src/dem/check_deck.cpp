// SPDX-License-Identifier: BSD-3-Clause
#include "dem/check_deck.hpp"

#include <fmt/core.h>

#include <cmath>
#include <sstream>
#include <string_view>

#include "dem/check_deck_codes.hpp"
#include "restitution/errors.hpp"
#include "restitution/units.hpp"

namespace restitution::dem {
namespace {

void validate(const CheckDeckRequest& r) {
  require_check_deck(r.code);
  if (r.pairs.empty() || r.speeds_m_s.empty())
    throw InvalidInput("a check deck needs at least one type pair and one speed");
  require_deck_size(r.code, r.pairs.size(), r.speeds_m_s.size());
  for (const double v : r.speeds_m_s) {
    if (!std::isfinite(v) || v <= 0.0)
      throw InvalidInput(fmt::format("a check deck's speeds must be finite and > 0 m/s, got {}", v));
  }
  for (const CheckPair& p : r.pairs) {
    if (p.type1 < 1 || p.type2 < 1 || p.type1 > r.type_count || p.type2 > r.type_count) {
      throw InvalidInput(fmt::format("check deck: type pair {},{} outside the {} atom types", p.type1,
                                     p.type2, r.type_count));
    }
    if (p.eps_restitution.size() != r.speeds_m_s.size()) {
      throw InvalidInput(fmt::format("check deck: type pair {},{} has {} eps for {} speeds", p.type1, p.type2,
                                     p.eps_restitution.size(), r.speeds_m_s.size()));
    }
  }
}

// The value of `key=value` in a check line's fields (NaN when absent or not a number).
double field(const std::string& line, const std::string& key) {
  const auto at = line.find(" " + key + "=");
  if (at == std::string::npos) return NAN;
  try {
    return std::stod(line.substr(at + key.size() + 2));
  } catch (const std::exception&) {
    return NAN;
  }
}

}  // namespace

double natural_time_s(const Pair& pair, double velocity_m_s) {
  return natural_time_scale_s(
      hertz_stiffness(pair.effective_modulus_pa, pair.effective_radius_m) / pair.effective_mass_kg,
      velocity_m_s);
}

std::size_t max_deck_collisions(Code code) {
  return code_entry(code).max_deck_collisions;
}

std::size_t max_deck_types(Code code, std::size_t speeds) {
  return max_deck_types(max_deck_collisions(code), speeds);
}

std::size_t max_deck_types(std::size_t collisions, std::size_t speeds) {
  std::size_t n = 0;
  while ((n + 1) * (n + 2) / 2 * speeds <= collisions) ++n;
  return n;
}

void require_deck_size(Code code, std::size_t type_pairs, std::size_t speeds) {
  const std::size_t most = max_deck_collisions(code);
  if (type_pairs * speeds <= most) return;
  throw InvalidInput(
      fmt::format("--deck: {} type pair{} x {} speed{} = {} collisions; a {} check deck holds at most {} (so "
                  "that it runs "
                  "in minutes): give fewer atom types (--radius, --classes) or speeds (--impact-velocity)",
                  type_pairs, type_pairs == 1 ? "" : "s", speeds, speeds == 1 ? "" : "s", type_pairs * speeds,
                  code_name(code), most));
}

bool has_check_deck(Code code) {
  return code_entry(code).check_deck != nullptr;
}

void require_check_deck(Code code) {
  if (!has_check_deck(code)) {
    throw InvalidInput(fmt::format(
        "--deck: no runnable deck for {}: it is a C++ library, not a program that reads an input file, and "
        "is "
        "not installed here to check one against; check decks exist for {}",
        code_name(code), code_list(" and ", [](const CodeEntry& e) { return e.check_deck != nullptr; })));
  }
}

void require_check_deck_name(Code code, const std::string& path) {
  const std::string_view suffix = code_entry(code).check_deck_suffix;
  const bool ends_with_suffix =
      path.size() >= suffix.size() && path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0;
  if (ends_with_suffix) return;
  throw InvalidInput(fmt::format(
      "--deck {}: {} runs a deck only from a file whose name ends in {} (`{}FILE` with another name runs "
      "nothing and exits 0); name it {}{}",
      path, code_name(code), suffix, code_entry(code).check_deck_run, path, suffix));
}

std::string check_deck_command(Code code, const std::string& path) {
  require_check_deck(code);
  return code_entry(code).check_deck_run + path;
}

std::string check_deck_preamble(const CheckDeckRequest& r, int n) {
  std::string s = fmt::format("# restitution check deck for {}: run it with `{}`\n", code_name(r.code),
                              check_deck_command(r.code, "<this file>"));
  for (const std::string& c : r.comments) s += "# " + c + "\n";
  s += fmt::format(
      "# It pastes the lines `restitution dem` printed unchanged, collides every type pair head-on at every\n"
      "# speed, and measures eps = (separation speed) / (impact speed) once the contact is over. Each "
      "collision\n"
      "# runs at dt = T/{0} and T/{1} (T = k^(-2/5) v^(-1/5), the natural time; the integrator is first "
      "order\n"
      "# in dt for this velocity-dependent force), and eps_code is their Richardson extrapolation\n"
      "# (10 eps_dt - eps_10dt) / 9. One line per type pair and speed:\n"
      "# {2} code={3} types=I,J speed=V_m_s eps_10dt=.. eps_dt=.. eps_code=.. eps_restitution=..\n"
      "#   rel_diff=(eps_code - eps_restitution)/eps_restitution gap_m=(surface gap at the end: > 0, contact "
      "over)\n",
      n, 10 * n, kCheckTag, code_name(r.code));
  return s;
}

std::string check_deck(const CheckDeckRequest& request) {
  validate(request);
  const CodeEntry& code = code_entry(request.code);
  const int n = request.steps_per_time > 0 ? request.steps_per_time : code.check_deck_steps;
  return code.check_deck(request, n);
}

std::vector<CheckLine> read_check_lines(const std::string& output) {
  std::vector<CheckLine> lines;
  std::istringstream in(output);
  const std::string start = std::string(kCheckTag) + " ";
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(start, 0) != 0) continue;
    CheckLine c;
    const auto code_at = line.find(" code=");
    if (code_at != std::string::npos) {
      const auto begin = code_at + 6;
      c.code = line.substr(begin, line.find(' ', begin) - begin);
    }
    const auto types_at = line.find(" types=");
    if (types_at == std::string::npos ||
        std::sscanf(line.c_str() + types_at, " types=%d,%d", &c.type1, &c.type2) != 2) {
      c.type1 = c.type2 = 0;
    }
    c.speed_m_s = field(line, "speed");
    c.eps_10dt = field(line, "eps_10dt");
    c.eps_dt = field(line, "eps_dt");
    c.eps_code = field(line, "eps_code");
    c.eps_restitution = field(line, "eps_restitution");
    c.rel_diff = field(line, "rel_diff");
    c.gap_m = field(line, "gap_m");
    lines.push_back(c);
  }
  return lines;
}

}  // namespace restitution::dem
