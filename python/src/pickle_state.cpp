// SPDX-License-Identifier: BSD-3-Clause
#include "pickle_state.hpp"

#include <fmt/core.h>

#include "restitution/errors.hpp"

namespace restitution::python {

void check_state(const pybind11::tuple& state, std::size_t size, const char* type) {
  if (state.size() != size)
    throw InvalidInput(fmt::format("cannot unpickle {}: its state has {} items, this module's has {}", type,
                                   state.size(), size));
}

}  // namespace restitution::python
