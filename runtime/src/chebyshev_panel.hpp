// A smooth function on one panel [-1, 1], held by its values at the Chebyshev points of the
// second kind x_j = cos(j pi/M), j = 0..M: barycentric interpolation (Berrut & Trefethen,
// SIAM Review 46, 2004) and the antiderivative from -1 through the Chebyshev coefficients.
#pragma once

#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace wavecontact::detail {

class ChebyshevPanel {
 public:
  static std::vector<double> points(int M) {
    std::vector<double> x(M + 1);
    for (int j = 0; j <= M; ++j) x[j] = std::cos(M_PI * j / M);
    return x;
  }
  // points(M), computed once for the panel sizes the solver uses (M = order + 2, order <= 66).
  static const std::vector<double>& cached_points(int M) {
    static const std::array<std::vector<double>, 71> table = [] {
      std::array<std::vector<double>, 71> t;
      for (int m = 1; m < static_cast<int>(t.size()); ++m) t[m] = points(m);
      return t;
    }();
    if (M < 1 || M >= static_cast<int>(table.size())) throw std::out_of_range("ChebyshevPanel: M beyond the table");
    return table[M];
  }

  ChebyshevPanel() = default;
  // values[j] at points(M)[j].
  explicit ChebyshevPanel(std::vector<double> values) : values_(std::move(values)) {}

  double operator()(double x) const {
    const int M = static_cast<int>(values_.size()) - 1;
    const std::vector<double>& nodes = cached_points(M);
    double num = 0, den = 0;
    for (int j = 0; j <= M; ++j) {
      const double d = x - nodes[j];
      if (d == 0) return values_[j];
      const double l = ((j % 2) ? -1.0 : 1.0) * (j == 0 || j == M ? 0.5 : 1.0) / d;
      num += l * values_[j], den += l;
    }
    return num / den;
  }

  // The coefficients B_k of Int_{-1}^{x} (interpolant) = sum_k B_k T_k(x).
  std::vector<double> antiderivative() const {
    const int M = static_cast<int>(values_.size()) - 1;
    // cos(pi i/M) for i in [0, 2M): x_i, or x_(2M - i) past pi.
    const std::vector<double>& nodes = cached_points(M);
    std::vector<double> c(M + 3, 0.0);  // f = c_0/2 + sum c_k T_k
    for (int k = 0; k <= M; ++k) {
      double sum = 0;
      for (int j = 0; j <= M; ++j) {
        const int i = (j * k) % (2 * M);
        sum += (j == 0 || j == M ? 0.5 : 1.0) * values_[j] * nodes[i <= M ? i : 2 * M - i];
      }
      c[k] = 2 * sum / M * (k == M ? 0.5 : 1.0);
    }
    std::vector<double> B(M + 2, 0.0);
    for (int k = 1; k <= M + 1; ++k) B[k] = (c[k - 1] - c[k + 1]) / (2 * k);
    double at_minus_one = 0;
    for (int k = 1; k <= M + 1; ++k) at_minus_one += (k % 2 ? -1.0 : 1.0) * B[k];
    B[0] = -at_minus_one;
    return B;
  }

  static double chebyshev_sum(const std::vector<double>& B, double x) {
    // Clenshaw's recurrence for sum_k B_k T_k(x).
    double b1 = 0, b2 = 0;
    for (int k = static_cast<int>(B.size()) - 1; k >= 1; --k) {
      const double b0 = 2 * x * b1 - b2 + B[k];
      b2 = b1, b1 = b0;
    }
    return x * b1 - b2 + B[0];
  }

 private:
  std::vector<double> values_;
};

}  // namespace wavecontact::detail
