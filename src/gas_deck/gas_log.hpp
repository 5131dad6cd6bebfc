// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Reading back what a gas deck (gas_deck/lammps_gas_deck.hpp) printed: LAMMPS's screen output or log file,
// the lines starting with kGasTag (one cooling curve per law) and the kGasSetupTag line that opens each run
// (gas_deck/gas_log_setup.hpp). The reader is strict, since a garbled log must not become numbers: every
// line of the deck holds exactly the fields the deck prints, each number the whole token; times increase
// within a run. A file is streamed line by line (memory bounded whatever its size).
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "gas_deck/gas_log_setup.hpp"

namespace restitution::gas_deck {

// A run holds at most this many prints (a deck prints points_per_decade <= 100 per decade of time): more is
// not a deck's log, and refused before the points fill the memory.
inline constexpr std::size_t kMostGasLogPrints = 100000;

struct CoolingCurve {
  std::string law;     // "viscoelastic" | "constant-eps"
  std::string source;  // where it was read (a log file's name)
  std::vector<double> time_s, temperature_j;
  std::vector<std::size_t> line;  // the 1-based line of each point in the log
  GasLogSetup setup;              // from the run's kGasSetupTag line
};

struct GasLog {
  std::vector<CoolingCurve> curves;  // in order of first appearance (a log may hold both laws' runs)
  std::vector<std::string> notes;    // what was left out and why: a cut last line, a repeated print
};

// The curves in `text`, named `source` in messages. Lines that are not the deck's are skipped (LAMMPS echoes
// the input: a `print` command itself is not a line the deck printed); a CR before the newline is dropped.
// Throws InvalidInput naming `source` and the line for: a deck's line without all its fields or with a field
// that is not a number; a law other than viscoelastic and constant-eps; a data line before its run's setup
// line; a second run of one law (two logs appended); a time not after the previous one (unless the same
// print repeated, which is left out with a note); more than kMostGasLogPrints points; a line longer than
// 1 MiB. A deck's line cut by the end of the text (no newline) is left out with a note.
GasLog read_gas_log(std::string_view text, const std::string& source);

// The same for a file, streamed. Throws InvalidInput naming the option --compare for a file that does not
// exist or is not a regular file (a FIFO, a device, a folder), IoError when it cannot be read.
GasLog read_gas_log_file(const std::filesystem::path& path);

// The local exponent d ln T / d ln t at the midpoints of consecutive points (t > 0), geometric mean times.
struct LocalExponent {
  std::vector<double> time_s, exponent;
};
LocalExponent local_exponent(const std::vector<double>& time_s, const std::vector<double>& temperature_j);

}  // namespace restitution::gas_deck
