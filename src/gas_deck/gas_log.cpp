// SPDX-License-Identifier: BSD-3-Clause
#include "gas_deck/gas_log.hpp"

#include <fmt/core.h>
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <optional>
#include <utility>

#include "gas_deck/gas_log_tokens.hpp"
#include "restitution/errors.hpp"
#include "restitution/fit.hpp"
#include "sweep/line_reader.hpp"

namespace restitution::gas_deck {
namespace {

// One line the deck prints per scheduled time (lammps_gas_deck.cpp), its fields in this order.
struct Print {
  std::string_view law;
  double time_s = 0.0, temperature_j = 0.0, timestep_s = 0.0;
  std::uint64_t step = 0;
};

std::optional<Print> parse_print(std::string_view line) {
  const auto tokens = split_tokens(line);
  if (tokens.size() != 6 || tokens[0] != kGasTag) return std::nullopt;
  const auto law = value_of(tokens[1], "law");
  const auto number = [&](std::size_t i, std::string_view key) {
    const auto text = value_of(tokens[i], key);
    return text ? whole_number(*text) : std::nullopt;
  };
  const auto t = number(2, "time_s");
  const auto temperature = number(3, "temperature_j");
  const auto dt = number(4, "timestep_s");
  const auto step_text = value_of(tokens[5], "step");
  const auto step = step_text ? whole_count(*step_text) : std::nullopt;
  if (!law || law->empty() || !t || !temperature || !dt || !step) return std::nullopt;
  if (*t < 0.0 || !(*temperature > 0.0) || !(*dt > 0.0)) return std::nullopt;
  return Print{*law, *t, *temperature, *dt, *step};
}

bool known_law(std::string_view law) {
  return law == "viscoelastic" || law == "constant-eps";
}

bool starts_with(std::string_view line, std::string_view tag) {
  return line.size() > tag.size() && line.substr(0, tag.size()) == tag && line[tag.size()] == ' ';
}

// The curves of one log, fed line by line.
class GasLogParser {
 public:
  explicit GasLogParser(std::string source) : source_(std::move(source)) {}

  // `line` without its newline; `terminated`: a newline followed it; `whole`: it was not cut at the bound.
  void add(std::string_view line, std::size_t number, bool terminated, bool whole) {
    if (!whole) fail(number, "a line longer than 1 MiB: not a LAMMPS log", line);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);  // a log saved with CRLF line ends
    const bool setup = starts_with(line, kGasSetupTag);
    if (!setup && !starts_with(line, kGasTag)) return;  // LAMMPS's own output, the echoed input
    if (!terminated) {
      log_.notes.push_back(
          fmt::format("{}:{}: the last line is cut off (no newline: a run stopped while "
                      "printing?): left out",
                      source_, number));
      return;
    }
    if (setup) {
      add_setup(line, number);
    } else {
      add_print(line, number);
    }
  }

  GasLog finish() {
    for (std::size_t i = 0; i < repeats_.size(); ++i) {
      if (repeats_[i] == 0) continue;
      log_.notes.push_back(
          fmt::format("{}: {} repeated print(s) of the {} run (the same time, temperature and "
                      "step: a block that ran no step) counted once",
                      source_, repeats_[i], log_.curves[i].law));
    }
    return std::move(log_);
  }

 private:
  [[noreturn]] void fail(std::size_t number, std::string_view what, std::string_view line) const {
    throw InvalidInput(fmt::format("{}:{}: {}: '{}'", source_, number, what, quoted_excerpt(line)));
  }

  CoolingCurve* curve_of(std::string_view law) {
    const auto it = std::find_if(log_.curves.begin(), log_.curves.end(),
                                 [&](const CoolingCurve& c) { return c.law == law; });
    return it == log_.curves.end() ? nullptr : &*it;
  }

  void add_setup(std::string_view line, std::size_t number) {
    const auto setup = parse_gas_log_setup(line);
    if (!setup) {
      fail(number,
           fmt::format("a {} line without the fields the deck prints (law, end, then {} numbers)",
                       kGasSetupTag, kGasLogSetupFields.size()),
           line);
    }
    if (!known_law(setup->law))
      fail(number, fmt::format("a run of law '{}': neither viscoelastic nor constant-eps", setup->law), line);
    if (const CoolingCurve* earlier = curve_of(setup->law)) {
      fail(number,
           fmt::format("a second run of the {} gas begins here (the first began at line {}): give each run's "
                       "log once, not appended to another",
                       setup->law, setup_lines_[static_cast<std::size_t>(earlier - log_.curves.data())]),
           line);
    }
    log_.curves.push_back({setup->law, source_, {}, {}, {}, *setup});
    setup_lines_.push_back(number);
    repeats_.push_back(0);
    last_step_.push_back(0);
  }

  void add_print(std::string_view line, std::size_t number) {
    const auto print = parse_print(line);
    if (!print) {
      fail(number,
           fmt::format("a {} line without law, time_s >= 0, temperature_j > 0, timestep_s > 0 and step, each "
                       "a whole number (a garbled or half-written line)",
                       kGasTag),
           line);
    }
    if (!known_law(print->law))
      fail(number, fmt::format("a run of law '{}': neither viscoelastic nor constant-eps", print->law), line);
    CoolingCurve* curve = curve_of(print->law);
    if (curve == nullptr) {
      fail(number,
           fmt::format("a print of the {} run before its {} line (a deck written by an older version: write "
                       "the deck again and run it)",
                       print->law, kGasSetupTag),
           line);
    }
    const auto i = static_cast<std::size_t>(curve - log_.curves.data());
    if (!curve->time_s.empty() && !(print->time_s > curve->time_s.back())) {
      if (print->time_s == curve->time_s.back() && print->temperature_j == curve->temperature_j.back() &&
          print->step == last_step_[i]) {
        ++repeats_[i];
        return;
      }
      fail(number,
           fmt::format("time_s is not after the {} s of line {}: a second run appended to this log?",
                       curve->time_s.back(), curve->line.back()),
           line);
    }
    if (curve->time_s.size() >= kMostGasLogPrints)
      fail(number, fmt::format("more than {} prints of one run: not a deck's log", kMostGasLogPrints), line);
    curve->time_s.push_back(print->time_s);
    curve->temperature_j.push_back(print->temperature_j);
    curve->line.push_back(number);
    last_step_[i] = print->step;
  }

  std::string source_;
  GasLog log_;
  std::vector<std::size_t> setup_lines_, repeats_;
  std::vector<std::uint64_t> last_step_;
};

GasLog read_lines(LineReader& lines, const std::string& source) {
  GasLogParser parser(source);
  std::uint64_t offset = 0;
  for (std::size_t number = 1;; ++number) {
    const LineReader::Line line = lines.at(offset);
    if (!line.complete && line.length == 0) break;  // the end of the data
    parser.add(line.text, number, line.complete, line.length == line.text.size());
    if (!line.complete) break;
    offset += line.length + 1;
  }
  return parser.finish();
}

}  // namespace

GasLog read_gas_log(std::string_view text, const std::string& source) {
  LineReader lines = LineReader::of_text(text);
  return read_lines(lines, source);
}

GasLog read_gas_log_file(const std::filesystem::path& path) {
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0) {
    if (errno == ENOENT || errno == ENOTDIR)
      throw InvalidInput(fmt::format("--compare: no file '{}'", quoted_excerpt(path.string())));
    throw IoError(
        fmt::format("--compare: cannot read '{}': {}", quoted_excerpt(path.string()), std::strerror(errno)));
  }
  if (!S_ISREG(status.st_mode)) {
    throw InvalidInput(
        fmt::format("--compare: '{}' is not a regular file (a folder, FIFO or device): give "
                    "the log file of a run",
                    quoted_excerpt(path.string())));
  }
  FileLines file(path);
  return read_lines(file.lines(), path.string());
}

LocalExponent local_exponent(const std::vector<double>& time_s, const std::vector<double>& temperature_j) {
  LocalExponent e;
  for (std::size_t i = 1; i < time_s.size(); ++i) {
    if (!(time_s[i - 1] > 0.0) || !(time_s[i] > time_s[i - 1])) continue;
    e.time_s.push_back(std::sqrt(time_s[i - 1] * time_s[i]));
    e.exponent.push_back(std::log(temperature_j[i] / temperature_j[i - 1]) /
                         std::log(time_s[i] / time_s[i - 1]));
  }
  return e;
}

}  // namespace restitution::gas_deck
