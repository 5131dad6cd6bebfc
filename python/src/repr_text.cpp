// SPDX-License-Identifier: BSD-3-Clause
#include "repr_text.hpp"

#include <fmt/core.h>

namespace restitution::python {

std::string optional_text(const std::optional<double>& x, const char* unit) {
  return x ? fmt::format("{} {}", *x, unit) : std::string("None");
}

}  // namespace restitution::python
