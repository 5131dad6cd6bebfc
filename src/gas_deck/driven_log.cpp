// SPDX-License-Identifier: BSD-3-Clause
#include "gas_deck/driven_log.hpp"

#include <fmt/core.h>

#include <array>
#include <string_view>

#include "gas_deck/gas_log_tokens.hpp"
#include "gas_deck/lammps_gas_deck.hpp"
#include "restitution/errors.hpp"
#include "sweep/line_reader.hpp"

namespace restitution::gas_deck {
namespace {

// The numbers of `fields` (keys in order) after the tag, or InvalidInput naming the place.
template <std::size_t N>
std::array<double, N> numbers_of(const std::vector<std::string_view>& tokens, std::size_t first,
                                 const std::array<std::string_view, N>& keys, const std::string& where) {
  if (tokens.size() != first + N)
    throw InvalidInput(fmt::format("{}: not the {} fields of the deck's line", where, N));
  std::array<double, N> out{};
  for (std::size_t k = 0; k < N; ++k) {
    const auto value = value_of(tokens[first + k], keys[k]);
    const auto number = value ? whole_number(*value) : std::nullopt;
    if (!number) throw InvalidInput(fmt::format("{}: field {} is not {}=NUMBER", where, first + k, keys[k]));
    out[k] = *number;
  }
  return out;
}

void read_line(std::string_view line, const std::string& where, DrivenLog& log) {
  const std::vector<std::string_view> tokens = split_tokens(line);
  if (tokens.empty()) return;
  if (tokens[0] == kDrivenSetupTag) {
    const auto v = numbers_of<3>(tokens, 1, {"bath_temperature_j", "bath_time_s", "steady_from_s"}, where);
    const DrivenBathLine bath{v[0], v[1], v[2]};
    if (log.bath &&
        (log.bath->bath_temperature_j != bath.bath_temperature_j ||
         log.bath->bath_time_s != bath.bath_time_s || log.bath->steady_from_s != bath.steady_from_s)) {
      throw InvalidInput(
          fmt::format("{}: a second bath, not the first's (two decks' runs in one log)", where));
    }
    log.bath = bath;
    return;
  }
  if (tokens[0] != kDrivenTag || tokens.size() < 2) return;
  const auto law = value_of(tokens[1], "law");
  if (!law || (*law != "viscoelastic" && *law != "constant-eps")) {
    throw InvalidInput(fmt::format("{}: law= must be viscoelastic or constant-eps", where));
  }
  const auto v = numbers_of<3>(tokens, 2, {"time_s", "mean_v2_m2_s2", "mean_v4_m4_s4"}, where);
  DrivenMoments* run = nullptr;
  for (DrivenMoments& r : log.runs) {
    if (r.law == *law) run = &r;
  }
  if (run == nullptr) run = &log.runs.emplace_back(DrivenMoments{std::string(*law), {}, {}, {}});
  if (!run->time_s.empty() && v[0] <= run->time_s.back()) return;  // a block that ran no step: printed twice
  run->time_s.push_back(v[0]);
  run->mean_v2_m2_s2.push_back(v[1]);
  run->mean_v4_m4_s4.push_back(v[2]);
}

}  // namespace

DrivenLog read_driven_log_file(const std::filesystem::path& path) {
  FileLines file(path);
  DrivenLog log;
  std::uint64_t offset = 0;
  for (std::size_t number = 1;; ++number) {
    const LineReader::Line line = file.lines().at(offset);
    if (!line.complete) break;  // the end, or a last line cut while being written
    offset += line.length + 1;
    std::string_view text = line.text;
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    if (text.substr(0, kDrivenTag.size()) != kDrivenTag) continue;
    read_line(text, fmt::format("{} line {}", path.string(), number), log);
  }
  return log;
}

}  // namespace restitution::gas_deck
