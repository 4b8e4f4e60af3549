#include "hilbert.hpp"

#include <sstream>
#include <stdexcept>
#include <vector>

#include "core/canonical.hpp"
#include "core/printed.hpp"
#include "core/symbols.hpp"

namespace wavecontact::derive {

using GiNaC::ex;
using GiNaC::numeric;

namespace {

// (1/pi) Int v^{2k}/sqrt(alpha^2 - v^2) dv = alpha^{2k} C(2k, k) / 4^k.
ex polynomial_moment(const ex& polynomial, const GiNaC::symbol& t) {
  const ex alpha = sym::alpha();
  ex sum = 0;
  const int degree = polynomial.degree(t);
  for (int k = 0; k <= degree; ++k) {
    const ex c = polynomial.coeff(t, k);
    if (c.is_zero()) continue;
    sum += c * GiNaC::pow(alpha, 2 * k) * GiNaC::binomial(numeric(2 * k), numeric(k)) / GiNaC::pow(numeric(4), k);
  }
  return sum;
}

// The first `count` Taylor coefficients at t = tau of the rational function
// numerator/denominator (polynomials in t): shifted coefficients, then series division.
std::vector<ex> taylor_coefficients(const ex& numerator, const ex& denominator, const ex& tau, int count,
                                    const GiNaC::symbol& t) {
  auto shifted = [&](const ex& polynomial) {
    // c_i of p(tau + h) = sum_i c_i h^i: c_i = sum_k p_k C(k, i) tau^(k - i).
    std::vector<ex> c(count, ex(0));
    const int degree = polynomial.degree(t);
    for (int k = 0; k <= degree; ++k) {
      const ex p_k = polynomial.coeff(t, k);
      if (p_k.is_zero()) continue;
      for (int i = 0; i < count && i <= k; ++i) {
        c[i] += p_k * GiNaC::binomial(numeric(k), numeric(i)) * GiNaC::pow(tau, k - i);
      }
    }
    return c;
  };
  const std::vector<ex> n = shifted(numerator), d = shifted(denominator);
  const ex d0 = d[0].normal();
  std::vector<ex> psi(count);
  for (int i = 0; i < count; ++i) {
    ex sum = n[i];
    for (int j = 1; j <= i; ++j) sum -= d[j] * psi[i - j];
    psi[i] = (sum / d0).normal();
  }
  return psi;
}

// Residue at t = tau of Psi(t)/(t - tau)^order * E1(t): the moment of the pole part.
// With q(t) = t^2 - alpha^2 t = (t kappa)^2, E1 = -1/(t kappa) = E1(tau) (q/q0)^(-1/2)
// near tau, and f = (q(tau + h)/q0)^(-1/2) = sum_n P_n h^n / q0^n obeys q f' = -q' f/2:
//   P_{n+1} = -[(q1 (2n + 1)/2) P_n + n q0 P_{n-1}] / (n + 1),  P_0 = 1,
// q0 = q(tau) = tau^2 kappa^2, q1 = q'(tau) = 2 tau - alpha^2. The residue is
//   E1(tau) sum_n psi_{order-1-n} P_n / q0^n,  psi_i the Taylor coefficients of Psi,
// E1(tau) = -kappa/(tau kappa^2), one radical times a rational function: no derivatives
// of E1, whose expressions swell with the order.
RadicalSum pole_moment(const ex& Psi_numerator, const ex& Psi_denominator, const ex& tau, int order,
                       const GiNaC::symbol& t, Radicals& radicals) {
  const ex alpha_squared = GiNaC::pow(sym::alpha(), 2);
  const ex q0 = (tau * (tau - alpha_squared)).expand(), q1 = (2 * tau - alpha_squared).expand();
  const std::vector<ex> psi = taylor_coefficients(Psi_numerator, Psi_denominator, tau, order, t);
  ex previous = 0, current = 1;  // P_{n-1}, P_n
  ex sum = 0;                    // sum_n psi_{order-1-n} P_n q0^(order-1-n)
  for (int n = 0; n < order; ++n) {
    sum += psi[order - 1 - n] * current * GiNaC::pow(q0, order - 1 - n);
    const ex next = (-(q1 * numeric(2 * n + 1, 2) * current + n * q0 * previous) / numeric(n + 1)).expand();
    previous = current;
    current = next;
  }
  const unsigned index = radicals.index_of(tau);
  // E1(tau) / q0^(order-1) = -kappa/(tau kappa^2 q0^(order-1)) = -kappa tau / q0^order.
  return RadicalSum::monomial(RadicalSum::Mask{1} << index, (-tau * sum / GiNaC::pow(q0, order)).normal());
}

// M[numerator/(denominator constant)] for polynomials numerator, denominator in t and a
// t-free constant (no radicals): a quotient taken as it is, without a gcd.
RadicalSum fraction_moment(const ex& numerator, const ex& denominator, const ex& constant, Radicals& radicals) {
  const GiNaC::symbol& t = sym::t();
  if (!numerator.is_polynomial(t) || !denominator.is_polynomial(t)) {
    throw std::invalid_argument("weighted_moment: integrand is not rational in t: " + printed(numerator / denominator));
  }
  const ex polynomial_part = GiNaC::quo(numerator, denominator, t);
  const ex remainder = GiNaC::rem(numerator, denominator, t);
  RadicalSum result = RadicalSum::rational(polynomial_moment(polynomial_part, t) / constant);
  if (remainder.is_zero() || denominator.degree(t) == 0) return result;

  const ex factored = GiNaC::factor(denominator);
  // Poles in a fixed order, so radicals are numbered the same on every run.
  const std::vector<ex> factors =
      GiNaC::is_a<GiNaC::mul>(factored) ? sorted_operands(factored) : std::vector<ex>{factored};
  for (const ex& factor_power : factors) {
    const bool is_power = GiNaC::is_a<GiNaC::power>(factor_power);
    const ex base = is_power ? factor_power.op(0) : factor_power;
    if (!base.has(t)) continue;
    if (!is_power && !factor_power.has(t)) continue;
    const int order = is_power ? GiNaC::ex_to<numeric>(factor_power.op(1)).to_int() : 1;
    if (base.degree(t) != 1) {
      throw std::invalid_argument("weighted_moment: denominator factor " + printed(base) +
                                  " is not linear in v^2; only poles t = tau in v^2 over the rationals of the "
                                  "parameters are supported");
    }
    const ex a1 = base.coeff(t, 1), a0 = base.coeff(t, 0);
    const ex tau = (-a0 / a1).normal();
    const ex rest = GiNaC::quo(denominator, GiNaC::pow(base, order).expand(), t);
    result +=
        pole_moment(remainder, (GiNaC::pow(a1, order) * rest).expand(), tau, order, t, radicals).scaled(1 / constant);
  }
  return result;
}

// M[Phi] for a rational Phi without radicals.
RadicalSum rational_moment(const ex& Phi, Radicals& radicals) {
  const ex nd = Phi.normal().numer_denom();
  return fraction_moment(nd.op(0).expand(), nd.op(1).expand(), 1, radicals);
}

}  // namespace

ex even_in_square(const ex& e, const GiNaC::symbol& v, const GiNaC::symbol& t) {
  const ex nd = e.normal().numer_denom();
  auto convert = [&](const ex& polynomial) {
    const ex p = polynomial.expand();
    if (!p.is_polynomial(v)) {
      throw std::invalid_argument("even_in_square: not rational in " + printed(v) + ": " + printed(e));
    }
    ex result = 0;
    for (int k = p.ldegree(v); k <= p.degree(v); ++k) {
      const ex c = p.coeff(v, k);
      if (c.is_zero()) continue;
      if (k % 2 != 0) {
        throw std::invalid_argument("even_in_square: not even in " + printed(v) + ": " + printed(e));
      }
      result += c * GiNaC::pow(t, k / 2);
    }
    return result;
  };
  return convert(nd.op(0)) / convert(nd.op(1));
}

RadicalSum weighted_moment(const RadicalSum& Phi, Radicals& radicals) {
  RadicalSum result;
  for (const auto& [mask, coefficient] : Phi.terms()) {
    result += RadicalSum::monomial(mask, 1).times(rational_moment(coefficient, radicals), radicals);
  }
  return result.normalized();
}

RadicalSum bounded_inversion(const ex& g, Radicals& radicals) {
  const GiNaC::symbol &v = sym::v(), &t = sym::t(), &s = sym::s();
  if (!(g.subs(v == -v) + g).normal().is_zero()) {
    throw std::invalid_argument("bounded_inversion: g(v) is not odd: " + printed(g));
  }
  // Gamma(t) = v g(v) = N(t)/Q(t) is even in v. The divided difference is
  // [N(t) Q(s) - N(s) Q(t)] / (t - s) over Q(t) Q(s): the division by t - s is exact, and
  // Q(s) is a constant of the moment in t.
  const ex Gamma = even_in_square(v * g, v, t).numer_denom();
  const ex N = Gamma.op(0).expand(), Q = Gamma.op(1).expand();
  const ex Q_s = Q.subs(t == s);
  const ex numerator = GiNaC::quo((N * Q_s - N.subs(t == s) * Q).expand(), t - s, t);
  return fraction_moment(numerator, Q, Q_s, radicals).normalized();
}

RadicalSum load_integral(const RadicalSum& I, Radicals& radicals) {
  // P = 2 Int sqrt(alpha^2 - u^2) I(u^2)/(1 + u^2) du
  //   = 2 pi M[(alpha^2 - t) I(t)/(1 + t)].
  // (pi stays outside: the engine's polynomial algebra is over the rationals.)
  const GiNaC::symbol &t = sym::t(), &s = sym::s();
  const ex weight = 2 * (GiNaC::pow(sym::alpha(), 2) - t) / (1 + t);
  const RadicalSum integrand = I.transformed([&](const ex& c) { return (c.subs(s == t) * weight).normal(); });
  return weighted_moment(integrand, radicals).scaled(GiNaC::Pi);
}

}  // namespace wavecontact::derive
