// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `restitution dem` output for several atom types: the per-type-pair lines, each pair's ε at the speeds and,
// for a binned size range, the worst ε error of the binning (docs/dem.md, "Polydisperse sets").
#include <optional>
#include <string>

#include "dem/polydisperse_lines.hpp"

namespace restitution::cli {

// The check deck `--deck FILE` wrote, and the command that runs it.
struct WrittenDeck {
  std::string file, run;
};

void print_polydisperse_text(const dem::PolydisperseResult& r, const std::optional<WrittenDeck>& deck);
// One JSON object: code, end, A and how it was set, `types`, `pairs` (per pair E*, R_eff, m_eff, the
// parameters and eps per speed), `lines`, `notes`, for a range `binning`, and with --deck `deck` (file, run).
void print_polydisperse_json(const dem::PolydisperseResult& r, const std::optional<WrittenDeck>& deck);

}  // namespace restitution::cli
