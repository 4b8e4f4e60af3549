#include "hilbert.hpp"

#include <sstream>
#include <stdexcept>
#include <vector>

#include "canonical.hpp"
#include "symbols.hpp"

namespace wavecontact::derive {

using GiNaC::ex;
using GiNaC::numeric;

namespace {

std::string str(const ex& e) {
  std::ostringstream os;
  os << e;
  return os.str();
}

// (1/pi) Int v^{2k}/sqrt(alpha^2 - v^2) dv = alpha^{2k} C(2k, k) / 4^k.
ex polynomial_moment(const ex& polynomial, const GiNaC::symbol& t) {
  const ex alpha = sym::alpha();
  ex sum = 0;
  const int degree = polynomial.degree(t);
  for (int k = 0; k <= degree; ++k) {
    const ex c = polynomial.coeff(t, k);
    if (c.is_zero()) continue;
    sum += c * GiNaC::pow(alpha, 2 * k) * GiNaC::binomial(numeric(2 * k), numeric(k)) /
           GiNaC::pow(numeric(4), k);
  }
  return sum;
}

// A polynomial in w = 1/kappa(t) with coefficients rational in t: the form in which
// E1(t) = -w/t and all its t-derivatives live, since dw/dt = -alpha^2 w^3 / (2 t^2).
using WPolynomial = std::vector<ex>;

WPolynomial derivative(const WPolynomial& f, const GiNaC::symbol& t) {
  const ex alpha = sym::alpha();
  WPolynomial d(f.size() + 2, ex(0));
  for (std::size_t j = 0; j < f.size(); ++j) {
    if (f[j].is_zero()) continue;
    d[j] += f[j].diff(t);
    if (j > 0) d[j + 2] -= numeric(static_cast<long>(j)) * f[j] * GiNaC::pow(alpha, 2) /
                          (2 * GiNaC::pow(t, 2));
  }
  for (auto& c : d) c = c.normal();
  return d;
}

// Residue at t = tau of Psi(t)/(t - tau)^order * E1(t): the moment of the pole part.
RadicalSum pole_moment(const ex& Psi, const ex& tau, int order, const GiNaC::symbol& t,
                       Radicals& radicals) {
  WPolynomial f{ex(0), (-Psi / t).normal()};
  for (int k = 1; k < order; ++k) f = derivative(f, t);
  const unsigned index = radicals.index_of(tau);
  const ex square = radicals.square(index);
  ex rational_part = 0, kappa_part = 0;
  for (std::size_t j = 0; j < f.size(); ++j) {
    if (f[j].is_zero()) continue;
    const ex c = f[j].subs(t == tau);
    // w^j = kappa^{-j}: kappa / square^{(j+1)/2} for odd j, 1/square^{j/2} for even j.
    if (j % 2 == 1) {
      kappa_part += c / GiNaC::pow(square, static_cast<long>((j + 1) / 2));
    } else {
      rational_part += c / GiNaC::pow(square, static_cast<long>(j / 2));
    }
  }
  const ex scale = 1 / GiNaC::factorial(numeric(order - 1));
  RadicalSum r = RadicalSum::rational(rational_part * scale);
  r += RadicalSum::monomial(RadicalSum::Mask{1} << index, kappa_part * scale);
  return r;
}

// M[Phi] for a rational Phi without radicals.
RadicalSum rational_moment(const ex& Phi, Radicals& radicals) {
  const GiNaC::symbol& t = sym::t();
  const ex nd = Phi.normal().numer_denom();
  const ex numerator = nd.op(0).expand(), denominator = nd.op(1).expand();
  if (!numerator.is_polynomial(t) || !denominator.is_polynomial(t)) {
    throw std::invalid_argument("weighted_moment: integrand is not rational in t: " + str(Phi));
  }
  const ex polynomial_part = GiNaC::quo(numerator, denominator, t);
  const ex remainder = GiNaC::rem(numerator, denominator, t);
  RadicalSum result = RadicalSum::rational(polynomial_moment(polynomial_part, t));
  if (remainder.is_zero() || denominator.degree(t) == 0) return result;

  const ex factored = GiNaC::factor(denominator);
  // Poles in a fixed order, so radicals are numbered the same on every run.
  const std::vector<ex> factors = GiNaC::is_a<GiNaC::mul>(factored)
                                      ? sorted_operands(factored)
                                      : std::vector<ex>{factored};
  for (const ex& factor_power : factors) {
    const bool is_power = GiNaC::is_a<GiNaC::power>(factor_power);
    const ex base = is_power ? factor_power.op(0) : factor_power;
    if (!base.has(t)) continue;
    if (!is_power && !factor_power.has(t)) continue;
    const int order = is_power ? GiNaC::ex_to<numeric>(factor_power.op(1)).to_int() : 1;
    if (base.degree(t) != 1) {
      throw std::invalid_argument(
          "weighted_moment: denominator factor " + str(base) +
          " is not linear in v^2; only poles t = tau in v^2 over the rationals of the "
          "parameters are supported");
    }
    const ex a1 = base.coeff(t, 1), a0 = base.coeff(t, 0);
    const ex tau = (-a0 / a1).normal();
    const ex rest = GiNaC::quo(denominator, GiNaC::pow(base, order).expand(), t);
    const ex Psi = (remainder / (GiNaC::pow(a1, order) * rest)).normal();
    result += pole_moment(Psi, tau, order, t, radicals);
  }
  return result.normalized();
}

}  // namespace

ex even_in_square(const ex& e, const GiNaC::symbol& v, const GiNaC::symbol& t) {
  const ex nd = e.normal().numer_denom();
  auto convert = [&](const ex& polynomial) {
    const ex p = polynomial.expand();
    if (!p.is_polynomial(v)) {
      throw std::invalid_argument("even_in_square: not rational in " + str(v) + ": " + str(e));
    }
    ex result = 0;
    for (int k = p.ldegree(v); k <= p.degree(v); ++k) {
      const ex c = p.coeff(v, k);
      if (c.is_zero()) continue;
      if (k % 2 != 0) {
        throw std::invalid_argument("even_in_square: not even in " + str(v) + ": " + str(e));
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
    result += RadicalSum::monomial(mask, 1).times(rational_moment(coefficient, radicals),
                                                  radicals);
  }
  return result.normalized();
}

RadicalSum bounded_inversion(const ex& g, Radicals& radicals) {
  const GiNaC::symbol &v = sym::v(), &t = sym::t(), &s = sym::s();
  if (!(g.subs(v == -v) + g).normal().is_zero()) {
    throw std::invalid_argument("bounded_inversion: g(v) is not odd: " + str(g));
  }
  // Gamma(t) = v g(v) is even in v.
  const ex Gamma = even_in_square(v * g, v, t);
  const ex divided_difference = ((Gamma - Gamma.subs(t == s)) / (t - s)).normal();
  return weighted_moment(RadicalSum::rational(divided_difference), radicals);
}

RadicalSum load_integral(const RadicalSum& I, Radicals& radicals) {
  // P = 2 Int sqrt(alpha^2 - u^2) I(u^2)/(1 + u^2) du
  //   = 2 pi M[(alpha^2 - t) I(t)/(1 + t)].
  // (pi stays outside: the engine's polynomial algebra is over the rationals.)
  const GiNaC::symbol &t = sym::t(), &s = sym::s();
  const ex weight = 2 * (GiNaC::pow(sym::alpha(), 2) - t) / (1 + t);
  const RadicalSum integrand =
      I.transformed([&](const ex& c) { return (c.subs(s == t) * weight).normal(); });
  return weighted_moment(integrand, radicals).scaled(GiNaC::Pi);
}

}  // namespace wavecontact::derive
