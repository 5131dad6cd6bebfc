// SPDX-License-Identifier: BSD-3-Clause
// restitution.fast: the library's certified fast table (restitution/fast.hpp) for one value or an array.
#include "restitution/fast.hpp"

#include <fmt/core.h>
#include <pybind11/numpy.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "array_index.hpp"
#include "bindings.hpp"
#include "restitution/calibration.hpp"
#include "restitution/contact_law.hpp"
#include "restitution/errors.hpp"
#include "without_gil.hpp"

namespace py = pybind11;

namespace restitution::python {
namespace {

using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;
using FastFunction = double (*)(double, CollisionEnd);

// Applies f to every element with the GIL released (a table lookup each: no thread pool). The first
// InvalidInput stops the loop and comes back, with the GIL held, naming the element's index.
DoubleArray apply(FastFunction f, const DoubleArray& in, const std::string& end, const char* name) {
  const CollisionEnd which = end_from_name(end);
  if (in.size() == 0) throw InvalidInput(fmt::format("{} is an empty array: give at least one value", name));
  DoubleArray out(std::vector<py::ssize_t>(in.shape(), in.shape() + in.ndim()));
  const double* x = in.data();
  double* y = out.mutable_data();
  const auto size = static_cast<std::size_t>(in.size());
  std::optional<std::size_t> bad;
  std::string message;
  run_without_gil([&] {
    for (std::size_t i = 0; i < size; ++i) {
      try {
        y[i] = f(x[i], which);
      } catch (const InvalidInput& e) {
        bad = i;
        message = e.what();
        break;
      }
    }
  });
  if (bad) throw InvalidInput(fmt::format("{} ({} at {})", message, name, index_text(*bad, in)));
  return out;
}

void def_pair(py::module_& m, const char* name, FastFunction f, const char* argument, const char* doc) {
  m.def(
      name, [f](double x, const std::string& end) { return f(x, end_from_name(end)); }, py::arg(argument),
      py::arg("end"), doc);
  m.def((std::string(name) + "_array").c_str(),
        [f, argument](const DoubleArray& x, const std::string& end) { return apply(f, x, end, argument); },
        py::arg(argument), py::arg("end"), doc);
}

// Python applies the domain of every front end (docs/accuracy.md): ζ = 0 or in [kSmallestServedZeta,
// kLargestCheckedZeta], refused outside in the CLI's words, where the library's fast functions go on (the
// large-ζ laws, the subnormal 1 - ε) for embedding. Negative and NaN ζ are left to the fast functions' own
// messages.
void require_in_domain(double zeta) {
  if (zeta > kLargestCheckedZeta) require_checked_zeta(zeta);
  require_served_zeta(zeta);
}
double checked_eps(double zeta, CollisionEnd end) {
  require_in_domain(zeta);
  return fast::eps(zeta, end);
}
double checked_one_minus_eps(double zeta, CollisionEnd end) {
  require_in_domain(zeta);
  return fast::one_minus_eps(zeta, end);
}
double checked_collision_duration(double zeta, CollisionEnd end) {
  require_in_domain(zeta);
  return fast::collision_duration(zeta, end);
}
MaxCompression checked_max_compression(double zeta) {
  require_in_domain(zeta);
  return fast::max_compression(zeta);
}

// The maximal compression's two numbers as FastFunctions (it has no end), for apply().
double max_compression_tau(double zeta, CollisionEnd /*end*/) {
  return checked_max_compression(zeta).tau;
}
double max_compression_x(double zeta, CollisionEnd /*end*/) {
  return checked_max_compression(zeta).x;
}

}  // namespace

void bind_fast(py::module_& m) {
  def_pair(m, "eps", &checked_eps, "zeta",
           "eps(zeta) from the certified fast table; 0 <= zeta <= 1e6 natural units.");
  def_pair(m, "one_minus_eps", &checked_one_minus_eps, "zeta",
           "1 - eps(zeta) to its own relative accuracy; 0 <= zeta <= 1e6 natural units.");
  def_pair(m, "zeta_from_eps", &fast_zeta_for_eps, "eps",
           "zeta (natural units) with eps(zeta) = eps in (0, 1], refused below eps(1e6).");
  def_pair(m, "collision_duration", &checked_collision_duration, "zeta",
           "collision duration tau_c (natural units) at 0 <= zeta <= 1e6, from the fast table and its "
           "large-zeta law.");
  const char* compression =
      "(tau_max, x_max), natural units, at 0 <= zeta <= 1e6, from the fast table and its laws.";
  m.def(
      "max_compression",
      [](double zeta) {
        const MaxCompression c = checked_max_compression(zeta);
        return py::make_tuple(c.tau, c.x);
      },
      py::arg("zeta"), compression);
  m.def(
      "max_compression_array",
      [](const DoubleArray& zeta) {
        return py::make_tuple(apply(&max_compression_tau, zeta, "delayed-recovery", "zeta"),
                              apply(&max_compression_x, zeta, "delayed-recovery", "zeta"));
      },
      py::arg("zeta"), compression);
}

}  // namespace restitution::python
