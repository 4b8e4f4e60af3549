#include "minimax.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace wavecontact::derive {

using GiNaC::numeric;

namespace {

numeric horner(const std::vector<numeric>& p, const numeric& u) {
  numeric value = 0;
  for (auto c = p.rbegin(); c != p.rend(); ++c) value = value * u + *c;
  return value;
}

// Solves A x = b by Gaussian elimination with partial pivoting (A square, small).
std::vector<numeric> solve(std::vector<std::vector<numeric>> A, std::vector<numeric> b) {
  const std::size_t n = b.size();
  for (std::size_t column = 0; column < n; ++column) {
    std::size_t pivot = column;
    for (std::size_t row = column + 1; row < n; ++row) {
      if (GiNaC::abs(A[row][column]) > GiNaC::abs(A[pivot][column])) pivot = row;
    }
    std::swap(A[column], A[pivot]);
    std::swap(b[column], b[pivot]);
    for (std::size_t row = column + 1; row < n; ++row) {
      const numeric factor = A[row][column] / A[column][column];
      for (std::size_t k = column; k < n; ++k) A[row][k] -= factor * A[column][k];
      b[row] -= factor * b[column];
    }
  }
  std::vector<numeric> x(n);
  for (std::size_t row = n; row-- > 0;) {
    numeric sum = b[row];
    for (std::size_t k = row + 1; k < n; ++k) sum -= A[row][k] * x[k];
    x[row] = sum / A[row][row];
  }
  return x;
}

// The point of largest |e| in [lo, hi] near a sampled maximum (golden section; |e| is
// unimodal there).
std::pair<numeric, numeric> refine_maximum(const std::function<numeric(const numeric&)>& e, numeric lo, numeric hi) {
  const numeric ratio = (GiNaC::sqrt(numeric(5)) - 1) / 2;
  numeric x1 = hi - ratio * (hi - lo), x2 = lo + ratio * (hi - lo);
  numeric f1 = GiNaC::abs(e(x1)), f2 = GiNaC::abs(e(x2));
  for (int i = 0; i < 60; ++i) {
    if (f1 > f2) {
      hi = x2, x2 = x1, f2 = f1;
      x1 = hi - ratio * (hi - lo), f1 = GiNaC::abs(e(x1));
    } else {
      lo = x1, x1 = x2, f1 = f2;
      x2 = lo + ratio * (hi - lo), f2 = GiNaC::abs(e(x2));
    }
  }
  const numeric x = (lo + hi) / 2;
  return {x, e(x)};
}

// The local extrema of e over [lo, hi], alternating in sign: the largest |e| of each run
// of one sign among `samples` points, refined, the interval's ends included as sampled.
std::vector<std::pair<numeric, numeric>> alternating_extrema(const std::function<numeric(const numeric&)>& e,
                                                             const numeric& lo, const numeric& hi, int samples) {
  std::vector<numeric> u(samples), value(samples);
  for (int i = 0; i < samples; ++i) {
    u[i] = lo + (hi - lo) * i / (samples - 1);
    value[i] = e(u[i]);
  }
  std::vector<std::pair<numeric, numeric>> extrema;
  int start = 0;
  while (start < samples) {
    int end = start, best = start;
    while (end < samples && value[end].is_negative() == value[start].is_negative()) {
      if (GiNaC::abs(value[end]) > GiNaC::abs(value[best])) best = end;
      ++end;
    }
    if (best == 0 || best == samples - 1) {
      extrema.emplace_back(u[best], value[best]);
    } else {
      extrema.push_back(refine_maximum(e, u[best - 1], u[best + 1]));
    }
    start = end;
  }
  return extrema;
}

}  // namespace

numeric nearest_double(const numeric& q) {
  int exponent = 0;
  const double mantissa = std::frexp(q.to_double(), &exponent);
  const auto integer = static_cast<long long>(std::ldexp(mantissa, 53));
  return numeric(static_cast<long>(integer)) * GiNaC::ex_to<numeric>(GiNaC::pow(numeric(2), exponent - 53));
}

std::vector<numeric> remez(const Function& f, const numeric& lo, const numeric& hi, int degree) {
  const int points = degree + 2;
  const numeric pi = GiNaC::ex_to<numeric>(GiNaC::Pi.evalf());
  std::vector<numeric> reference(points);
  for (int i = 0; i < points; ++i) {  // Chebyshev extrema, ends included
    reference[i] = (lo + hi) / 2 - (hi - lo) / 2 * GiNaC::cos(pi * i / (points - 1));
  }
  for (int iteration = 0; iteration < 60; ++iteration) {
    // p(u_i) - (-1)^i E f(u_i) = f(u_i): the relative error levelled at +-E.
    std::vector<std::vector<numeric>> A(points, std::vector<numeric>(points));
    std::vector<numeric> b(points);
    for (int i = 0; i < points; ++i) {
      const numeric fi = f(reference[i]);
      numeric power = 1;
      for (int k = 0; k <= degree; ++k, power *= reference[i]) A[i][k] = power;
      A[i][degree + 1] = i % 2 == 0 ? -fi : fi;
      b[i] = fi;
    }
    std::vector<numeric> p = solve(A, b);
    const numeric levelled = GiNaC::abs(p.back());
    p.pop_back();
    const auto error = [&](const numeric& u) { return horner(p, u) / f(u) - 1; };
    auto extrema = alternating_extrema(error, lo, hi, 40 * points);
    while (static_cast<int>(extrema.size()) > points) {  // drop the smaller end
      if (GiNaC::abs(extrema.front().second) < GiNaC::abs(extrema.back().second)) {
        extrema.erase(extrema.begin());
      } else {
        extrema.pop_back();
      }
    }
    if (static_cast<int>(extrema.size()) < points) {
      throw std::runtime_error("remez: the error does not alternate at degree " + std::to_string(degree));
    }
    numeric largest = 0;
    for (int i = 0; i < points; ++i) {
      reference[i] = extrema[i].first;
      largest =
          std::max(largest, GiNaC::abs(extrema[i].second), [](const numeric& x, const numeric& y) { return x < y; });
    }
    if ((largest - levelled) / largest < numeric(1, 1000000)) return p;
  }
  throw std::runtime_error("remez: no levelled error after 60 iterations at degree " + std::to_string(degree));
}

numeric max_relative_error(const Function& f, const std::vector<numeric>& p, const numeric& lo, const numeric& hi) {
  const auto error = [&](const numeric& u) { return horner(p, u) / f(u) - 1; };
  numeric largest = 0;
  for (const auto& [u, e] : alternating_extrema(error, lo, hi, 400 * static_cast<int>(p.size()))) {
    largest = std::max(largest, GiNaC::abs(e), [](const numeric& x, const numeric& y) { return x < y; });
  }
  return largest;
}

}  // namespace wavecontact::derive
