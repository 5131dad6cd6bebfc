// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The formats a figure is written in: a scene's `format = ["png", "pdf"]` and the commands' --format
// png,pdf,svg share this spelling (scripts/plots/style.py writes them).
#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace restitution::scene {

inline constexpr std::array<std::string_view, 3> kFigureFormats{"png", "pdf", "svg"};

// The formats named, in the order given, each once. Throws InvalidInput naming an unknown format, or when
// none is named.
std::vector<std::string> figure_formats(const std::vector<std::string>& names);

// figure_formats() of a comma-separated list ("png,pdf").
std::vector<std::string> figure_formats_from_list(std::string_view list);

// The format a figure file named on the command line (--plot FILE) is written in: its extension, png, pdf or
// svg, never another name. Throws InvalidInput naming the file and the formats that work for any other
// extension or none.
std::string figure_format_of(std::string_view file);

// The formats of --plot FILE [--format LIST]: FILE's own first, then those of the list not yet in it (an
// empty list adds none).
std::vector<std::string> plot_figure_formats(std::string_view file, std::string_view also);

// The format a report links to: PNG when written (every viewer shows it), else the first.
const std::string& linked_figure_format(const std::vector<std::string>& formats);

}  // namespace restitution::scene
