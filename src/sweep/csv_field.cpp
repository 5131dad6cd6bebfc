// SPDX-License-Identifier: BSD-3-Clause
#include "sweep/csv_field.hpp"

namespace restitution {

std::string quoted_field(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"') {
      out += "\"\"";
    } else {
      out += (c == '\n' || c == '\r') ? ' ' : c;
    }
  }
  return out + "\"";
}

}  // namespace restitution
