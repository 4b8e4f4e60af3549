#include "full_contact.hpp"

#include <sstream>
#include <stdexcept>
#include <vector>

#include "hilbert.hpp"
#include "symbols.hpp"

namespace wavecontact::derive {

using GiNaC::ex;

namespace {

// The coefficient of h^order in the Taylor series of the rational function f at h = 0.
ex taylor_coefficient(const ex& f, const GiNaC::symbol& h, int order) {
  const ex series = f.series(h == 0, order + 1);
  return GiNaC::series_to_poly(series).coeff(h, order).normal();
}

}  // namespace

ex full_contact_pressure(const ex& R) {
  const GiNaC::symbol& t = sym::t();
  const ex v = sym::v();
  const ex Y = R.subs(sym::Cx() == (1 - t) / (1 + t)).normal();
  const ex denominator = GiNaC::factor(Y.denom());
  const std::vector<ex> factors = GiNaC::is_a<GiNaC::mul>(denominator)
                                      ? std::vector<ex>(denominator.begin(), denominator.end())
                                      : std::vector<ex>{denominator};
  const GiNaC::symbol h("h");
  ex in_cosine = 0;  // p_fc/((E*/2)(pi/b1)), summed over the poles
  for (const ex& factor_power : factors) {
    const bool power = GiNaC::is_a<GiNaC::power>(factor_power);
    const ex factor = power ? factor_power.op(0) : factor_power;
    if (!factor.has(t)) continue;
    if (factor.degree(t) != 1) {
      std::ostringstream os;
      os << "full_contact_pressure: the factor " << factor << " of the profile's denominator is not linear in v^2";
      throw std::invalid_argument(os.str());
    }
    const int l = power ? GiNaC::ex_to<GiNaC::numeric>(factor_power.op(1)).to_int() : 1;
    const ex tau = (-factor.coeff(t, 0) / factor.coeff(t, 1)).normal();
    // Res_{t=tau} Y(t) v/(sqrt(-t)(v^2 - t)) = (1/sqrt(-tau)) [h^(l-1)] W(tau + h) v (1 + h/tau)^(-1/2)/(v^2 - tau - h),
    // W = (t - tau)^l Y.
    const ex W = (Y * GiNaC::pow(t - tau, l)).normal().subs(t == tau + h);
    ex root_series = 0;  // (1 + h/tau)^(-1/2) to order l - 1: binomial(-1/2, n) (h/tau)^n
    GiNaC::numeric binomial = 1;
    for (int n = 0; n < l; ++n) {
      root_series += binomial * GiNaC::pow(h / tau, n);
      binomial = binomial * (GiNaC::numeric(-1, 2) - n) / (n + 1);
    }
    const ex residue = taylor_coefficient(W * root_series * v / (v * v - tau - h), h, l - 1);
    // (1 + v^2)/2 d/dv of the pole's part of H[Y], even in v: in t, then in Cx.
    const GiNaC::symbol& v_symbol = GiNaC::ex_to<GiNaC::symbol>(v);
    const ex even = even_in_square((residue.diff(v_symbol) * (1 + v * v) / 2).normal(), v_symbol, t);
    in_cosine += even.subs(t == (1 - sym::Cx()) / (1 + sym::Cx())).normal() / GiNaC::sqrt(-tau);
  }
  return sym::E() / 2 * GiNaC::Pi / sym::b1() * in_cosine;
}

}  // namespace wavecontact::derive
