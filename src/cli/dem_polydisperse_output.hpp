// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `restitution dem` output for several atom types: the per-type-pair lines, each pair's ε at the speeds and,
// for a binned size range, the worst ε error of the binning (docs/dem.md, "Polydisperse sets").
#include "dem/polydisperse_lines.hpp"

namespace restitution::cli {

void print_polydisperse_text(const dem::PolydisperseResult& r);
// One JSON object: code, end, A and how it was set, `types`, `pairs` (per pair E*, R_eff, m_eff, the
// parameters and eps per speed), `lines`, `notes` and, for a range, `binning`.
void print_polydisperse_json(const dem::PolydisperseResult& r);

}  // namespace restitution::cli
