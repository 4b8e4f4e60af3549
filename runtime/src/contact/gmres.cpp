#include "gmres.hpp"

#include <cmath>

namespace wavecontact::detail {

namespace {

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

}  // namespace

std::vector<double> gmres(const LinearMap& A, const LinearMap& M_inverse, const std::vector<double>& b,
                          double tolerance, int restart, int restarts) {
  const std::size_t n = b.size();
  std::vector<double> x(n, 0.0);
  const double b_norm = std::sqrt(dot(b, b));
  if (b_norm == 0) return x;
  std::vector<double> r = b;
  for (int cycle = 0; cycle < restarts; ++cycle) {
    const double beta = std::sqrt(dot(r, r));
    if (beta <= tolerance * b_norm) break;
    const int m = restart;
    bool converged = false;  // the rotated residual |g_k|, which equals |b - A x|, met the tolerance
    std::vector<std::vector<double>> V(static_cast<std::size_t>(m + 1)), Z(static_cast<std::size_t>(m));
    // The Hessenberg matrix by columns, in one block: a Newton step's systems converge in 2 to
    // 10 of the 60 columns, and a row of its own each was a quarter of a map's allocations.
    std::vector<double> hessenberg(static_cast<std::size_t>((m + 1) * m));
    const auto H = [&](std::size_t row, std::size_t column) -> double& {
      return hessenberg[column * static_cast<std::size_t>(m + 1) + row];
    };
    std::vector<double> cs(static_cast<std::size_t>(m)), sn(static_cast<std::size_t>(m)),
        g(static_cast<std::size_t>(m + 1), 0.0);
    V[0] = r;
    for (double& v : V[0]) v /= beta;
    g[0] = beta;
    int k = 0;
    for (; k < m; ++k) {
      const std::size_t uk = static_cast<std::size_t>(k);
      Z[uk] = M_inverse(V[uk]);
      std::vector<double> w = A(Z[uk]);
      for (int i = 0; i <= k; ++i) {  // modified Gram-Schmidt
        const std::size_t ui = static_cast<std::size_t>(i);
        H(ui, uk) = dot(w, V[ui]);
        for (std::size_t j = 0; j < n; ++j) w[j] -= H(ui, uk) * V[ui][j];
      }
      H(uk + 1, uk) = std::sqrt(dot(w, w));
      V[uk + 1] = w;
      if (H(uk + 1, uk) > 0) {
        for (double& v : V[uk + 1]) v /= H(uk + 1, uk);
      }
      for (int i = 0; i < k; ++i) {  // the previous rotations
        const std::size_t ui = static_cast<std::size_t>(i);
        const double t = cs[ui] * H(ui, uk) + sn[ui] * H(ui + 1, uk);
        H(ui + 1, uk) = -sn[ui] * H(ui, uk) + cs[ui] * H(ui + 1, uk);
        H(ui, uk) = t;
      }
      const double rho = std::hypot(H(uk, uk), H(uk + 1, uk));
      cs[uk] = rho > 0 ? H(uk, uk) / rho : 1, sn[uk] = rho > 0 ? H(uk + 1, uk) / rho : 0;
      H(uk, uk) = rho, H(uk + 1, uk) = 0;
      g[uk + 1] = -sn[uk] * g[uk], g[uk] = cs[uk] * g[uk];
      if (std::fabs(g[uk + 1]) <= tolerance * b_norm || H(uk, uk) == 0) {
        converged = std::fabs(g[uk + 1]) <= tolerance * b_norm;
        ++k;
        break;
      }
    }
    // y from the triangle, x += Z y.
    std::vector<double> y(static_cast<std::size_t>(k));
    for (int i = k - 1; i >= 0; --i) {
      const std::size_t ui = static_cast<std::size_t>(i);
      double s = g[ui];
      for (int j = i + 1; j < k; ++j) s -= H(ui, static_cast<std::size_t>(j)) * y[static_cast<std::size_t>(j)];
      y[ui] = H(ui, ui) != 0 ? s / H(ui, ui) : 0;
    }
    for (int i = 0; i < k; ++i) {
      for (std::size_t j = 0; j < n; ++j) x[j] += y[static_cast<std::size_t>(i)] * Z[static_cast<std::size_t>(i)][j];
    }
    // The residual itself only for a restart: its product would be one more of the 2 to 10 a
    // Newton step takes.
    if (converged || cycle + 1 == restarts) break;
    const std::vector<double> Ax = A(x);
    for (std::size_t j = 0; j < n; ++j) r[j] = b[j] - Ax[j];
  }
  return x;
}

}  // namespace wavecontact::detail
