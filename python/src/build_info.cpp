// SPDX-License-Identifier: BSD-3-Clause
// restitution.build_info(): which build of the library and of SUNDIALS this module runs, as the command
// line's --version and every JSON output say it (a CVODE solve costs 2-3x more on Debian's unoptimized
// SUNDIALS; the numbers are the same).
#include "bindings.hpp"
#include "restitution/restitution.hpp"

namespace py = pybind11;

namespace restitution::python {

void bind_build_info(py::module_& m) {
  m.def(
      "build_info",
      [] {
        const SundialsBuild build = sundials_build();
        py::dict sundials;
        sundials["version"] = build.version;
        sundials["optimized"] = build.optimized;
        sundials["description"] = sundials_build_description();
        py::dict info;
        info["version"] = RESTITUTION_VERSION;
        info["sundials"] = sundials;
        return info;
      },
      "The module's version and its SUNDIALS build (version, optimized, description).");
}

}  // namespace restitution::python
