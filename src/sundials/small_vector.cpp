// SPDX-License-Identifier: BSD-3-Clause
#include "sundials/small_vector.hpp"

#include <algorithm>
#include <cmath>

namespace restitution::sundials {
namespace {

// The operations for vectors of Length components (0: any length, read from the vector).
template <sunindextype Length>
struct Loops {
  // The operations are called through SUNDIALS' C function table: no exception may leave them, and none
  // can (plain arithmetic on doubles).
  static double* data(N_Vector v) { return NV_DATA_S(v); }
  // A length known at compile time (the 3-component state) lets the compiler unroll every loop.
  static sunindextype size(N_Vector v) { return Length > 0 ? Length : NV_LENGTH_S(v); }

  // out[i] = f(i) for every component; the pointers are read once (SUNDIALS' content struct).
  template <class F>
  static void assign(N_Vector out, F f) {
    double* z = data(out);
    const sunindextype n = size(out);
    for (sunindextype i = 0; i < n; ++i) z[i] = f(i);
  }

  static void linear_sum(double a, N_Vector x, double b, N_Vector y, N_Vector z) noexcept {
    const double* xd = data(x);
    const double* yd = data(y);
    assign(z, [=](sunindextype i) { return a * xd[i] + b * yd[i]; });
  }

  static void set_constant(double c, N_Vector z) noexcept {
    assign(z, [=](sunindextype) { return c; });
  }

  static void product(N_Vector x, N_Vector y, N_Vector z) noexcept {
    const double* xd = data(x);
    const double* yd = data(y);
    assign(z, [=](sunindextype i) { return xd[i] * yd[i]; });
  }

  static void quotient(N_Vector x, N_Vector y, N_Vector z) noexcept {
    const double* xd = data(x);
    const double* yd = data(y);
    assign(z, [=](sunindextype i) { return xd[i] / yd[i]; });
  }

  static void scale(double c, N_Vector x, N_Vector z) noexcept {
    const double* xd = data(x);
    assign(z, [=](sunindextype i) { return c * xd[i]; });
  }

  static void absolute(N_Vector x, N_Vector z) noexcept {
    const double* xd = data(x);
    assign(z, [=](sunindextype i) { return std::abs(xd[i]); });
  }

  static void inverse(N_Vector x, N_Vector z) noexcept {
    const double* xd = data(x);
    assign(z, [=](sunindextype i) { return 1.0 / xd[i]; });
  }

  static void add_constant(N_Vector x, double b, N_Vector z) noexcept {
    const double* xd = data(x);
    assign(z, [=](sunindextype i) { return xd[i] + b; });
  }

  static void compare(double c, N_Vector x, N_Vector z) noexcept {
    const double* xd = data(x);
    assign(z, [=](sunindextype i) { return std::abs(xd[i]) >= c ? 1.0 : 0.0; });
  }

  static double max_norm(N_Vector x) noexcept {
    const double* xd = data(x);
    double m = 0.0;
    for (sunindextype i = 0; i < size(x); ++i) m = std::max(m, std::abs(xd[i]));
    return m;
  }

  static double weighted_square_sum(N_Vector x, N_Vector w) noexcept {
    const double* xd = data(x);
    const double* wd = data(w);
    double sum = 0.0;
    for (sunindextype i = 0; i < size(x); ++i) sum += (xd[i] * wd[i]) * (xd[i] * wd[i]);
    return sum;
  }

  static double weighted_rms_norm(N_Vector x, N_Vector w) noexcept {
    return std::sqrt(weighted_square_sum(x, w) / static_cast<double>(size(x)));
  }

  static double minimum(N_Vector x) noexcept { return *std::min_element(data(x), data(x) + size(x)); }

  // z = Σ c_j x_j (x_0 may be z itself: each component is read before it is written).
  static int linear_combination(int count,
                                double* c,  // NOLINT(readability-non-const-parameter): SUNDIALS signature
                                N_Vector* x, N_Vector z) noexcept {
    assign(z, [=](sunindextype i) {
      double sum = 0.0;
      for (int j = 0; j < count; ++j) sum += c[j] * data(x[j])[i];
      return sum;
    });
    return 0;
  }

  // z_j = a_j x + y_j.
  static int scale_add_multi(int count,
                             double* a,  // NOLINT(readability-non-const-parameter): SUNDIALS signature
                             N_Vector x, N_Vector* y, N_Vector* z) noexcept {
    const double* xd = data(x);
    for (int j = 0; j < count; ++j) {
      const double* yd = data(y[j]);
      const double aj = a[j];
      assign(z[j], [=](sunindextype i) { return aj * xd[i] + yd[i]; });
    }
    return 0;
  }

  static void install(N_Vector_Ops ops) {
    ops->nvlinearsum = linear_sum;
    ops->nvconst = set_constant;
    ops->nvprod = product;
    ops->nvdiv = quotient;
    ops->nvscale = scale;
    ops->nvabs = absolute;
    ops->nvinv = inverse;
    ops->nvaddconst = add_constant;
    ops->nvmaxnorm = max_norm;
    ops->nvmaxnormlocal = max_norm;
    ops->nvwrmsnorm = weighted_rms_norm;
    ops->nvwsqrsumlocal = weighted_square_sum;
    ops->nvmin = minimum;
    ops->nvminlocal = minimum;
    ops->nvcompare = compare;
    ops->nvlinearcombination = linear_combination;
    ops->nvscaleaddmulti = scale_add_multi;
  }
};

}  // namespace

Vector make_small_vector(sunindextype length, const Context& context) {
  Vector v = make_serial_vector(length, context);
  // Clones copy this table (N_VCloneEmpty), so every vector CVODE makes from this one uses these loops.
  if (length == 3) {
    Loops<3>::install(v->ops);
  } else if (length == 4) {  // the Sundman form's state (src/cvode/cvode_integrator.hpp)
    Loops<4>::install(v->ops);
  } else if (length == 8) {  // the oblique contact's (oblique_contact.cpp, via the event driver)
    Loops<8>::install(v->ops);
  } else {
    Loops<0>::install(v->ops);
  }
  return v;
}

}  // namespace restitution::sundials
