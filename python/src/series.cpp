// SPDX-License-Identifier: BSD-3-Clause
// restitution.series: the recomputed series coefficients and the closed-form approximations by name.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <optional>
#include <span>
#include <string>

#include "bindings.hpp"
#include "restitution/errors.hpp"
#include "restitution_series_study/series_named.hpp"

namespace py = pybind11;

namespace restitution::python {
namespace {

using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

py::array_t<double> to_array(const std::vector<double>& values) {
  return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
}

// One array, or the tuple (a, b) for max-compression.
py::object coefficients(const std::string& kind, int count) {
  const auto lists = series::coefficients_by_kind(kind, count);
  if (lists.size() == 1) return to_array(lists[0].values);
  return py::make_tuple(to_array(lists[0].values), to_array(lists[1].values));
}

}  // namespace

void bind_series(py::module_& m) {
  m.attr("coefficient_kinds") = py::tuple(py::cast(series::coefficient_kinds()));
  m.attr("evaluation_kinds") = py::tuple(py::cast(series::evaluation_kinds()));
  m.def("coefficients", &coefficients, py::arg("kind"), py::arg("count"),
        "Recomputed series coefficients (natural units, zeta = beta v^(1/5)), rounded from __float128:\n"
        "  'naive': c_1..c_N of eps = 1 + sum c_k zeta^k (count N <= 60)\n"
        "  'delayed-recovery': h_0..h_N of eps = sum h_k zeta^(k/2) (N <= 120)\n"
        "  'max-compression': the tuple (a_1..a_N, b_0..b_N) of tau_max = tau_max0 + sum a_k zeta^k and\n"
        "  x_max = sum b_k zeta^k (N <= 60).\n"
        "Raises ValueError naming kind or count.");
  m.def(
      "eval",
      [](const std::string& kind, const DoubleArray& zeta, std::optional<int> terms, bool published) {
        if (zeta.size() == 0) throw InvalidInput("zeta is an empty array: give at least one value");
        const auto e = series::evaluate_by_kind(kind, std::span(zeta.data(), zeta.size()), terms, published);
        DoubleArray eps(std::vector<py::ssize_t>(zeta.shape(), zeta.shape() + zeta.ndim()));
        double* out = eps.mutable_data();
        for (const series::Value& v : e.values) *out++ = v.eps;
        return eps;
      },
      py::arg("kind"), py::arg("zeta"), py::arg("terms"), py::arg("published"),
      "eps of one series or approximation at every zeta of an array; same shape out.");
}

}  // namespace restitution::python
