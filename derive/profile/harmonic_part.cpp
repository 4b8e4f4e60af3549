#include "harmonic_part.hpp"

#include <stdexcept>

#include "core/symbols.hpp"

namespace wavecontact::derive {

using GiNaC::ex;
using GiNaC::numeric;

std::vector<ex> chebyshev_t_coefficients(const ex& polynomial, const ex& c) {
  // c^i = 2^(1-i) sum_{j < i/2} C(i, j) T_{i-2j}(c) + 2^(-i) C(i, i/2) T_0 (i even).
  const ex p = polynomial.expand();
  const int degree = p.degree(c);
  std::vector<ex> T(degree + 1, ex(0));
  for (int i = 0; i <= degree; ++i) {
    const ex a = p.coeff(c, i);
    if (a.is_zero()) continue;
    const numeric half_power = GiNaC::ex_to<numeric>(GiNaC::pow(numeric(2), -i));
    numeric binomial = 1;  // C(i, j)
    for (int j = 0; 2 * j <= i; ++j) {
      T[i - 2 * j] += (2 * j == i ? half_power : 2 * half_power) * binomial * a;
      binomial = binomial * (i - j) / (j + 1);
    }
  }
  for (auto& coefficient : T) coefficient = coefficient.expand();
  return T;
}

HarmonicSplit split_harmonic_part(const ex& Y) {
  const GiNaC::symbol& c = sym::Cx();
  const ex nd = Y.normal().numer_denom();
  const ex numerator = nd.op(0).expand(), denominator = nd.op(1).expand();
  if (!numerator.is_polynomial(c) || !denominator.is_polynomial(c)) {
    throw std::invalid_argument("split_harmonic_part: not rational in cos x");
  }
  // A denominator free of c is Y's own: its inverse adds no singularity.
  if (denominator.degree(c) > 0 && !GiNaC::is_a<numeric>(denominator.lcoeff(c))) return {{}, Y};
  if (numerator.degree(c) < 1) return {{}, Y};
  if (denominator.degree(c) == 0) return {chebyshev_t_coefficients(numerator / denominator, c), 0};
  const ex quotient = GiNaC::quo(numerator, denominator, c);
  if (quotient.degree(c) < 1) return {{}, Y};
  return {chebyshev_t_coefficients(quotient, c), (GiNaC::rem(numerator, denominator, c) / denominator).normal()};
}

ex legendre_polynomial(int k, const ex& y) {
  ex previous = 1, current = y;
  if (k == 0) return previous;
  for (int i = 1; i < k; ++i) {
    const ex next = ((2 * i + 1) * y * current - i * previous) / (i + 1);
    previous = current;
    current = next.expand();
  }
  return current;
}

namespace {

// P_0..P_K(Ca).
std::vector<ex> legendre_polynomials(int K) {
  std::vector<ex> P;
  for (int k = 0; k <= K; ++k) P.push_back(legendre_polynomial(k, sym::Ca()));
  return P;
}

}  // namespace

ex harmonic_pressure(const std::vector<ex>& cosine) {
  const ex Cx = sym::Cx();
  const int K = static_cast<int>(cosine.size()) - 1;
  const std::vector<ex> P = legendre_polynomials(K);
  ex sum = 0, v_previous = 1, v_current = 1;  // V_0 = 1, V_1 = 2x - 1
  for (int j = 0; j < K; ++j) {
    if (j == 1) v_current = 2 * Cx - 1;
    if (j >= 2) {
      const ex next = (2 * Cx * v_current - v_previous).expand();
      v_previous = v_current;
      v_current = next;
    }
    ex B = 0;
    for (int k = j + 1; k <= K; ++k) B += k * cosine[k] * P[k - 1 - j];
    sum += B * v_current;
  }
  return sym::E() / 2 * GiNaC::sqrt(sym::D() * (1 + Cx)) * sum.expand();
}

ex harmonic_load(const std::vector<ex>& cosine) {
  const int K = static_cast<int>(cosine.size()) - 1;
  const std::vector<ex> P = legendre_polynomials(K);
  ex sum = 0;
  for (int k = 1; k <= K; ++k) sum += k * cosine[k] * (P[k - 1] - P[k]);
  return GiNaC::Pi / 2 * sym::E() * sum.expand();
}

ex harmonic_load_slope_factor(const std::vector<ex>& cosine) {
  // P depends on a^ through Ca alone: dP/dSa - dP/dCa = -dP/dCa.
  return -harmonic_load(cosine).diff(sym::Ca());
}

}  // namespace wavecontact::derive
