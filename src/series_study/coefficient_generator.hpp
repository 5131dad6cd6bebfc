// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Series arithmetic behind the independent computation of the coefficients a_k, b_k, c_k, h_k (natural
// units: x'' + ζ x' sqrt(x) + x^{3/2} = 0, x(0) = 0, x'(0) = 1). Templated on the scalar so that two
// working precisions can be compared; see docs/series.md for the derivation.
//
// 1. Trajectory near τ = 0 (2008 paper, App. A): x = τ (1 + R) with R a double series in p = ζ τ^{3/2}
//    and q = τ^{5/2}, R = Σ e_{km} p^k q^m (the term τ^{1+(3k+5m)/2} ζ^k). τ d/dτ multiplies the
//    monomial by its grade n/2, n = 3k + 5m, so Eq. (A3) times τ becomes the recursion
//        n (n + 2)/4 e_{km} = -[p (1 + R + τR') sqrt(1+R) + q (1+R)^{3/2}]_{km}.
// 2. Maximal compression: x and x' at τ0 = τ_max0 as ζ-series (sums over m converge like 0.177^m), then
//    the local Taylor series in δ = τ - τ0 from x'' = -sqrt(x) (ζ x' + x), then x'(τ0 + δ(ζ)) = 0 solved
//    order by order: δ = Σ a_k ζ^k, x_max = Σ b_k ζ^k.
// 3. Naive ε (2008 paper, App. B): equal maximal compression of the direct collision and of the inverse
//    one (speed ε, damping -ζ): X(ζ) = ε^{4/5} X(-ζ ε^{1/5}); solved order by order for ε^{1/5}.
// 4. Delayed recovery (App. C): in the inverse collision with damping -w, s = w t, the end condition
//    Z = w Z' reads (t - 1) F = τF' and every monomial carries λ^{k+m}, λ = w^{5/2}; the velocity there is
//    V(λ) = Σ v_j λ^j (v_1 = 4/15). With w = ζ ε_n^{1/5}: ε = ε_n(ζ) V(ζ^{5/2} ε_n^{1/2}), a series in √ζ.
#include <cmath>
#include <vector>

namespace restitution::series::detail {

// Truncated power series: coefficient i of the variable^i, i <= order.
template <typename T>
using Series = std::vector<T>;

template <typename T>
Series<T> multiply(const Series<T>& a, const Series<T>& b, int order) {
  Series<T> r(order + 1, T(0));
  const int na = static_cast<int>(a.size()) - 1;
  const int nb = static_cast<int>(b.size()) - 1;
  for (int i = 0; i <= std::min(na, order); ++i) {
    if (a[i] == T(0)) continue;
    for (int j = 0; j <= std::min(nb, order - i); ++j) r[i + j] += a[i] * b[j];
  }
  return r;
}

// (1 + f)^alpha for f without constant term, by the recurrence from (1+f) g' = alpha g f'.
template <typename T>
Series<T> power_one_plus(const Series<T>& f, const T& alpha, int order) {
  Series<T> g(order + 1, T(0));
  g[0] = T(1);
  for (int n = 1; n <= order; ++n) {
    T sum(0);
    for (int j = 1; j <= n && j < static_cast<int>(f.size()); ++j)
      sum += (alpha * T(j) - T(n - j)) * f[j] * g[n - j];
    g[n] = sum / T(n);
  }
  return g;
}

template <typename T>
Series<T> inverse(const Series<T>& a, int order) {
  Series<T> r(order + 1, T(0));
  r[0] = T(1) / a[0];
  for (int n = 1; n <= order; ++n) {
    T sum(0);
    for (int j = 1; j <= n && j < static_cast<int>(a.size()); ++j) sum += a[j] * r[n - j];
    r[n] = -sum * r[0];
  }
  return r;
}

// sqrt of a series with a positive constant term.
template <typename T>
Series<T> square_root(const Series<T>& a, int order) {
  using std::sqrt;
  const T s0 = sqrt(a[0]);
  Series<T> f(order + 1, T(0));
  for (int i = 1; i <= order && i < static_cast<int>(a.size()); ++i) f[i] = a[i] / a[0];
  Series<T> r = power_one_plus(f, T(1) / T(2), order);
  for (T& c : r) c *= s0;
  return r;
}

// R = Σ e_{km} p^k q^m for k <= k_max, m <= m_max; e(k, m) with e(0, 0) = 0.
template <typename T>
class TrajectorySeries {
 public:
  TrajectorySeries(int k_max, int m_max) : k_max_(k_max), m_max_(m_max) {
    const auto size = static_cast<std::size_t>((k_max + 1) * (m_max + 1));
    e_.assign(size, T(0));
    std::vector<T> s(size, T(0)), a(size, T(0)), b(size, T(0));  // sqrt(1+R), A, B of the recursion
    s[0] = a[0] = b[0] = T(1);
    const int grade_max = 3 * k_max + 5 * m_max;
    for (int n = 1; n <= grade_max; ++n) {
      for (int k = 0; 3 * k <= n && k <= k_max; ++k) {
        if ((n - 3 * k) % 5 != 0) continue;
        const int m = (n - 3 * k) / 5;
        if (m > m_max) continue;
        T rhs(0);
        if (k > 0) rhs += a[index(k - 1, m)];
        if (m > 0) rhs += b[index(k, m - 1)];
        e_[index(k, m)] = -T(4) * rhs / T(n * (n + 2));
      }
      for (int k = 0; 3 * k <= n && k <= k_max; ++k) {
        if ((n - 3 * k) % 5 != 0) continue;
        const int m = (n - 3 * k) / 5;
        if (m > m_max) continue;
        update_products(k, m, s, a, b);
      }
    }
  }

  [[nodiscard]] int k_max() const { return k_max_; }
  [[nodiscard]] int m_max() const { return m_max_; }
  [[nodiscard]] const T& e(int k, int m) const { return e_[index(k, m)]; }
  static int grade(int k, int m) { return 3 * k + 5 * m; }

 private:
  [[nodiscard]] std::size_t index(int k, int m) const {
    return static_cast<std::size_t>(k * (m_max_ + 1) + m);
  }

  // Coefficient (k, m) of S = (1+R)^{1/2} (grade recurrence (1+R) D S = S D R / 2), B = (1+R) S and
  // A = (1 + R + DR) S, where D multiplies a monomial of grade n by n/2.
  void update_products(int k, int m, std::vector<T>& s, std::vector<T>& a, std::vector<T>& b) const {
    const int n = grade(k, m);
    T s_sum(0), a_sum(0), b_sum(0);  // s_sum carries a factor 2n, a_sum a factor 2
    for (int i = 0; i <= k; ++i)
      for (int j = 0; j <= m; ++j) {
        if (i == 0 && j == 0) continue;
        const T& r = e_[index(i, j)];
        const int g = grade(i, j);
        s_sum += T(g - 2 * (n - g)) * r * s[index(k - i, m - j)];
      }
    const T s_km = s_sum / T(2 * n);
    s[index(k, m)] = s_km;
    for (int i = 0; i <= k; ++i)
      for (int j = 0; j <= m; ++j) {
        if (i == 0 && j == 0) continue;
        const T rs = e_[index(i, j)] * s[index(k - i, m - j)];
        b_sum += rs;
        a_sum += T(2 + grade(i, j)) * rs;
      }
    a[index(k, m)] = s_km + a_sum / T(2);
    b[index(k, m)] = s_km + b_sum;
  }

  int k_max_, m_max_;
  std::vector<T> e_;
};

template <typename T>
struct GeneratedSeries {
  Series<T> a;  // τ_max - τ_max0 = Σ_{k>=1} a_k ζ^k (a[0] = 0)
  Series<T> b;  // x_max = Σ b_k ζ^k
  Series<T> c;  // ε_naive = 1 + Σ c_k ζ^k (c[0] = 1, the whole series)
  Series<T> h;  // ε_delayed = Σ h_k ζ^{k/2} (h[0] = 1)
  Series<T> v;  // V(λ) = Σ v_j λ^j, velocity ratio at the premature end of the inverse collision
  T tau_max0;
};

// x(τ0) and x'(τ0) as ζ-series (order k_max) from the trajectory series.
template <typename T>
void values_at(const TrajectorySeries<T>& traj, const T& tau0, Series<T>& x, Series<T>& xdot) {
  using std::pow;
  const int order = traj.k_max();
  x.assign(order + 1, T(0));
  xdot.assign(order + 1, T(0));
  const T q0 = pow(tau0, T(5) / T(2));
  const T p_scale = pow(tau0, T(3) / T(2));  // ζ^k τ^{3k/2}
  for (int k = 0; k <= order; ++k) {
    T pk = pow(p_scale, k);
    T sum_x(k == 0 ? 1 : 0), sum_d(k == 0 ? 1 : 0);
    T qm(1);
    for (int m = 0; m <= traj.m_max(); ++m, qm *= q0) {
      const T term = traj.e(k, m) * pk * qm;
      sum_x += term;
      sum_d += term * (T(1) + T(TrajectorySeries<T>::grade(k, m)) / T(2));
    }
    x[k] = tau0 * sum_x;
    xdot[k] = sum_d;
  }
}

template <typename T>
void maximal_compression(const TrajectorySeries<T>& traj, const T& tau0, Series<T>& a, Series<T>& b) {
  const int order = traj.k_max();
  const int taylor = order + 2;  // δ = O(ζ): δ^i only matters for i <= order, x' needs X_{i+1}
  std::vector<Series<T>> X(taylor + 1, Series<T>(order + 1, T(0)));
  values_at(traj, tau0, X[0], X[1]);
  std::vector<Series<T>> W;  // sqrt(X) in δ, each coefficient a ζ-series
  W.push_back(square_root(X[0], order));
  const Series<T> half_inv_w0 = [&] {
    Series<T> r = inverse(W[0], order);
    for (T& c : r) c /= T(2);
    return r;
  }();
  for (int i = 0; i + 2 <= taylor; ++i) {
    if (i >= 1) {  // W_i = (X_i - Σ_{l=1}^{i-1} W_l W_{i-l}) / (2 W_0)
      Series<T> num = X[i];
      for (int l = 1; l < i; ++l) {
        const Series<T> prod = multiply(W[l], W[i - l], order);
        for (int j = 0; j <= order; ++j) num[j] -= prod[j];
      }
      W.push_back(multiply(num, half_inv_w0, order));
    }
    // X_{i+2} (i+1)(i+2) = -Σ_l W_l G_{i-l}, G_j = ζ (j+1) X_{j+1} + X_j
    Series<T> rhs(order + 1, T(0));
    for (int l = 0; l <= i; ++l) {
      const int j = i - l;
      Series<T> g = X[j];
      for (int z = 1; z <= order; ++z) g[z] += T(j + 1) * X[j + 1][z - 1];
      const Series<T> prod = multiply(W[l], g, order);
      for (int z = 0; z <= order; ++z) rhs[z] -= prod[z];
    }
    for (int z = 0; z <= order; ++z) X[i + 2][z] = rhs[z] / T((i + 1) * (i + 2));
  }
  // x'(τ0 + δ) = Σ_i (i+1) X_{i+1} δ^i = 0 with δ = Σ_{j>=1} a_j ζ^j: δ = -(Y_0 + Σ_{i>=2} Y_i δ^i) / Y_1.
  auto horner = [&](const Series<T>& delta, int first, int shift) {  // Σ_{i>=first} coef_i δ^{i-first}
    Series<T> acc(order + 1, T(0));
    for (int i = taylor - shift; i >= first; --i) {
      acc = multiply(acc, delta, order);
      for (int z = 0; z <= order; ++z) acc[z] += T(shift ? i + 1 : 1) * X[i + shift][z];
    }
    return acc;
  };
  Series<T> delta(order + 1, T(0));
  const Series<T> inv_y1 = inverse(Series<T>([&] {
                                     Series<T> y1 = X[2];
                                     for (T& c : y1) c *= T(2);
                                     return y1;
                                   }()),
                                   order);
  for (int iteration = 0; iteration <= order; ++iteration) {
    // Y(δ) = Y_0 + δ (Y_1 + δ Σ_{i>=2} Y_i δ^{i-2}); fixed point δ = -(Y_0 + δ² Σ_{i>=2}) / Y_1
    const Series<T> tail = horner(delta, 2, 1);
    Series<T> num = multiply(multiply(delta, delta, order), tail, order);
    for (int z = 0; z <= order; ++z) num[z] += X[1][z];
    Series<T> next = multiply(num, inv_y1, order);
    for (T& c : next) c = -c;
    next[0] = T(0);
    delta = next;
  }
  a = delta;
  b = horner(delta, 0, 0);
}

// ε_naive^{1/5} from X(ζ) = e^4 X(-ζ e), then ε_naive = e^5.
template <typename T>
Series<T> naive_restitution(const Series<T>& b, int order) {
  Series<T> e(order + 1, T(0));
  e[0] = T(1);
  for (int j = 1; j <= order; ++j) {
    // residual of order j with e_j = 0; e_j enters only through 4 b_0 e_j
    Series<T> minus_zeta_e(j + 1, T(0));
    for (int i = 0; i + 1 <= j; ++i) minus_zeta_e[i + 1] = -e[i];
    Series<T> composed(j + 1, T(0));  // Σ b_k (-ζ e)^k by Horner
    for (int k = j; k >= 0; --k) {
      composed = multiply(composed, minus_zeta_e, j);
      composed[0] += b[k];
    }
    Series<T> e4 = multiply(multiply(e, e, j), multiply(e, e, j), j);
    const Series<T> rhs = multiply(e4, composed, j);
    e[j] = (b[j] - rhs[j]) / (T(4) * b[0]);
  }
  Series<T> e2 = multiply(e, e, order);
  return multiply(multiply(e2, e2, order), e, order);
}

// V(λ) = Z'(s_T) in the inverse collision, order j_max in λ = w^{5/2}; needs e_{km} with k + m <= j_max.
template <typename T>
Series<T> premature_end_velocity(const TrajectorySeries<T>& traj, int j_max) {
  // t = 1 + θ(λ); fixed point θ = Σ σ_km (n/2) t^{n/2} / (1 + Σ σ_km t^{n/2}), σ_km = e_km (-1)^k λ^{k+m}
  const int n_max = 3 * j_max + 5 * j_max;
  auto sums = [&](const Series<T>& theta, Series<T>& f, Series<T>& df) {
    const Series<T> root = power_one_plus(theta, T(1) / T(2), j_max);  // t^{1/2}
    std::vector<Series<T>> powers(n_max + 1);
    powers[0] = Series<T>(j_max + 1, T(0));
    powers[0][0] = T(1);
    for (int n = 1; n <= n_max; ++n) powers[n] = multiply(powers[n - 1], root, j_max);
    f.assign(j_max + 1, T(0));
    df.assign(j_max + 1, T(0));
    f[0] = T(1);
    for (int k = 0; k <= std::min(j_max, traj.k_max()); ++k)
      for (int m = 0; k + m <= j_max && m <= traj.m_max(); ++m) {
        if (k == 0 && m == 0) continue;
        const int n = TrajectorySeries<T>::grade(k, m);
        const T coef = (k % 2 ? -traj.e(k, m) : traj.e(k, m));
        for (int z = 0; z + k + m <= j_max; ++z) {
          f[z + k + m] += coef * powers[n][z];
          df[z + k + m] += coef * T(n) / T(2) * powers[n][z];
        }
      }
  };
  Series<T> theta(j_max + 1, T(0)), f, df;
  for (int iteration = 0; iteration <= j_max; ++iteration) {
    sums(theta, f, df);
    theta = multiply(df, inverse(f, j_max), j_max);
  }
  sums(theta, f, df);
  for (int z = 0; z <= j_max; ++z) f[z] += df[z];  // V = F + τF'
  return f;
}

// ε_delayed as a series in σ = sqrt(ζ), order 2·order: Σ_j v_j σ^{5j} ε_n^{1 + j/2}.
template <typename T>
Series<T> delayed_restitution(const Series<T>& c, const Series<T>& v, int sigma_order) {
  const int zeta_order = sigma_order / 2;
  Series<T> eps_minus_one(zeta_order + 1, T(0));
  for (int i = 1; i <= zeta_order; ++i) eps_minus_one[i] = c[i];
  Series<T> h(sigma_order + 1, T(0));
  for (int j = 0; 5 * j <= sigma_order && j < static_cast<int>(v.size()); ++j) {
    const Series<T> power = power_one_plus(eps_minus_one, T(1) + T(j) / T(2), zeta_order);
    for (int i = 0; 5 * j + 2 * i <= sigma_order; ++i) h[5 * j + 2 * i] += v[j] * power[i];
  }
  return h;
}

template <typename T>
T undamped_max_time() {
  using std::atan;
  using std::pow;
  using std::sqrt;
  using std::tgamma;
  const T pi = T(4) * atan(T(1));
  return pow(T(4) / T(5), T(3) / T(5)) * tgamma(T(2) / T(5)) * sqrt(pi) / (T(2) * tgamma(T(9) / T(10)));
}

// order: the largest power of ζ for a_k, b_k, c_k (h_k up to ζ^{order/1}, i.e. σ^{2·order});
// m_max: truncation of the trajectory series in q = τ^{5/2}.
template <typename T>
GeneratedSeries<T> generate(int order, int m_max) {
  GeneratedSeries<T> out;
  out.tau_max0 = undamped_max_time<T>();
  const TrajectorySeries<T> traj(order, m_max);
  maximal_compression(traj, out.tau_max0, out.a, out.b);
  out.c = naive_restitution(out.b, order);
  const int sigma_order = 2 * order;
  out.v = premature_end_velocity(traj, sigma_order / 5);
  out.h = delayed_restitution(out.c, out.v, sigma_order);
  return out;
}

}  // namespace restitution::series::detail
