// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The partial file of a sweep written to a file (FILE.partial; sweep_to_file, `restitution sweep`): what
// --resume trusts. Line 1 names the sweep's settings, line 2 is "index," + the CSV header + ",crc32", then
// one line per finished point in completion order: "INDEX,ROW,CRC", where ROW is the point's row of the final
// table and CRC the CRC-32 (IEEE, as zlib's crc32) of "INDEX,ROW" in 8 lowercase hex digits. A row carries
// its own integrity: a line cut off by a failed write, or joined to the next one, fails its checksum; every
// field is also parsed against the header.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sweep/line_reader.hpp"

namespace restitution {

// Line 2 of the partial file for a table with this CSV header.
std::string partial_header(const std::string& header);
// Appends "index,row,crc\n" to `out`.
void append_partial_line(std::string& out, std::size_t index, std::string_view row);
// The row of a line that append_partial_line wrote (the text between the index and the checksum); nothing
// when the line is not of that form or its checksum is wrong.
std::optional<std::string_view> partial_line_row(std::string_view line);

// The finished points of an interrupted sweep as its partial file holds them: where each valid row is, not
// the rows (a resumed sweep copies them from the file into the table when their turn comes).
struct PartialSweep {
  static constexpr std::uint64_t kNotDone = std::numeric_limits<std::uint64_t>::max();
  std::vector<std::uint64_t> row_offset;  // per grid point: the byte offset of its line, or kNotDone
  std::size_t kept = 0;                   // points with a valid row
  std::size_t failed = 0;                 // of which failed numerically
  std::size_t dropped = 0;             // complete lines dropped as damaged (their points are computed again)
  std::size_t first_dropped_line = 0;  // line number of the first of them (1-based), 0: none
  std::size_t duplicates = 0;          // exact repeats of a kept line, ignored
  // Length of the file up to its last complete line; 0: the file holds nothing to keep (empty, or only a
  // cut-off start of its first two lines) and is written afresh.
  std::uint64_t valid_bytes = 0;
};

// Reads a partial file written for the same settings line and CSV header, one line at a time. A row is kept
// when its checksum holds and every field parses as the header says (numbers as the table writes them, its
// ζ the grid's); any other line is dropped and its point computed again, as is a cut-off last line. An exact
// repeat of a kept line is ignored. Throws InvalidInput naming the file (and line) when the file belongs to
// another sweep, or when one point has two valid rows that differ. `path` names the file in messages, and
// `resume_option` what asked to resume (SweepFile::resume_option).
PartialSweep read_partial_sweep(LineReader& lines, const std::filesystem::path& path,
                                const std::string& settings, const std::string& header,
                                const std::vector<double>& zetas,
                                std::string_view resume_option = "--resume");
// The same on a file's text (tests, fuzzing).
PartialSweep parse_partial_sweep(std::string_view text, const std::filesystem::path& path,
                                 const std::string& settings, const std::string& header,
                                 const std::vector<double>& zetas,
                                 std::string_view resume_option = "--resume");

}  // namespace restitution
