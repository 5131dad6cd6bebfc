// SPDX-License-Identifier: BSD-3-Clause
#include "scene/figure_formats.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "restitution/errors.hpp"

namespace restitution::scene {

std::vector<std::string> figure_formats(const std::vector<std::string>& names) {
  if (names.empty()) {
    throw InvalidInput(fmt::format("no figure format given (known: {})", fmt::join(kFigureFormats, ", ")));
  }
  std::vector<std::string> formats;
  for (const std::string& name : names) {
    if (std::find(kFigureFormats.begin(), kFigureFormats.end(), name) == kFigureFormats.end()) {
      throw InvalidInput(
          fmt::format("unknown figure format '{}' (known: {})", name, fmt::join(kFigureFormats, ", ")));
    }
    if (std::find(formats.begin(), formats.end(), name) == formats.end()) formats.push_back(name);
  }
  return formats;
}

std::vector<std::string> figure_formats_from_list(std::string_view list) {
  std::vector<std::string> names;
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    names.emplace_back(list.substr(start, comma - start));
    start = comma + 1;
  }
  return figure_formats(list.empty() ? std::vector<std::string>{} : names);
}

std::string figure_format_of(std::string_view file) {
  const std::string extension = std::filesystem::path(file).extension().string();
  const std::string_view format =
      extension.empty() ? std::string_view() : std::string_view(extension).substr(1);
  if (std::find(kFigureFormats.begin(), kFigureFormats.end(), format) == kFigureFormats.end()) {
    throw InvalidInput(fmt::format("'{}' names no figure format: end the file name in .{}", file,
                                   fmt::join(kFigureFormats, ", .")));
  }
  return std::string(format);
}

std::vector<std::string> plot_figure_formats(std::string_view file, std::string_view also) {
  std::vector<std::string> formats = {figure_format_of(file)};
  if (also.empty()) return formats;
  for (std::string& format : figure_formats_from_list(also)) {
    if (std::find(formats.begin(), formats.end(), format) == formats.end())
      formats.push_back(std::move(format));
  }
  return formats;
}

const std::string& linked_figure_format(const std::vector<std::string>& formats) {
  const auto png = std::find(formats.begin(), formats.end(), "png");
  return png != formats.end() ? *png : formats.front();
}

}  // namespace restitution::scene
