#include "sundials/small_vector.hpp"

#include <algorithm>
#include <cmath>

namespace restitution::sundials {
namespace {

// The operations are called through SUNDIALS' C function table: no exception may leave them, and none
// can (plain arithmetic on doubles).
struct View {
  explicit View(N_Vector v) : data(NV_DATA_S(v)), size(NV_LENGTH_S(v)) {}
  double* data;
  sunindextype size;
};

void linear_sum(double a, N_Vector x, double b, N_Vector y, N_Vector z) noexcept {
  const View vx(x), vy(y), vz(z);
  for (sunindextype i = 0; i < vz.size; ++i) vz.data[i] = a * vx.data[i] + b * vy.data[i];
}

void set_constant(double c, N_Vector z) noexcept {
  const View vz(z);
  std::fill(vz.data, vz.data + vz.size, c);
}

void product(N_Vector x, N_Vector y, N_Vector z) noexcept {
  const View vx(x), vy(y), vz(z);
  for (sunindextype i = 0; i < vz.size; ++i) vz.data[i] = vx.data[i] * vy.data[i];
}

void quotient(N_Vector x, N_Vector y, N_Vector z) noexcept {
  const View vx(x), vy(y), vz(z);
  for (sunindextype i = 0; i < vz.size; ++i) vz.data[i] = vx.data[i] / vy.data[i];
}

void scale(double c, N_Vector x, N_Vector z) noexcept {
  const View vx(x), vz(z);
  for (sunindextype i = 0; i < vz.size; ++i) vz.data[i] = c * vx.data[i];
}

void absolute(N_Vector x, N_Vector z) noexcept {
  const View vx(x), vz(z);
  for (sunindextype i = 0; i < vz.size; ++i) vz.data[i] = std::abs(vx.data[i]);
}

void inverse(N_Vector x, N_Vector z) noexcept {
  const View vx(x), vz(z);
  for (sunindextype i = 0; i < vz.size; ++i) vz.data[i] = 1.0 / vx.data[i];
}

void add_constant(N_Vector x, double b, N_Vector z) noexcept {
  const View vx(x), vz(z);
  for (sunindextype i = 0; i < vz.size; ++i) vz.data[i] = vx.data[i] + b;
}

double max_norm(N_Vector x) noexcept {
  const View vx(x);
  double m = 0.0;
  for (sunindextype i = 0; i < vx.size; ++i) m = std::max(m, std::abs(vx.data[i]));
  return m;
}

double weighted_square_sum(N_Vector x, N_Vector w) noexcept {
  const View vx(x), vw(w);
  double sum = 0.0;
  for (sunindextype i = 0; i < vx.size; ++i) {
    const double p = vx.data[i] * vw.data[i];
    sum += p * p;
  }
  return sum;
}

double weighted_rms_norm(N_Vector x, N_Vector w) noexcept {
  return std::sqrt(weighted_square_sum(x, w) / static_cast<double>(NV_LENGTH_S(x)));
}

double minimum(N_Vector x) noexcept {
  const View vx(x);
  return *std::min_element(vx.data, vx.data + vx.size);
}

void compare(double c, N_Vector x, N_Vector z) noexcept {
  const View vx(x), vz(z);
  for (sunindextype i = 0; i < vz.size; ++i) vz.data[i] = std::abs(vx.data[i]) >= c ? 1.0 : 0.0;
}

// z = Σ c_j x_j (x_0 may be z itself).
int linear_combination(int count, double* c, N_Vector* x, N_Vector z) noexcept {
  const View vz(z);
  for (sunindextype i = 0; i < vz.size; ++i) {
    double sum = 0.0;
    for (int j = 0; j < count; ++j) sum += c[j] * NV_DATA_S(x[j])[i];
    vz.data[i] = sum;
  }
  return 0;
}

// z_j = a_j x + y_j.
int scale_add_multi(int count, double* a, N_Vector x, N_Vector* y, N_Vector* z) noexcept {
  const View vx(x);
  for (int j = 0; j < count; ++j) {
    const double* yj = NV_DATA_S(y[j]);
    double* zj = NV_DATA_S(z[j]);
    for (sunindextype i = 0; i < vx.size; ++i) zj[i] = a[j] * vx.data[i] + yj[i];
  }
  return 0;
}

}  // namespace

Vector make_small_vector(sunindextype length, const Context& context) {
  Vector v = make_serial_vector(length, context);
  // Clones copy this table (N_VCloneEmpty), so every vector CVODE makes from this one uses these loops.
  N_Vector_Ops ops = v->ops;
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
  return v;
}

}  // namespace restitution::sundials
