// SPDX-License-Identifier: BSD-3-Clause
#include "sweep/sweep_partial.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cstring>
#include <iterator>

#include "restitution/errors.hpp"
#include "sweep/number_text.hpp"
#include "sweep/physical_columns.hpp"

namespace restitution {
namespace {

constexpr std::size_t kCrcDigits = 8;
constexpr std::size_t kMaxQuotedLine = 200;  // of a foreign line, in a message

// CRC-32 (IEEE 802.3, reflected, as zlib's crc32): it detects every burst error up to 32 bits, and a cut-off
// or joined line with probability 1 - 2^-32.
constexpr std::array<std::uint32_t, 256> kCrcTable = [] {
  std::array<std::uint32_t, 256> table{};
  for (std::uint32_t i = 0; i < table.size(); ++i) {
    std::uint32_t c = i;
    for (int bit = 0; bit < 8; ++bit) c = (c & 1U) != 0 ? 0xEDB88320U ^ (c >> 1U) : c >> 1U;
    table[i] = c;
  }
  return table;
}();

std::uint32_t crc32(std::string_view bytes) {
  std::uint32_t c = 0xFFFFFFFFU;
  for (const char b : bytes) c = kCrcTable[(c ^ static_cast<unsigned char>(b)) & 0xFFU] ^ (c >> 8U);
  return c ^ 0xFFFFFFFFU;
}

// The checksum as the line writes it. Compared as text: a fuzzer learns the expected bytes from the compare.
std::array<char, kCrcDigits> crc_text(std::string_view bytes) {
  std::array<char, kCrcDigits + 1> text{};
  fmt::format_to_n(text.data(), kCrcDigits, "{:08x}", crc32(bytes));
  std::array<char, kCrcDigits> digits{};
  std::copy_n(text.begin(), kCrcDigits, digits.begin());
  return digits;
}

// A whole number as the program writes it: decimal digits, no sign, no leading zero.
bool canonical_count(std::string_view text, std::uint64_t& value) {
  if (text.empty() || (text.size() > 1 && text.front() == '0')) return false;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size();
}

// A double exactly as number17 writes it: anything else ("abc", "1.0", a cut-off "0.12") is not the
// program's.
bool canonical_number(std::string_view text, double& value) {
  if (text.empty()) return false;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size() && number17(value) == text;
}

// The error field of a failed row, as quoted_field (sweep_table.cpp) writes it.
bool quoted_message(std::string_view text) {
  if (text.size() < 2 || text.front() != '"' || text.back() != '"') return false;
  const std::string_view inner = text.substr(1, text.size() - 2);
  for (std::size_t i = 0; i < inner.size(); ++i) {
    if (inner[i] == '\r') return false;
    if (inner[i] == '"' && (i + 1 == inner.size() || inner[++i] != '"')) return false;
  }
  return true;
}

// What the header says of a row: how many fields, and how many leading ones (zeta, velocity_m_s, beta) a
// failed row keeps. The last three are steps, status and error; all the others are numbers.
struct Columns {
  std::size_t count = 0;
  std::size_t axis = 1;
};

Columns columns_of(std::string_view header) {
  Columns c;
  c.count = static_cast<std::size_t>(std::count(header.begin(), header.end(), ',')) + 1;
  const std::vector<std::string>& velocity = velocity_columns();
  std::size_t begin = header.find(',');
  while (begin != std::string_view::npos) {
    const std::size_t end = header.find(',', begin + 1);
    const std::string_view name = header.substr(begin + 1, end - begin - 1);
    if (std::find(velocity.begin(), velocity.end(), name) == velocity.end()) break;
    ++c.axis;
    begin = end;
  }
  return c;
}

// Parses one row line against the header; on success sets the point's index and whether it failed.
class RowCheck {
 public:
  RowCheck(std::string_view header, const std::vector<double>& zetas)
      : columns_(columns_of(header)), zetas_(zetas) {
    fields_.reserve(columns_.count);
  }

  bool operator()(std::string_view line, std::size_t& index, bool& failed) {
    const std::optional<std::string_view> row = partial_line_row(line);
    std::uint64_t parsed_index = 0;
    if (columns_.count < 3) return false;  // no header of the program's
    if (!row || !canonical_count(line.substr(0, line.find(',')), parsed_index) ||
        parsed_index >= zetas_.size())
      return false;
    index = static_cast<std::size_t>(parsed_index);
    if (!split(*row)) return false;
    const std::size_t steps = columns_.count - 3;
    const std::string_view status = fields_[columns_.count - 2];
    const std::string_view error = fields_.back();
    failed = status == "failed";
    if (!failed && status != "ok") return false;
    double value = 0.0;
    for (std::size_t i = 0; i < steps; ++i) {
      const bool filled = !failed || i < columns_.axis;
      if (filled ? !canonical_number(fields_[i], value) : !fields_[i].empty()) return false;
      if (i == 0 && value != zetas_[index]) return false;  // a row of another grid point
    }
    std::uint64_t count = 0;
    if (failed) return fields_[steps].empty() && quoted_message(error);
    return canonical_count(fields_[steps], count) && error.empty();
  }

 private:
  // The fields before the error are plain; the error (last) may hold commas inside its quotes.
  bool split(std::string_view row) {
    fields_.clear();
    std::size_t begin = 0;
    for (std::size_t i = 0; i + 1 < columns_.count; ++i) {
      const std::size_t comma = row.find(',', begin);
      if (comma == std::string_view::npos) return false;
      fields_.push_back(row.substr(begin, comma - begin));
      if (fields_.back().find('"') != std::string_view::npos) return false;
      begin = comma + 1;
    }
    fields_.push_back(row.substr(begin));
    return true;
  }

  Columns columns_;
  const std::vector<double>& zetas_;
  std::vector<std::string_view> fields_;
};

std::string shortened(std::string_view line) {
  return line.size() <= kMaxQuotedLine ? std::string(line)
                                       : fmt::format("{}...", line.substr(0, kMaxQuotedLine));
}

[[noreturn]] void refuse(std::string_view resume_option, const std::filesystem::path& path, std::size_t line,
                         const std::string& why) {
  throw InvalidInput(fmt::format("{}: {}:{}: {}", resume_option, path.string(), line, why));
}

// The line number (1-based) of the line that starts at `offset`; for messages only.
std::size_t line_number_at(LineReader& lines, std::uint64_t offset) {
  std::size_t number = 1;
  for (std::uint64_t at = 0; at < offset; ++number) at += lines.at(at).length + 1;
  return number;
}

}  // namespace

std::string partial_header(const std::string& header) {
  return "index," + header + ",crc32";
}

void append_partial_line(std::string& out, std::size_t index, std::string_view row) {
  const std::size_t start = out.size();
  fmt::format_to(std::back_inserter(out), "{},", index);
  out += row;
  const std::array<char, kCrcDigits> crc = crc_text(std::string_view(out).substr(start));
  out += ',';
  out.append(crc.data(), crc.size());
  out += '\n';
}

std::optional<std::string_view> partial_line_row(std::string_view line) {
  if (line.size() < kCrcDigits + 1 || line[line.size() - kCrcDigits - 1] != ',') return std::nullopt;
  const std::string_view body = line.substr(0, line.size() - kCrcDigits - 1);
  const std::array<char, kCrcDigits> crc = crc_text(body);
  if (std::memcmp(crc.data(), line.data() + body.size() + 1, kCrcDigits) != 0) return std::nullopt;
  const std::size_t comma = body.find(',');
  if (comma == std::string_view::npos) return std::nullopt;
  return body.substr(comma + 1);
}

PartialSweep read_partial_sweep(LineReader& lines, const std::filesystem::path& path,
                                const std::string& settings, const std::string& header,
                                const std::vector<double>& zetas, std::string_view resume_option) {
  PartialSweep partial;
  const std::string header_line = partial_header(header);
  std::uint64_t offset = 0;
  std::size_t line_number = 0;
  for (const std::string* expected : {&settings, &header_line}) {
    const LineReader::Line line = lines.at(offset);
    ++line_number;
    // Cut off while the sweep started (a full disk): no row to keep, the file is written afresh.
    if (!line.complete && std::string_view(*expected).starts_with(line.text)) return partial;
    if (line.text == *expected) {
      offset += line.length + 1;
      continue;
    }
    if (line_number == 1) {
      refuse(resume_option, path, 1,
             fmt::format("written by another sweep ('{}', this one is '{}'): resume it with that sweep's "
                         "settings, or delete it to start this one",
                         shortened(line.text), settings));
    }
    if (line.text == header) {
      refuse(resume_option, path, 2,
             "written by an earlier version of restitution (rows without checksums): finish it with that "
             "version, or delete it to start afresh");
    }
    refuse(resume_option, path, 2, "its CSV header differs from this sweep's: delete it to start afresh");
  }

  partial.row_offset.assign(zetas.size(), PartialSweep::kNotDone);
  RowCheck valid(header, zetas);
  for (;;) {
    const LineReader::Line line = lines.at(offset);
    if (!line.complete) break;  // cut off while being written: computed again
    ++line_number;
    const std::uint64_t here = offset;
    offset += line.length + 1;
    std::size_t index = 0;
    bool failed = false;
    if (line.length != line.text.size() ||
        !valid(line.text, index, failed)) {  // a line held in part is no row
      ++partial.dropped;
      if (partial.first_dropped_line == 0) partial.first_dropped_line = line_number;
      continue;
    }
    std::uint64_t& first = partial.row_offset[index];
    if (first == PartialSweep::kNotDone) {
      first = here;
      ++partial.kept;
      if (failed) ++partial.failed;
      continue;
    }
    const std::string again(line.text);  // the next read reuses the view's bytes
    if (lines.at(first).text == again) {
      ++partial.duplicates;
      continue;
    }
    refuse(resume_option, path, line_number,
           fmt::format("point {} (zeta = {}) has two valid rows that differ, here and at line {}: keep the "
                       "one you trust, delete the other line, and run {} again",
                       index, number17(zetas[index]), line_number_at(lines, first), resume_option));
  }
  partial.valid_bytes = offset;
  return partial;
}

PartialSweep parse_partial_sweep(std::string_view text, const std::filesystem::path& path,
                                 const std::string& settings, const std::string& header,
                                 const std::vector<double>& zetas, std::string_view resume_option) {
  LineReader lines = LineReader::of_text(text);
  return read_partial_sweep(lines, path, settings, header, zetas, resume_option);
}

}  // namespace restitution
