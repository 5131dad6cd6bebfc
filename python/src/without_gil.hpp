// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Library work with the GIL released, safe while the interpreter shuts down.
//
// When the interpreter is finalizing, CPython ends every other thread that asks for the GIL back with
// pthread_exit (3.11: in PyEval_RestoreThread). glibc implements that as a forced unwind
// (abi::__forced_unwind), which aborts the process ("terminate called without an active exception", rc 134)
// when it meets a noexcept frame - such as pybind11::gil_scoped_release's destructor, which takes the GIL
// back. A daemon thread inside a call at exit aborted that way 20 times in 20. Here the GIL is taken back
// in ordinary control flow, never in a destructor, so that thread's end unwinds through these frames as it
// does through numpy's C code; the work's own exceptions are rethrown once the GIL is held again.
#include <pybind11/pybind11.h>

#include <functional>
#include <optional>
#include <type_traits>
#include <utility>

namespace restitution::python {

// Runs work() with the GIL released and returns with it held (the thread may instead end there, see
// above). Must be called with the GIL held. work must not touch Python objects.
void run_without_gil(const std::function<void()>& work);

// run_without_gil returning work()'s result.
template <class Work>
auto without_gil(Work&& work) -> std::invoke_result_t<Work&> {
  using Result = std::invoke_result_t<Work&>;
  if constexpr (std::is_void_v<Result>) {
    run_without_gil(work);
  } else {
    std::optional<Result> result;
    run_without_gil([&] { result.emplace(work()); });
    return std::move(*result);
  }
}

// Inside run_without_gil's work: runs `with_gil` with the caller's thread state and the GIL taken back,
// then releases it again, in ordinary control flow for the same reason.
void briefly_with_gil(PyThreadState* caller, const std::function<void()>& with_gil);

}  // namespace restitution::python
