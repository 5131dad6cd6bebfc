// SPDX-License-Identifier: BSD-3-Clause
// eps and solve: one collision or an array of them, with the library's result types as Python classes.
#include <fmt/core.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "array_index.hpp"
#include "bindings.hpp"
#include "parallel_solve.hpp"
#include "pickle_state.hpp"
#include "restitution/contact_law.hpp"
#include "restitution/errors.hpp"
#include "restitution/sweep.hpp"
#include "restitution/units.hpp"
#include "solve_options.hpp"
#include "without_gil.hpp"

namespace py = pybind11;

namespace restitution::python {
namespace {

using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

// One solver per Python thread, kept between calls: building a solver allocates CVODE's memory, which
// would cost more than a Taylor solve.
CollisionSolver& thread_solver() {
  thread_local CollisionSolver solver;
  return solver;
}

// The law's natural form at ζ, in the checked range (the same contract as the command line).
ContactLaw natural_law(const std::string& law, double zeta) {
  const ContactLaw natural = ContactLaw::natural(law_from_name(law), zeta);
  require_checked_zeta(zeta);
  return natural;
}

CollisionResult solve_one(const std::string& law, double zeta, const SolveOptions& options) {
  const ContactLaw natural = natural_law(law, zeta);
  return without_gil([&] { return thread_solver().solve(natural, options); });
}

// solve(end="both"): each end as eps() computes it, so that the two agree to the last digit. One solve of
// both ends plans its tolerances and method for both (the delayed-recovery eps then differs from the
// one-end solve in the 12th digit, both inside the tolerance); two one-end solves cost 1.2-1.8x the one solve
// and give one answer. The naive end's solve, which runs through the whole collision, gives the maximal
// compression, the method and the trajectory; the statistics are the sum of both solves.
CollisionResult solve_both_ends(const std::string& law, double zeta, SolveOptions options) {
  options.ends = EndSet{CollisionEnd::naive};  // refused, in the library's words, where it does not exist
  CollisionResult result = solve_one(law, zeta, options);
  options.ends = EndSet{CollisionEnd::delayed_recovery};
  options.keep_trajectory = false;
  const CollisionResult delayed = solve_one(law, zeta, options);
  result[CollisionEnd::delayed_recovery] = delayed[CollisionEnd::delayed_recovery];
  result.stats += delayed.stats;
  return result;
}

double eps_scalar(double zeta, const std::string& end, double tolerance, const std::string& method,
                  const std::string& law) {
  const SolveOptions options = solve_options(end, tolerance, method, false);
  return end_of(solve_one(law, zeta, options), end_from_name(end)).eps;
}

DoubleArray eps_array(const DoubleArray& zeta, const std::string& end, double tolerance,
                      const std::string& method, const std::string& law, unsigned threads,
                      const py::object& progress) {
  const SolveOptions options = solve_options(end, tolerance, method, false);
  const LawKind kind = law_from_name(law);
  const CollisionEnd which = end_from_name(end);
  if (zeta.size() == 0) throw InvalidInput("zeta is an empty array: give at least one value");
  const double* in = zeta.data();
  // The refusals that depend on ζ, checked before the sweep so that the message can name the index.
  check_elements(zeta, "zeta",
                 [in, &options, &law](std::size_t i) { check_solvable(natural_law(law, in[i]), options); });
  const std::vector<double> zetas(in, in + zeta.size());
  DoubleArray eps(std::vector<py::ssize_t>(zeta.shape(), zeta.shape() + zeta.ndim()));
  double* out = eps.mutable_data();
  const auto failure = parallel_solve(
      kind, zetas, options, threads,
      [out, which](std::size_t i, const CollisionResult& r) { out[i] = end_of(r, which).eps; }, progress);
  if (failure) {
    throw NumericalFailure(
        fmt::format("{} (zeta at {})", failure->message, index_text(failure->index, zeta)));
  }
  return eps;
}

DoubleArray zetas_from(const DoubleArray& beta, const DoubleArray& velocity) {
  if (beta.size() != velocity.size()) throw InvalidInput("beta and velocity must have the same size");
  const double* b = beta.data();
  const double* v = velocity.data();
  DoubleArray zeta(std::vector<py::ssize_t>(beta.shape(), beta.shape() + beta.ndim()));
  double* out = zeta.mutable_data();
  check_elements(beta, "beta, velocity", [=](std::size_t i) { out[i] = zeta_from(b[i], v[i]); });
  return zeta;
}

py::array_t<double> column(const std::vector<TrajectoryPoint>& points, double TrajectoryPoint::*field) {
  py::array_t<double> values(static_cast<py::ssize_t>(points.size()));
  double* out = values.mutable_data();
  for (const TrajectoryPoint& p : points) *out++ = p.*field;
  return values;
}

// Reprs: every field, in natural units (x'(0) = 1) as the docstrings say, shortest round-trip digits.
std::string end_repr(const EndResult& e) {
  return fmt::format(
      "EndResult(eps={}, one_minus_eps={}, tau={}, x={}, velocity={}, dissipated_energy={}; natural units)",
      e.eps, e.one_minus_eps, e.tau, e.x, e.velocity, e.dissipated_energy);
}

std::string max_compression_repr(const MaxCompression& c) {
  return fmt::format("MaxCompression(tau={}, x={}; natural units)", c.tau, c.x);
}

std::string stats_repr(const SolverStats& s) {
  return fmt::format(
      "SolverStats(steps={}, rhs_evaluations={}, jacobian_evaluations={}, root_evaluations={}, "
      "error_test_failures={}, convergence_failures={})",
      s.steps, s.rhs_evaluations, s.jacobian_evaluations, s.root_evaluations, s.error_test_failures,
      s.convergence_failures);
}

std::string result_repr(const CollisionResult& r) {
  std::string ends;
  for (const CollisionEnd end : kCollisionEnds)
    ends += fmt::format(", {}={}", end_key(end), r[end] ? end_repr(*r[end]) : "None");
  return fmt::format(
      "CollisionResult(law='{}', zeta={}, tolerance={}, method='{}', max_compression={}{}, {}, "
      "trajectory={} points)",
      law_name(r.law), r.parameter, r.tolerance, method_name(r.method),
      max_compression_repr(r.max_compression), ends, stats_repr(r.stats), r.trajectory.size());
}

// Pickling (multiprocessing, joblib, dask): each type's state is a tuple of plain Python values, the
// enumerations by name, so that a pickle does not depend on the order of the library's enums.
py::tuple end_state(const EndResult& e) {
  return py::make_tuple(e.eps, e.one_minus_eps, e.tau, e.x, e.velocity, e.dissipated_energy);
}

EndResult end_from_state(const py::tuple& t) {
  check_state(t, 6, "EndResult");
  return EndResult{t[0].cast<double>(), t[1].cast<double>(), t[2].cast<double>(),
                   t[3].cast<double>(), t[4].cast<double>(), t[5].cast<double>()};
}

py::tuple max_compression_state(const MaxCompression& c) {
  return py::make_tuple(c.tau, c.x);
}

MaxCompression max_compression_from_state(const py::tuple& t) {
  check_state(t, 2, "MaxCompression");
  return MaxCompression{t[0].cast<double>(), t[1].cast<double>()};
}

py::tuple stats_state(const SolverStats& s) {
  return py::make_tuple(s.steps, s.rhs_evaluations, s.jacobian_evaluations, s.root_evaluations,
                        s.error_test_failures, s.convergence_failures);
}

SolverStats stats_from_state(const py::tuple& t) {
  check_state(t, 6, "SolverStats");
  return SolverStats{t[0].cast<long>(), t[1].cast<long>(), t[2].cast<long>(),
                     t[3].cast<long>(), t[4].cast<long>(), t[5].cast<long>()};
}

py::tuple result_state(const CollisionResult& r) {
  py::list ends;
  for (const CollisionEnd end : kCollisionEnds)
    ends.append(r[end] ? py::object(end_state(*r[end])) : py::none());
  py::list trajectory;
  for (const TrajectoryPoint& p : r.trajectory)
    trajectory.append(py::make_tuple(p.tau, p.x, p.velocity, p.acceleration));
  return py::make_tuple(law_name(r.law), r.parameter, r.speed_independent, r.tolerance, method_name(r.method),
                        max_compression_state(r.max_compression), stats_state(r.stats), py::tuple(ends),
                        trajectory);
}

CollisionResult result_from_state(const py::tuple& t) {
  check_state(t, 9, "CollisionResult");
  CollisionResult r;
  r.law = law_from_name(t[0].cast<std::string>());
  r.parameter = t[1].cast<double>();
  r.speed_independent = t[2].cast<bool>();
  r.tolerance = t[3].cast<double>();
  r.method = method_from_name(t[4].cast<std::string>());
  r.max_compression = max_compression_from_state(t[5].cast<py::tuple>());
  r.stats = stats_from_state(t[6].cast<py::tuple>());
  const auto ends = t[7].cast<py::tuple>();
  check_state(ends, kCollisionEnds.size(), "CollisionResult's ends");
  for (std::size_t i = 0; i < kCollisionEnds.size(); ++i)
    if (!ends[i].is_none()) r[kCollisionEnds[i]] = end_from_state(ends[i].cast<py::tuple>());
  for (const py::handle point : t[8].cast<py::list>()) {
    const auto p = point.cast<py::tuple>();
    check_state(p, 4, "a trajectory point");
    r.trajectory.push_back(
        {p[0].cast<double>(), p[1].cast<double>(), p[2].cast<double>(), p[3].cast<double>()});
  }
  return r;
}

void bind_result_types(py::module_& m) {
  py::class_<EndResult>(m, "EndResult", "One end of the collision; times and lengths in natural units.")
      .def_readonly("eps", &EndResult::eps, "Coefficient of restitution eps = -x'(tau_c)/x'(0).")
      .def_readonly("one_minus_eps", &EndResult::one_minus_eps, "1 - eps, without cancellation as eps -> 1.")
      .def_readonly("tau", &EndResult::tau, "Duration of the collision tau_c (natural units).")
      .def_readonly("x", &EndResult::x, "Compression at the end (0 at the naive end; natural units).")
      .def_readonly("velocity", &EndResult::velocity, "x'(tau_c) as integrated (natural units).")
      .def_readonly("dissipated_energy", &EndResult::dissipated_energy,
                    "Energy dissipated up to tau_c (natural units: the initial kinetic energy is 1/2).")
      .def("__repr__", &end_repr)
      .def(py::pickle(&end_state, &end_from_state));
  py::class_<MaxCompression>(m, "MaxCompression", "The point of maximal compression (natural units).")
      .def_readonly("tau", &MaxCompression::tau, "Time of maximal compression.")
      .def_readonly("x", &MaxCompression::x, "Maximal compression.")
      .def("__repr__", &max_compression_repr)
      .def(py::pickle(&max_compression_state, &max_compression_from_state));
  py::class_<SolverStats>(m, "SolverStats", "Work done by the integrator, summed over the phases of a solve.")
      .def_readonly("steps", &SolverStats::steps)
      .def_readonly("rhs_evaluations", &SolverStats::rhs_evaluations)
      .def_readonly("jacobian_evaluations", &SolverStats::jacobian_evaluations)
      .def_readonly("root_evaluations", &SolverStats::root_evaluations)
      .def_readonly("error_test_failures", &SolverStats::error_test_failures)
      .def_readonly("convergence_failures", &SolverStats::convergence_failures)
      .def("__repr__", &stats_repr)
      .def(py::pickle(&stats_state, &stats_from_state));
  py::class_<CollisionResult>(m, "CollisionResult",
                              "One collision: both ends (or the one asked for), the maximal compression, the "
                              "solver's statistics and, if asked for, the trajectory. Natural units.")
      .def_readonly("zeta", &CollisionResult::parameter,
                    "The law's parameter: zeta = beta v^(1/5) (natural units), or the damping ratio r for "
                    "the linear dash-pot.")
      .def_property_readonly(
          "law", [](const CollisionResult& r) { return law_name(r.law); }, "The contact law's name.")
      .def_readonly("tolerance", &CollisionResult::tolerance, "Requested accuracy of eps.")
      .def_property_readonly(
          "method", [](const CollisionResult& r) { return method_name(r.method); },
          "The method actually used: bdf, adams or taylor.")
      .def_readonly("max_compression", &CollisionResult::max_compression)
      .def_property_readonly(
          "naive", [](const CollisionResult& r) { return r[CollisionEnd::naive]; },
          "The naive end (x = 0), or None if not asked for.")
      .def_property_readonly(
          "delayed_recovery", [](const CollisionResult& r) { return r[CollisionEnd::delayed_recovery]; },
          "The delayed-recovery end (force = 0), or None if not asked for.")
      .def_readonly("stats", &CollisionResult::stats)
      .def_property_readonly(
          "has_trajectory", [](const CollisionResult& r) { return !r.trajectory.empty(); },
          "True when solved with trajectory=True.")
      .def_property_readonly(
          "tau", [](const CollisionResult& r) { return column(r.trajectory, &TrajectoryPoint::tau); },
          "Trajectory times tau (natural units); empty unless trajectory=True.")
      .def_property_readonly(
          "x", [](const CollisionResult& r) { return column(r.trajectory, &TrajectoryPoint::x); },
          "Trajectory compression x(tau) (natural units); empty unless trajectory=True.")
      .def_property_readonly(
          "velocity",
          [](const CollisionResult& r) { return column(r.trajectory, &TrajectoryPoint::velocity); },
          "Trajectory x'(tau) (natural units); empty unless trajectory=True.")
      .def_property_readonly(
          "acceleration",
          [](const CollisionResult& r) { return column(r.trajectory, &TrajectoryPoint::acceleration); },
          "Trajectory x''(tau) (natural units); empty unless trajectory=True.")
      .def("__repr__", &result_repr)
      .def(py::pickle(&result_state, &result_from_state));
}

}  // namespace

void bind_collision(py::module_& m) {
  bind_result_types(m);
  m.def("eps_scalar", &eps_scalar, py::arg("zeta"), py::arg("end"), py::arg("tolerance"), py::arg("method"),
        py::arg("law"), "eps at one zeta (natural units), end naive or delayed-recovery.");
  m.def(
      "eps_array", &eps_array, py::arg("zeta"), py::arg("end"), py::arg("tolerance"), py::arg("method"),
      py::arg("law"), py::arg("threads"), py::arg("progress") = py::none(),
      "eps at every zeta of an array, on `threads` threads (0: all cores) with the GIL released; same shape "
      "out. progress: None or callable(done, total), called a few times a second and at the end.");
  m.attr("law_names") = law_names();
  m.def(
      "has_dissipative_constant",
      [](const std::string& law) { return has_dissipative_constant(law_from_name(law)); }, py::arg("law"),
      "Whether beta, a Material and the dissipative constant A describe the law (viscoelastic Hertz).");
  m.attr("default_tolerance") = kDefaultTolerance;
  m.attr("largest_checked_zeta") = kLargestCheckedZeta;
  m.attr("max_threads") = kMaxSweepThreads;  // as the command line's --threads
  m.def("require_checked_zeta", &require_checked_zeta, py::arg("zeta"),
        "ValueError unless 0 <= zeta <= 1e6 (the checked range).");
  m.def("zeta_from", &zeta_from, py::arg("beta"), py::arg("velocity"),
        "zeta = beta v^(1/5); beta in s^(1/5) m^(-1/5), velocity in m/s.");
  m.def("zetas_from", &zetas_from, py::arg("beta"), py::arg("velocity"),
        "zeta = beta v^(1/5) elementwise for two arrays of the same shape.");
  m.def(
      "solve",
      [](double zeta, const std::string& end, double tolerance, const std::string& method, bool trajectory,
         const std::string& law) {
        SolveOptions options = solve_options(end, tolerance, method, true);
        options.keep_trajectory = trajectory;
        if (options.ends == EndSet::both()) return solve_both_ends(law, zeta, options);
        return solve_one(law, zeta, options);
      },
      py::arg("zeta"), py::arg("end"), py::arg("tolerance"), py::arg("method"), py::arg("trajectory"),
      py::arg("law"), "One collision at zeta (natural units); end naive, delayed-recovery or both.");
}

}  // namespace restitution::python
