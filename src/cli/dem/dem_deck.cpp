// SPDX-License-Identifier: BSD-3-Clause
#include "cli/dem/dem_deck.hpp"

#include <fmt/core.h>

#include "dem/dem_codes.hpp"
#include "dem/oblique_check_deck.hpp"
#include "files/output_files.hpp"
#include "restitution/errors.hpp"

namespace restitution::cli {

void check_deck_target(const std::string& path, dem::Code code) {
  if (path.empty()) throw InvalidInput("--deck needs a file name, got an empty one");
  dem::require_check_deck(code);
  dem::require_check_deck_name(code, path);
  files::check_output_file(path);
}

void check_deck_size(dem::Code code, std::size_t type_count, std::size_t speed_count) {
  constexpr std::size_t kDefaultSpeeds = 3;  // v/10, v, 10 v
  dem::require_deck_size(code, type_count * (type_count + 1) / 2,
                         speed_count > 0 ? speed_count : kDefaultSpeeds);
}

std::string write_check_deck(const std::string& path, const dem::CheckDeckRequest& request) {
  files::write_file_atomically(path, dem::check_deck(request));
  return dem::check_deck_command(request.code, path);
}

std::string write_check_deck(const std::string& path, const dem::LinesResult& r, const Material& material,
                             const std::optional<DemOblique>& oblique) {
  dem::CheckDeckRequest request;
  request.code = r.deck.code;
  request.lines = r.deck.lines;
  dem::CheckPair pair;
  pair.pair = dem::pair_of(material);
  for (const auto& e : r.eps) {
    request.speeds_m_s.push_back(e.velocity_m_s);
    pair.eps_restitution.push_back(e.eps);
  }
  request.pairs = {pair};
  request.comments = {
      fmt::format("written by `restitution dem --code {}`: viscoelastic Hertz law, A = {:.10g} s, {} end",
                  dem::code_name(r.deck.code), r.dissipative_constant_s, end_name(r.deck.end)),
      fmt::format("type pair 1,1: radii {} and {} m, masses {} and {} kg", pair.pair.radius1_m,
                  pair.pair.radius2_m, pair.pair.mass1_kg, pair.pair.mass2_kg)};
  if (r.yade_version) {
    request.yade_version = r.yade_version->text;
    request.comments.push_back(fmt::format(
        "for YADE {}{}", r.yade_version->text,
        r.yade_exact_deck ? ": it cannot express the law; eps_restitution is the eps these lines give there"
                          : ""));
  }
  // The oblique section of the code (dem/oblique_check_deck.hpp).
  if (!oblique) return write_check_deck(path, request);
  files::write_file_atomically(path, dem::check_deck(request) + dem::oblique_check_section(*oblique, r.deck));
  return dem::check_deck_command(request.code, path);
}

}  // namespace restitution::cli
