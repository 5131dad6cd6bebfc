// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Reading back what a driven gas's deck (gas_deck/lammps_gas_deck.hpp, a DeckBath) printed beside its
// temperature lines (read by gas_deck/gas_log.hpp): its bath (kDrivenSetupTag) and the speed's second and
// fourth moments at each scheduled time (kDrivenTag), per law. Strict as gas_log.hpp: every field of a line
// present, in order, each number the whole token; a line cut by the end of the file is left out.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace restitution::gas_deck {

struct DrivenBathLine {
  double bath_temperature_j = 0.0, bath_time_s = 0.0, steady_from_s = 0.0;
};

struct DrivenMoments {
  std::string law;  // "viscoelastic" | "constant-eps"
  std::vector<double> time_s;
  std::vector<double> mean_v2_m2_s2, mean_v4_m4_s4;  // ⟨v²⟩ and ⟨v⁴⟩ over the spheres
};

struct DrivenLog {
  std::optional<DrivenBathLine> bath;  // none: the log of a freely cooling gas
  std::vector<DrivenMoments> runs;     // in order of first appearance
};

// Throws InvalidInput naming the file and line for a driven line without its fields, or with a field that is
// not a number, or two bath lines that differ; IoError when the file cannot be read (read_gas_log_file has
// checked that it is a regular file).
DrivenLog read_driven_log_file(const std::filesystem::path& path);

}  // namespace restitution::gas_deck
