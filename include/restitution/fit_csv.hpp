// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The CSV of measured coefficients of restitution that `fit-data` and scenes' [[fit]] read (docs/fit.md):
// a header naming the speed, eps and optionally sigma columns (the usual spellings, any order, an optional
// leading index column), then one measurement per line; RFC 4180 quoting; CR, LF or CRLF line ends; lines
// starting with '#' and blank lines are skipped. The file is parsed as it is read: only the numbers are held,
// and the bounds below are checked while reading, so that a device or an endless stream is refused early.
#include <cstddef>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <string_view>

#include "restitution/fit.hpp"

namespace restitution {

struct FitCsvLimits {
  std::size_t max_bytes = std::size_t{256} << 20;  // the whole file, comments included
  std::size_t max_line_bytes = 4096;               // one line (and one quoted field)
  std::size_t max_rows = 1'000'000;                // measurements
};

// Where a file may come from. The command line takes any readable file (a pipe too: the bounds stop an
// endless one); a scene, a file received from someone else, reads regular files only (no device, FIFO,
// socket, nor a /proc or /sys entry, whose contents are the machine's, not data).
enum class FitCsvSource { any_readable, regular_file };

// Throws InvalidInput naming the file, the line and the column of the first bad field (not a decimal number,
// a number beyond the range of a double, v <= 0, eps outside (0, 1), sigma outside
// [kSmallestFitSigma, kLargestFitSigma], a missing or extra field, a broken quote), an unknown, ambiguous or
// missing column, a bound exceeded, a file that cannot be read or has no measurements. A message echoes at
// most 40 characters of the offending field, non-printable bytes escaped.
FitData read_fit_csv(const std::filesystem::path& path, FitCsvSource source = FitCsvSource::any_readable,
                     const FitCsvLimits& limits = {});
// The same for a stream or text already in memory; `name` is the file name the messages give.
FitData parse_fit_csv(std::istream& in, const std::string& name, const FitCsvLimits& limits = {});
FitData parse_fit_csv(const std::string& text, const std::string& name, const FitCsvLimits& limits = {});

// At most 40 characters of `text` for a message, bytes outside printable ASCII as \xNN, "..." when cut.
std::string quoted_excerpt(std::string_view text);

}  // namespace restitution
