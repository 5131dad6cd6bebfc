// SPDX-License-Identifier: BSD-3-Clause
#include "dem/yade_versions.hpp"

#include <fmt/core.h>

#include <regex>

#include "dem/process_output.hpp"
#include "restitution/errors.hpp"

namespace restitution::dem {

std::optional<YadeVersion> parse_yade_version(std::string_view text) {
  static const std::regex version(R"((20\d\d)\.(\d\d)([a-z]?))");
  std::match_results<std::string_view::const_iterator> m;
  if (!std::regex_search(text.begin(), text.end(), m, version)) return std::nullopt;
  return YadeVersion{std::stoi(m[1].str()), std::stoi(m[2].str()), m[0].str()};
}

YadeVersion yade_version_from_name(std::string_view text) {
  const auto v = parse_yade_version(text);
  if (!v || v->text.size() != text.size())
    throw InvalidInput(fmt::format("--yade-version must be a YADE version such as 2023.02a, got '{}'", text));
  return *v;
}

std::optional<YadeVersion> yade_version_on_path() {
  // yade prints its banner noise on stderr; only the "Yade version: ..." line matters.
  const std::string out = output_of(std::string(code_entry(Code::yade).version_query) + " 2>/dev/null");
  const auto at = out.find("Yade version:");
  if (at == std::string::npos) return std::nullopt;
  return parse_yade_version(std::string_view(out).substr(at));
}

TargetedYade installed_yade_or_newest() {
  if (auto on_path = yade_version_on_path()) return {*on_path, "yade on PATH"};
  return {YadeVersion{}, "no yade on PATH: the lines of YADE 2024.02a and later"};
}

Deck yade_constant_eps_deck(const Deck& exact, double betan, double eps, const YadeVersion& version) {
  Deck d = exact;
  d.parameters.clear();
  for (const Parameter& p : exact.parameters) {
    if (p.name != "en" && p.name != "vn") d.parameters.push_back(p);
  }
  d.parameters.push_back(
      {"betan", betan, "damping ratio of the tangent stiffness, c_n = 2 betan sqrt(m_eff k_n) [1]"});
  d.lines.at(1) =
      fmt::format("Ip2_FrictMat_FrictMat_MindlinPhys(betan=MatchMaker(algo='val', val={:.17g}))", betan);
  d.notes = {
      fmt::format(
          "YADE {} has no vn: its MindlinPhys damps as c_n = 2 betan sqrt(m_eff k_n), the Tsuji member "
          "(zeta = sqrt(6) betan), which gives one eps at every speed, size and material: {:.10f}, the "
          "law's eps at the reference speed only (damping-check --recipe thornton-2013: en = eps "
          "instead of betan gives the same member through Thornton 2013's fit)",
          version.text, eps),
      "the exact viscoelastic law eps(v) needs YADE 2024.02a or later: `restitution dem --code yade "
      "--yade-version 2024.02a` prints its (en, vn) lines"};
  for (const std::string& note : exact.notes) {
    // The notes on vn's conversion and availability are the exact lines' own.
    if (note.find("beta = sigma^2") == std::string::npos && note.find("vn exists") == std::string::npos)
      d.notes.push_back(note);
  }
  return d;
}

}  // namespace restitution::dem
