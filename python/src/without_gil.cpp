// SPDX-License-Identifier: BSD-3-Clause
#include "without_gil.hpp"

#include <cxxabi.h>

#include <exception>

namespace restitution::python {

void run_without_gil(const std::function<void()>& work) {
  PyThreadState* const caller = PyEval_SaveThread();
  std::exception_ptr error;
  try {
    work();
  } catch (abi::__forced_unwind&) {
    throw;  // this thread is ending (briefly_with_gil at shutdown): it does not hold the GIL, must not take
            // it
  } catch (...) {
    error = std::current_exception();
  }
  PyEval_RestoreThread(caller);  // at shutdown this ends the thread: nothing below runs
  if (error) std::rethrow_exception(error);
}

void briefly_with_gil(PyThreadState* caller, const std::function<void()>& with_gil) {
  PyEval_RestoreThread(caller);  // at shutdown this ends the thread, as above
  try {
    with_gil();
  } catch (abi::__forced_unwind&) {
    throw;
  } catch (...) {
    PyEval_SaveThread();
    throw;
  }
  PyEval_SaveThread();
}

}  // namespace restitution::python
