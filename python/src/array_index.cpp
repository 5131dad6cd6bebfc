// SPDX-License-Identifier: BSD-3-Clause
#include "array_index.hpp"

#include <fmt/core.h>

#include <vector>

#include "restitution/errors.hpp"

namespace restitution::python {

std::string index_text(std::size_t flat_index, const pybind11::array& array) {
  if (array.ndim() <= 1) return fmt::format("index {}", flat_index);
  std::vector<std::size_t> index(static_cast<std::size_t>(array.ndim()));
  for (auto d = array.ndim(); d-- > 0;) {
    const auto extent = static_cast<std::size_t>(array.shape(d));
    index[static_cast<std::size_t>(d)] = flat_index % extent;
    flat_index /= extent;
  }
  std::string text = "index (";
  for (std::size_t d = 0; d < index.size(); ++d) text += fmt::format("{}{}", d > 0 ? ", " : "", index[d]);
  return text + ")";
}

void check_elements(const pybind11::array& array, const char* name,
                    const std::function<void(std::size_t)>& check) {
  const auto size = static_cast<std::size_t>(array.size());
  for (std::size_t i = 0; i < size; ++i) {
    try {
      check(i);
    } catch (const InvalidInput& e) {
      throw InvalidInput(fmt::format("{} ({} at {})", e.what(), name, index_text(i, array)));
    }
  }
}

}  // namespace restitution::python
