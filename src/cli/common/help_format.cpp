// SPDX-License-Identifier: BSD-3-Clause
#include "cli/common/help_format.hpp"

#include <sstream>
#include <utility>

namespace restitution::cli {
namespace {

std::size_t leading_spaces(const std::string& line) {
  const auto first = line.find_first_not_of(' ');
  return first == std::string::npos ? line.size() : first;
}

// An entry of the two-column layout ("  --name TYPE   description") or the continuation of its description.
bool in_description_column(const std::string& line, std::size_t column) {
  if (line.size() <= column || line[column] == ' ') return false;
  if (leading_spaces(line) == column) return true;
  return line.compare(0, 2, "  ") == 0 && line[column - 1] == ' ' && line[column - 2] == ' ';
}

void wrap_line(const std::string& line, std::size_t width, std::size_t description_column, std::string& out) {
  const std::size_t indent =
      in_description_column(line, description_column) ? description_column : leading_spaces(line) + 2;
  std::string rest = line;
  while (rest.size() > width) {
    // The last space within the width that is past the indentation (a break inside it would loop).
    std::size_t cut = rest.rfind(' ', width);
    const std::size_t floor = leading_spaces(rest);
    if (cut == std::string::npos || cut <= floor) {
      // A word longer than the room: a list of choices ("TEXT:{a,b,c}") breaks after a comma, else after the
      // word.
      const std::size_t comma = rest.rfind(',', width - 1);
      if (comma != std::string::npos && comma > floor) {
        out.append(rest, 0, comma + 1).push_back('\n');
        rest = std::string(indent, ' ') + rest.substr(comma + 1);
        continue;
      }
      cut = rest.find(' ', width);
      if (cut == std::string::npos) break;
    }
    std::size_t end = cut;
    while (end > floor && rest[end - 1] == ' ') --end;  // no trailing blanks
    out.append(rest, 0, end).push_back('\n');
    const std::size_t next = rest.find_first_not_of(' ', cut);
    if (next == std::string::npos) {
      rest.clear();
      break;
    }
    rest = std::string(indent, ' ') + rest.substr(next);
  }
  out += rest;
}

}  // namespace

std::string wrap_help_text(const std::string& text, std::size_t width, std::size_t description_column) {
  std::string out;
  std::istringstream lines(text);
  std::string line;
  bool first = true;
  while (std::getline(lines, line)) {
    if (!first) out.push_back('\n');
    first = false;
    wrap_line(line, width, description_column, out);
  }
  if (!text.empty() && text.back() == '\n') out.push_back('\n');
  return out;
}

std::string WrappingHelpFormatter::make_help(const CLI::App* app, std::string name,
                                             CLI::AppFormatMode mode) const {
  return wrap_help_text(CLI::Formatter::make_help(app, std::move(name), mode), kHelpWidth,
                        get_column_width());
}

}  // namespace restitution::cli
