#include "chebyshev.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>

#include <boost/math/constants/constants.hpp>

#include "cosine_transform.hpp"

namespace wavecontact::detail::chebyshev {

namespace {

using boost::math::double_constants::pi;

// Up to this many nodes the transform's cosines are tabulated; beyond, it is FFTW's DCT-II,
// planned once per M and thread (an M^2 table would reach 134 MB at
// M = 4096, and the three-term recurrence of T_j loses j ulps: the zone's own operator then
// multiplies coefficient j by j, a first-kind equation's amplification of noise).
constexpr int tabulated = 128;

// The nodes, their roundings and the transform's cosines cos(pi j (i + 1/2) / M) of one M,
// computed once; the cosines stored node by node, so that the transform adds one node's column
// to all coefficients at once.
struct Table {
  std::vector<double> nodes, roundings, cosines;  // cosines[i * M + j], for M <= tabulated
};

const Table& table(int M) {
  static std::mutex mutex;
  static std::map<int, std::unique_ptr<Table>> cache;
  const std::lock_guard<std::mutex> lock(mutex);
  std::unique_ptr<Table>& entry = cache[M];
  if (!entry) {
    entry = std::make_unique<Table>();
    entry->nodes.resize(static_cast<std::size_t>(M));
    entry->roundings.resize(static_cast<std::size_t>(M));
    for (int i = 0; i < M; ++i) {
      const double node = std::cos(pi * (i + 0.5) / M);
      entry->nodes[static_cast<std::size_t>(i)] = node;
      // In long double (11 more bits on x86-64, 49 on binary128; where it is double, none):
      // the rounding to a few digits.
      const long double exact = std::cos(boost::math::long_double_constants::pi * (i + 0.5L) / M);
      entry->roundings[static_cast<std::size_t>(i)] = static_cast<double>(exact - node);
    }
    if (M > tabulated) return *entry;
    entry->cosines.resize(static_cast<std::size_t>(M) * static_cast<std::size_t>(M));
    for (int j = 0; j < M; ++j) {
      for (int i = 0; i < M; ++i) {
        // j (i + 1/2) reduced modulo 2 M before the cosine keeps its argument small.
        const long k = (static_cast<long>(j) * (2 * i + 1)) % (4L * M);
        entry->cosines[static_cast<std::size_t>(i) * static_cast<std::size_t>(M) + static_cast<std::size_t>(j)] =
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

// Eight values of a recurrence side by side, one vector (GCC's vector extension: whatever
// registers the target has); each lane computed as the scalar recurrence computes it.
using Lanes = double __attribute__((vector_size(64)));

// Through memory, without passing a vector by value (whose ABI differs by target).
void load_lanes(Lanes& v, const double* t) { std::memcpy(&v, t, sizeof v); }
void store_lanes(double* out, const Lanes& v) { std::memcpy(out, &v, sizeof v); }

// The recurrence at `points` values of t: 32 at a time in four independent chains of eight
// lanes (one point's recurrence waits on each of its steps; four chains hide the wait), then
// eight at a time, then one by one. Cloned for AVX2 and AVX-512; chebyshev.cpp is compiled
// without contracting products and sums into FMAs, so every CPU gives the scalar code's bits.
__attribute__((target_clones("avx512f", "avx2", "default"))) void clenshaw(const double* c, std::size_t count,
                                                                           const double* t, double* out,
                                                                           std::size_t points, double a, double b) {
  std::size_t first = 0;
  for (; first + 32 <= points && count > 0; first += 32) {
    Lanes t0, t1, t2, t3;
    load_lanes(t0, t + first), load_lanes(t1, t + first + 8), load_lanes(t2, t + first + 16);
    load_lanes(t3, t + first + 24);
    Lanes p0 = {}, p1 = {}, p2 = {}, p3 = {}, q0 = {}, q1 = {}, q2 = {}, q3 = {};  // b_{j+1}, b_{j+2}
    for (std::size_t j = count; j-- > 1;) {
      const Lanes n0 = c[j] + 2 * t0 * p0 - q0, n1 = c[j] + 2 * t1 * p1 - q1, n2 = c[j] + 2 * t2 * p2 - q2,
                  n3 = c[j] + 2 * t3 * p3 - q3;
      q0 = p0, q1 = p1, q2 = p2, q3 = p3;
      p0 = n0, p1 = n1, p2 = n2, p3 = n3;
    }
    store_lanes(out + first, c[0] + p0 * (a * t0 + b) - q0);
    store_lanes(out + first + 8, c[0] + p1 * (a * t1 + b) - q1);
    store_lanes(out + first + 16, c[0] + p2 * (a * t2 + b) - q2);
    store_lanes(out + first + 24, c[0] + p3 * (a * t3 + b) - q3);
  }
  for (; first + 8 <= points && count > 0; first += 8) {
    Lanes t0, p0 = {}, q0 = {};
    load_lanes(t0, t + first);
    for (std::size_t j = count; j-- > 1;) {
      const Lanes n0 = c[j] + 2 * t0 * p0 - q0;
      q0 = p0, p0 = n0;
    }
    store_lanes(out + first, c[0] + p0 * (a * t0 + b) - q0);
  }
  for (; first < points; ++first) out[first] = clenshaw(c, count, t[first], a, b);
}

// out_j = sum_i columns[i M + j] values_i, each sum over i in order: eight coefficients at a
// time (the lanes above), then one by one; cloned as clenshaw is, the same bits on every CPU.
__attribute__((target_clones("avx512f", "avx2", "default"))) void transform_by_columns(const double* columns,
                                                                                       const double* values,
                                                                                       std::size_t M, double* out) {
  std::size_t first = 0;
  for (; first + 8 <= M; first += 8) {
    Lanes sum = {}, column;
    for (std::size_t i = 0; i < M; ++i) {
      load_lanes(column, columns + i * M + first);
      sum += column * values[i];
    }
    store_lanes(out + first, sum);
  }
  for (; first < M; ++first) {
    double sum = 0;
    for (std::size_t i = 0; i < M; ++i) sum += columns[i * M + first] * values[i];
    out[first] = sum;
  }
}

}  // namespace

const std::vector<double>& nodes(int M) { return table(M).nodes; }

const std::vector<double>& node_roundings(int M) { return table(M).roundings; }

void coefficients(const double* values, int M, double* out) {
  if (M > tabulated) {
    // y_j = 2 sum_i v_i cos(pi j (i + 1/2) / M) = 2 sum_i v_i T_j(tau_i).
    CosineTransform& transform = planned_transform(static_cast<std::size_t>(M), CosineTransform::Kind::dct2);
    std::vector<double>& y = transform.data();
    std::copy(values, values + M, y.begin());
    transform.apply();
    for (int j = 0; j < M; ++j) out[j] = y[static_cast<std::size_t>(j)] / (j == 0 ? 2.0 * M : static_cast<double>(M));
    return;
  }
  const Table& t = table(M);
  transform_by_columns(t.cosines.data(), values, static_cast<std::size_t>(M), out);
  for (int j = 0; j < M; ++j) out[j] = (j == 0 ? 1.0 : 2.0) * out[j] / M;
}

std::vector<double> coefficients(const std::vector<double>& values) {
  std::vector<double> out(values.size());
  coefficients(values.data(), static_cast<int>(values.size()), out.data());
  return out;
}

void values(const double* c, int count, int M, double* out) {
  if (M <= tabulated) {
    sums(Kind::t, c, static_cast<std::size_t>(count), nodes(M).data(), out, static_cast<std::size_t>(M));
    return;
  }
  // y_k = x_0 + 2 sum_{j>=1} x_j cos(pi j (k + 1/2) / M) = sum_j c_j T_j(tau_k): the terms past
  // the first halved.
  CosineTransform& transform = planned_transform(static_cast<std::size_t>(M), CosineTransform::Kind::dct3);
  std::vector<double>& y = transform.data();
  std::fill(y.begin(), y.end(), 0.0);
  for (int j = 0; j < count; ++j) y[static_cast<std::size_t>(j)] = j == 0 ? c[0] : c[j] / 2;
  transform.apply();
  std::copy(y.begin(), y.end(), out);
}

std::vector<double> derivative(const std::vector<double>& c) {
  // c'_{j-1} = c'_{j+1} + 2 j c_j from the highest, c'_0 halved.
  const std::size_t n = c.size();
  if (n < 2) return {};
  std::vector<double> d(n - 1, 0.0);
  for (std::size_t j = n - 1; j >= 1; --j)
    d[j - 1] = 2 * static_cast<double>(j) * c[j] + (j + 1 < n - 1 ? d[j + 1] : 0.0);
  d[0] /= 2;
  return d;
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

void sums(Kind kind, const double* c, std::size_t count, const double* t, double* out, std::size_t points) {
  const double a = kind == Kind::t ? 1 : 2, b = kind == Kind::v ? -1 : kind == Kind::w ? 1 : 0;
  clenshaw(c, count, t, out, points, a, b);
}

}  // namespace wavecontact::detail::chebyshev
