// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Which YADE the `dem --code yade` lines are for (docs/dem.md, YADE): Ip2_FrictMat_FrictMat_MindlinPhys takes
// `vn` (and so the exact viscoelastic law, through its Padé [3/6] inversion) only from YADE 2024.02a on.
// Older versions (Debian 12 ships 2023.02a) take `en` (Thornton 2013's fit) or `betan`, both a damping ratio
// of the tangent stiffness, c_n = 2 betan sqrt(m_eff k_n), k_n = (3/2) k xi^{1/2}: the Tsuji member with
// ζ = sqrt(6) betan, a constant ε at every speed (damping-check's thornton-2013 recipe).
#include <optional>
#include <string>
#include <string_view>

#include "dem/deck.hpp"

namespace restitution::dem {

struct YadeVersion {
  int year = 2024;
  int month = 2;
  std::string text = "2024.02a";  // as YADE prints it
  [[nodiscard]] bool has_vn() const { return year > 2024 || (year == 2024 && month >= 2); }
};

// "2023.02a" (also inside `yade --version`'s "Yade version: 2023.02a"); empty when there is no YYYY.MM.
std::optional<YadeVersion> parse_yade_version(std::string_view text);
// --yade-version: throws InvalidInput naming the value unless it is a YYYY.MM[x] version.
YadeVersion yade_version_from_name(std::string_view text);
// `yade --version` of the yade on PATH; empty when there is none or it prints no version.
std::optional<YadeVersion> yade_version_on_path();

// The YADE the lines are for when no version is named: the one on PATH, else 2024.02a (the first with vn, so
// the exact law); `source` says which, in words for the output.
struct TargetedYade {
  YadeVersion version;
  std::string source;
};
TargetedYade installed_yade_or_newest();

// The lines for a YADE without `vn`: `exact`'s material and law lines with MindlinPhys(betan = betan), betan
// [1] the damping ratio that gives `eps` at every speed; the notes say so and name the version that would
// take the exact lines.
Deck yade_constant_eps_deck(const Deck& exact, double betan, double eps, const YadeVersion& version);

}  // namespace restitution::dem
