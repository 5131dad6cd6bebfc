// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Error messages that name the element of an array argument.
#include <pybind11/numpy.h>

#include <cstddef>
#include <functional>
#include <string>

namespace restitution::python {

// "index 7" for a 1-d array, "index (1, 3)" for a C-ordered array of higher rank.
std::string index_text(std::size_t flat_index, const pybind11::array& array);

// Runs check(i) for every element i in C order; an InvalidInput it throws is rethrown with
// " (<name> at <index>)" appended, so that the message names both the value and its place.
void check_elements(const pybind11::array& array, const char* name,
                    const std::function<void(std::size_t)>& check);

}  // namespace restitution::python
