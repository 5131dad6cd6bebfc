// SPDX-License-Identifier: BSD-3-Clause
// The library's typed errors as Python exceptions: InvalidInput -> ValueError, NumericalFailure -> the
// ArithmeticError subclass NumericalFailure (exported as restitution.NumericalFailure).
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "restitution/errors.hpp"

namespace restitution::python {

void bind_errors(pybind11::module_& m) {
  static pybind11::exception<NumericalFailure> numerical_failure(m, "NumericalFailure",
                                                                 PyExc_ArithmeticError);
  numerical_failure.doc() =
      "The solver could not deliver the requested accuracy; the message names the parameter, the end, the "
      "tolerance, the solver's flag and, for arrays, the index. A subclass of ArithmeticError.";
  // pybind11 takes a plain function pointer of exactly this signature.
  pybind11::register_exception_translator(
      [](std::exception_ptr p) {  // NOLINT(performance-unnecessary-value-param)
        try {
          if (p) std::rethrow_exception(p);
        } catch (const InvalidInput& e) {
          PyErr_SetString(PyExc_ValueError, e.what());
        } catch (const NumericalFailure& e) {
          numerical_failure(e.what());
        }
      });
}

}  // namespace restitution::python
