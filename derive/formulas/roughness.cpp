#include "roughness.hpp"

#include <stdexcept>
#include <string>

#include <cln/integer.h>

#include "core/symbols.hpp"
#include "profile/block_keer.hpp"
#include "profile/harmonic_part.hpp"

namespace wavecontact::derive {

using GiNaC::ex;
using GiNaC::numeric;

void require_even(int n, const char* function) {
  if (n < 2 || n % 2 != 0) {
    throw std::invalid_argument(std::string(function) + ": n = " + std::to_string(n) + " must be an even integer >= 2");
  }
}

std::vector<numeric> expansion_coefficients(int n) {
  require_even(n, "expansion_coefficients");
  // P(t) = sum_m (-1)^m C(2n, 2m+1) t^m, t = v^2, so that Im((1+iv)^(2n)) = v P(v^2).
  std::vector<cln::cl_I> c(n);
  cln::cl_I binomial = 2 * n;  // C(2n, 1)
  for (int m = 0; m < n; ++m) {
    c[m] = m % 2 == 0 ? binomial : -binomial;
    // C(2n, 2m+3) = C(2n, 2m+1) (2n-2m-1)(2n-2m-2) / ((2m+2)(2m+3))
    binomial = cln::exquo(binomial * (2 * n - 2 * m - 1) * (2 * n - 2 * m - 2), cln::cl_I((2 * m + 2) * (2 * m + 3)));
  }
  // Taylor shift to powers of z = 1 + t: P(t) = sum_i c_i z^i.
  for (int i = 0; i < n - 1; ++i) {
    for (int j = n - 2; j >= i; --j) c[j] = c[j] - c[j + 1];
  }
  // s(v) = v P(t) / (n z^n) = sum_i c_i v / (n z^(n-i)), so k_j = c_(n-j) / n.
  std::vector<numeric> k(n);
  for (int j = 1; j <= n; ++j) k[j - 1] = numeric(cln::cl_I(c[n - j])) / n;
  return k;
}

numeric chebyshev_coefficient(int n, int j) {
  require_even(n, "chebyshev_coefficient");
  const numeric magnitude = GiNaC::binomial(numeric(n - 1 + j), numeric(n - j)) *
                            GiNaC::ex_to<numeric>(GiNaC::pow(numeric(2), 2 * j - 1)) / n;
  return (n - j) % 2 == 0 ? magnitude : -magnitude;
}

ex s_de_moivre(int n) { return sin_multiple(n, sym::v()) / n; }

bool expansion_matches_de_moivre(int n, const std::vector<numeric>& k) {
  require_even(n, "expansion_matches_de_moivre");
  // With t = v^2: eq. 18 times (1+t)^n / v is sum_j k_j (1+t)^(n-j), and de Moivre's
  // Im((1+iv)^(2n)) / (n v) is P(t)/n = sum_m (-1)^m C(2n, 2m+1) t^m / n. Both are
  // polynomials of degree n - 1 in t: equal at the n points t = 0..n-1, they are equal.
  std::vector<numeric> P(n);
  for (int m = 0; m < n; ++m) {
    const numeric c = GiNaC::binomial(numeric(2 * n), numeric(2 * m + 1));
    P[m] = m % 2 == 0 ? c : -c;
  }
  for (int t = 0; t < n; ++t) {
    numeric expansion = 0, direct = 0;  // both by Horner
    for (int j = 1; j <= n; ++j) expansion = expansion * (1 + t) + k[j - 1];
    for (int m = n - 1; m >= 0; --m) direct = direct * t + P[m];
    if (expansion != direct / n) return false;
  }
  return true;
}

double product_form_deviation(int n, int digits) {
  require_even(n, "product_form_deviation");
  const long saved = GiNaC::Digits;
  GiNaC::Digits = digits;
  double worst = 0;
  for (int i = 1; i <= n / 2 + 1; ++i) {
    const numeric v(i, n / 2 + 1);  // rational points in (0, 1]
    const ex w = GiNaC::pow(2 * v / (1 + v * v), 2);
    ex product = 2 * v * (1 - v * v) / GiNaC::pow(1 + v * v, 2);
    for (int k = 1; k <= n / 2 - 1; ++k) {
      product *= 1 - w / GiNaC::pow(GiNaC::sin(k * GiNaC::Pi / n), 2);
    }
    const numeric direct = GiNaC::ex_to<numeric>(s_de_moivre(n).subs(sym::v() == v));  // exact
    const numeric by_product = GiNaC::ex_to<numeric>(product.evalf());
    const numeric scale = GiNaC::abs(direct) > numeric(1, 1000) ? GiNaC::abs(direct) : numeric(1);
    worst = std::max(worst, (GiNaC::abs(by_product - direct) / scale).to_double());
  }
  GiNaC::Digits = saved;
  return worst;
}

ex roughness_profile(int n) { return sym::H2() * GiNaC::cos(n * sym::x()); }

namespace {

// H2 cos(n x^): the cosine sum with A_n = H2 alone.
std::vector<ex> roughness_cosine(int n) {
  std::vector<ex> cosine(n + 1, ex(0));
  cosine[n] = sym::H2();
  return cosine;
}

}  // namespace

ex legendre_dirichlet_pressure(int n) {
  require_even(n, "legendre_dirichlet_pressure");
  return harmonic_pressure(roughness_cosine(n));
}

ex legendre_dirichlet_load(int n) {
  require_even(n, "legendre_dirichlet_load");
  return harmonic_load(roughness_cosine(n));
}

RadicalSum eq19_term(int j, Radicals& radicals) {
  // 1/((alpha^2+1)^(j/2) (u^2+1)^j) = kappa^(-j) / (1+s)^j with kappa = kappa(-1) = sqrt(1+alpha^2).
  const unsigned index = radicals.index_of(-1);
  const ex square = radicals.square(index);
  const ex one_plus_s_power = GiNaC::pow(1 + sym::s(), j);
  if (j % 2 == 0) return RadicalSum::rational(1 / (GiNaC::pow(square, j / 2) * one_plus_s_power));
  return RadicalSum::monomial(RadicalSum::Mask{1} << index, 1 / (GiNaC::pow(square, (j + 1) / 2) * one_plus_s_power));
}

}  // namespace wavecontact::derive
