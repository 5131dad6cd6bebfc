// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Pickled states of the module's value types: tuples of plain Python values.
#include <pybind11/pybind11.h>

#include <cstddef>

namespace restitution::python {

// ValueError unless `state` holds `size` items: a pickle from another version of the module, or a
// hand-made state, is refused with the type's name rather than read out of bounds.
void check_state(const pybind11::tuple& state, std::size_t size, const char* type);

}  // namespace restitution::python
