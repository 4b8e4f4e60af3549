#include "chebyshev.hpp"

#include <algorithm>
#include <complex>

#include <unsupported/Eigen/FFT>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>

#include <boost/math/constants/constants.hpp>

namespace wavecontact::detail::chebyshev {

namespace {

using boost::math::double_constants::pi;

// Up to this many nodes the transform's cosines are tabulated; beyond, it is a fast Fourier
// transform of the values extended evenly to 2 M points (an M^2 table would reach 134 MB at
// M = 4096, and the three-term recurrence of T_j loses j ulps: the zone's own operator then
// multiplies coefficient j by j, a first-kind equation's amplification of noise).
constexpr int tabulated = 128;

// The nodes and the transform's cosines cos(pi j (i + 1/2) / M) of one M, computed once.
struct Table {
  std::vector<double> nodes, cosines;  // cosines[j * M + i], for M <= tabulated
};

const Table& table(int M) {
  static std::mutex mutex;
  static std::map<int, std::unique_ptr<Table>> cache;
  const std::lock_guard<std::mutex> lock(mutex);
  std::unique_ptr<Table>& entry = cache[M];
  if (!entry) {
    entry = std::make_unique<Table>();
    entry->nodes.resize(static_cast<std::size_t>(M));
    for (int i = 0; i < M; ++i) entry->nodes[static_cast<std::size_t>(i)] = std::cos(pi * (i + 0.5) / M);
    if (M > tabulated) return *entry;
    entry->cosines.resize(static_cast<std::size_t>(M) * static_cast<std::size_t>(M));
    for (int j = 0; j < M; ++j) {
      for (int i = 0; i < M; ++i) {
        // j (i + 1/2) reduced modulo 2 M before the cosine keeps its argument small.
        const long k = (static_cast<long>(j) * (2 * i + 1)) % (4L * M);
        entry->cosines[static_cast<std::size_t>(j) * static_cast<std::size_t>(M) + static_cast<std::size_t>(i)] =
            std::cos(pi * static_cast<double>(k) / (2.0 * M));
      }
    }
  }
  return *entry;
}

// Clenshaw for a family with P_0 = 1, P_1 = a t + b, P_{j+1} = 2 t P_j - P_{j-1}.
double clenshaw(const double* c, std::size_t count, double t, double a, double b) {
  if (count == 0) return 0;
  double b1 = 0, b2 = 0;
  for (std::size_t j = count; j-- > 1;) {
    const double next = c[j] + 2 * t * b1 - b2;
    b2 = b1, b1 = next;
  }
  // sum = c_0 P_0 + b1 P_1 - b2 P_0 (the recurrence's remainder).
  return c[0] + b1 * (a * t + b) - b2;
}

}  // namespace

const std::vector<double>& nodes(int M) { return table(M).nodes; }

void coefficients(const double* values, int M, double* out) {
  const Table& t = table(M);
  if (M > tabulated) {
    // y = (v_0 .. v_{M-1}, v_{M-1} .. v_0): Y_j = 2 e^{i pi j/(2M)} sum_i v_i cos(pi j (i + 1/2)/M).
    thread_local Eigen::FFT<double> fft;
    std::vector<double> y(static_cast<std::size_t>(2 * M));
    for (int i = 0; i < M; ++i) y[static_cast<std::size_t>(i)] = y[static_cast<std::size_t>(2 * M - 1 - i)] = values[i];
    std::vector<std::complex<double>> Y;
    fft.fwd(Y, y);
    for (int j = 0; j < M; ++j) {
      const std::complex<double> phase = std::polar(1.0, -pi * j / (2.0 * M));
      out[j] = (phase * Y[static_cast<std::size_t>(j)]).real() / 2 * (j == 0 ? 1.0 : 2.0) / M;
    }
    return;
  }
  for (int j = 0; j < M; ++j) {
    const double* row = t.cosines.data() + static_cast<std::size_t>(j) * static_cast<std::size_t>(M);
    double sum = 0;
    for (int i = 0; i < M; ++i) sum += row[i] * values[i];
    out[j] = (j == 0 ? 1.0 : 2.0) * sum / M;
  }
}

std::vector<double> coefficients(const std::vector<double>& values) {
  std::vector<double> out(values.size());
  coefficients(values.data(), static_cast<int>(values.size()), out.data());
  return out;
}

std::vector<double> extrema_coefficients(const std::vector<double>& values) {
  // c_j = (2/n) sum_i'' v_i cos(pi i j / n) (the first and last terms halved; c_0, c_n halved).
  const int n = static_cast<int>(values.size()) - 1;
  std::vector<double> c(values.size(), 0.0);
  for (int j = 0; j <= n; ++j) {
    double sum = 0;
    for (int i = 0; i <= n; ++i) {
      const double w = (i == 0 || i == n) ? 0.5 : 1.0;
      const long k = (static_cast<long>(i) * j) % (2L * n);
      sum += w * values[static_cast<std::size_t>(i)] * std::cos(pi * static_cast<double>(k) / n);
    }
    c[static_cast<std::size_t>(j)] = sum * 2 / n * ((j == 0 || j == n) ? 0.5 : 1.0);
  }
  return c;
}

double sum_t(const double* c, std::size_t count, double t) { return clenshaw(c, count, t, 1, 0); }
double sum_u(const double* c, std::size_t count, double t) { return clenshaw(c, count, t, 2, 0); }
double sum_v(const double* c, std::size_t count, double t) { return clenshaw(c, count, t, 2, -1); }
double sum_w(const double* c, std::size_t count, double t) { return clenshaw(c, count, t, 2, 1); }

}  // namespace wavecontact::detail::chebyshev
