// SPDX-License-Identifier: BSD-3-Clause
#include "sweep/physical_columns.hpp"

namespace restitution {

const std::vector<std::string>& velocity_columns() {
  static const std::vector<std::string> columns = {"velocity_m_s", "beta"};
  return columns;
}

std::string duration_column(CollisionEnd end) {
  return std::string(end_key(end)) + "_duration_s";
}

const std::vector<std::string>& si_max_compression_columns() {
  static const std::vector<std::string> columns = {"max_compression_time_s", "max_compression_m"};
  return columns;
}

double duration_s(const EndResult& end, const NaturalScales& scales) {
  return end.tau * scales.time_s;
}

std::vector<double> si_max_compression(const MaxCompression& m, const NaturalScales& scales) {
  return {m.tau * scales.time_s, m.x * scales.length_m};
}

}  // namespace restitution
