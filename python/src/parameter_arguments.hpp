// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A study's table (restitution/parameter_table.hpp) as Python's keywords: the arguments the Python side
// checked (their types), by the table's names, read into the rows' members; and the table as rows
// (name, kind, unit) that the tests compare with the signature, the docstring and the .pyi.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "restitution/parameter_table.hpp"

namespace restitution::python {

// One argument into its row's member; None leaves the default. False for a number_or_word, whose reading is
// the study's own.
template <class Inputs>
bool read_parameter_argument(const ParameterField<Inputs>& f, const pybind11::handle& value, Inputs& in) {
  if (value.is_none()) return f.kind != FieldKind::number_or_word;
  switch (f.kind) {
    case FieldKind::optional_number:
      in.*f.optional_number = value.cast<double>();
      break;
    case FieldKind::number:
      in.*f.number = value.cast<double>();
      break;
    case FieldKind::whole_number:
      in.*f.whole_number = value.cast<int>();
      break;
    case FieldKind::word:
    case FieldKind::optional_word:
      in.*f.word = value.cast<std::string>();
      break;
    case FieldKind::flag:
      in.*f.flag = value.cast<bool>();
      break;
    case FieldKind::numbers:
      in.*f.numbers = value.cast<std::vector<double>>();
      break;
    case FieldKind::number_or_word:
      return false;
  }
  return true;
}

// The arguments (a dict by the table's names) into a study's inputs; `own(row, value, inputs)` reads what
// read_parameter_argument leaves. A name the table lacks is a TypeError, as Python words it for `function`.
template <class Inputs, class Own>
Inputs parameter_arguments(const pybind11::dict& arguments, const std::vector<ParameterField<Inputs>>& fields,
                           const char* function, Own&& own) {
  Inputs in;
  for (const auto& [key, value] : arguments) {
    const auto name = pybind11::cast<std::string>(key);
    const ParameterField<Inputs>* f = nullptr;
    try {
      f = &field_named(fields, name, function);
    } catch (const std::out_of_range&) {
      throw pybind11::type_error(std::string(function) + "() got an unexpected keyword argument '" + name +
                                 "'");
    }
    if (!read_parameter_argument(*f, value, in)) own(*f, value, in);
  }
  return in;
}

inline const char* parameter_kind_name(FieldKind kind) {
  switch (kind) {
    case FieldKind::optional_number:
      return "optional number";
    case FieldKind::number:
      return "number";
    case FieldKind::whole_number:
      return "whole number";
    case FieldKind::word:
      return "word";
    case FieldKind::optional_word:
      return "optional word";
    case FieldKind::number_or_word:
      return "number or word";
    case FieldKind::flag:
      return "flag";
    case FieldKind::numbers:
      return "numbers";
  }
  return "";
}

// The table as a front end reads it: (name, kind, unit, from_material) per row, in the table's order.
template <class Inputs>
pybind11::list parameter_rows(const std::vector<ParameterField<Inputs>>& fields) {
  pybind11::list rows;
  for (const ParameterField<Inputs>& f : fields) {
    rows.append(pybind11::make_tuple(f.name, parameter_kind_name(f.kind), f.unit, f.from_material));
  }
  return rows;
}

}  // namespace restitution::python
