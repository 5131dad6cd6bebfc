// SPDX-License-Identifier: BSD-3-Clause
// libFuzzer target: the reader of a sweep's partial file (what `restitution sweep --resume` trusts). Any text
// must give rows of this sweep only, or InvalidInput naming the file; anything else is a finding. Every row
// the reader keeps is checked here on its own terms, not with the reader's code: its line round-trips (index,
// row and checksum as the writer writes them), it has the header's number of fields (quoted commas counted as
// text), its numbers parse whole and print back as the table writes them, its ζ is the grid's, and the counts
// add up. A torn row, an extra or missing field or `abc` in a number field that the reader kept is a finding.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "restitution/errors.hpp"
#include "sweep/number_text.hpp"
#include "sweep/sweep_partial.hpp"
#include "sweep/sweep_table.hpp"

namespace {

using namespace restitution;

void check(bool ok) {
  if (!ok) std::abort();
}

// CSV fields with RFC 4180 quoting: a comma inside quotes is text.
std::vector<std::string> csv_fields(std::string_view row) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (const char c : row) {
    if (c == '"') quoted = !quoted;
    if (c == ',' && !quoted) {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  check(!quoted);
  return fields;
}

bool is_number(const std::string& text) {
  if (text.empty()) return false;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && number17(value) == text;
}

bool is_count(const std::string& text) {
  return !text.empty() &&
         std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; }) &&
         (text.size() == 1 || text.front() != '0');
}

// The row of point `index` as the table would hold it (10 fields: zeta, 4 of the naive end, 2 of the maximal
// compression, steps, status, error).
void check_row(std::string_view row, std::size_t index, const std::vector<double>& zetas, std::size_t columns,
               bool& failed) {
  const std::vector<std::string> f = csv_fields(row);
  check(f.size() == columns);
  check(is_number(f[0]) && std::strtod(f[0].c_str(), nullptr) == zetas[index]);
  const std::string& status = f[columns - 2];
  failed = status == "failed";
  check(failed || status == "ok");
  for (std::size_t i = 1; i + 3 < columns; ++i) check(failed ? f[i].empty() : is_number(f[i]));
  check(failed ? f[columns - 3].empty() : is_count(f[columns - 3]));
  const std::string& error = f.back();
  check(failed ? error.size() >= 2 && error.front() == '"' && error.back() == '"' : error.empty());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::vector<double> zetas = zeta_values({0.0, 2.0, 5, false});
  static const std::string header = sweep_header(EndSet{CollisionEnd::naive});
  const std::size_t columns = static_cast<std::size_t>(std::count(header.begin(), header.end(), ',')) + 1;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const PartialSweep partial =
        parse_partial_sweep(text, "s.csv.partial", "# restitution sweep: fuzz", header, zetas);
    check(partial.valid_bytes <= text.size());
    check(partial.valid_bytes == 0 || text[partial.valid_bytes - 1] == '\n');
    check(partial.row_offset.empty() ? partial.kept == 0 : partial.row_offset.size() == zetas.size());
    std::size_t kept = 0;
    std::size_t failed = 0;
    for (std::size_t index = 0; index < partial.row_offset.size(); ++index) {
      const std::uint64_t offset = partial.row_offset[index];
      if (offset == PartialSweep::kNotDone) continue;
      ++kept;
      check(offset < partial.valid_bytes);
      const std::size_t end = text.find('\n', offset);
      check(end != std::string::npos && end < partial.valid_bytes);
      const std::string line = text.substr(offset, end - offset);
      const std::string prefix = std::to_string(index) + ",";
      check(line.rfind(prefix, 0) == 0 && line.size() > prefix.size() + 9);
      const std::string row = line.substr(prefix.size(), line.size() - prefix.size() - 9);
      std::string again;  // the writer's own line for this row: the same bytes, checksum included
      append_partial_line(again, index, row);
      check(again == line + "\n");
      bool row_failed = false;
      check_row(row, index, zetas, columns, row_failed);
      if (row_failed) ++failed;
    }
    check(kept == partial.kept && failed == partial.failed);
    // Every complete line after the first two was kept, dropped or a repeat.
    if (partial.valid_bytes > 0) {
      const auto lines = static_cast<std::size_t>(
          std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(partial.valid_bytes), '\n'));
      check(lines == 2 + partial.kept + partial.dropped + partial.duplicates);
    }
  } catch (const InvalidInput& e) {
    check(std::string(e.what()).find("s.csv.partial") != std::string::npos);
  }
  return 0;
}
