#include "full_contact.hpp"

#include <algorithm>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "hilbert.hpp"
#include "sub_interval.hpp"
#include "canonical.hpp"
#include "symbols.hpp"

namespace wavecontact::derive {

using GiNaC::ex;
using GiNaC::numeric;

namespace {

ex conjugate_logarithm_evalf(const ex& a, const ex& b, const ex& a_minus_b) {
  const ex values[] = {a.evalf(), b.evalf(), a_minus_b.evalf()};
  for (const ex& value : values) {
    if (!GiNaC::is_a<numeric>(value) || !GiNaC::ex_to<numeric>(value).is_real()) {
      return conjugate_logarithm(a, b, a_minus_b).hold();
    }
  }
  const numeric A = GiNaC::ex_to<numeric>(values[0]), B = GiNaC::ex_to<numeric>(values[1]);
  const numeric difference = GiNaC::ex_to<numeric>(values[2]);
  if (A.is_negative() || B.is_negative() || (A + B).is_zero()) {
    throw std::domain_error("conjugate_logarithm: a, b >= 0 and a + b > 0");
  }
  if (difference.is_zero() || A.is_zero()) return 0;
  if (B.is_zero()) return 2;
  // s^2 = min/max, atanh(s) = log(1 + s) - log(1 - s^2)/2 with 1 - s^2 = |a - b|/max: exact
  // however close a and b are.
  const numeric larger = A > B ? A : B, s = GiNaC::sqrt((A > B ? B : A) / larger);
  const numeric atanh = GiNaC::log(1 + s) - GiNaC::log(GiNaC::abs(difference) / larger) / 2;
  return difference / (A + B) * (A > B ? 2 * atanh / s : 2 * s * atanh);
}

// The coefficient of h^order in the Taylor series of the rational function f at h = 0.
ex taylor_coefficient(const ex& f, const GiNaC::symbol& h, int order) {
  const ex series = f.series(h == 0, order + 1);
  return GiNaC::series_to_poly(series).coeff(h, order).normal();
}

// Y(t) = W(t)/(t - tau)^order near each pole tau of Y.
struct Pole {
  ex tau;
  int order;
  ex regular;  // W, without the pole
};

std::vector<Pole> poles_in(const ex& Y, const GiNaC::symbol& t) {
  const ex denominator = GiNaC::factor(Y.denom());
  const std::vector<ex> factors = GiNaC::is_a<GiNaC::mul>(denominator)
                                      ? std::vector<ex>(denominator.begin(), denominator.end())
                                      : std::vector<ex>{denominator};
  std::vector<Pole> poles;
  for (const ex& factor_power : factors) {
    const bool power = GiNaC::is_a<GiNaC::power>(factor_power);
    const ex factor = power ? factor_power.op(0) : factor_power;
    if (!factor.has(t)) continue;
    if (factor.degree(t) != 1) {
      std::ostringstream os;
      os << "full_contact_pressure: the factor " << factor << " of the profile's denominator is not linear in v^2";
      throw std::invalid_argument(os.str());
    }
    const int order = power ? GiNaC::ex_to<numeric>(factor_power.op(1)).to_int() : 1;
    const ex tau = (-factor.coeff(t, 0) / factor.coeff(t, 1)).normal();
    poles.push_back({tau, order, (Y * GiNaC::pow(t - tau, order)).normal()});
  }
  return poles;
}

ex in_square(const ex& R) { return R.subs(sym::Cx() == (1 - sym::t()) / (1 + sym::t())).normal(); }

ex in_cosine_of(const ex& e) { return e.subs(sym::t() == (1 - sym::Cx()) / (1 + sym::Cx())).normal(); }

// rho(t) of one piece of a profile built with abs() (full_contact.hpp): the B_i(tau) of
// [0, beta] (top) or [beta, inf).
ex piece_rho(const ex& Y, const numeric& beta, bool top) {
  const GiNaC::symbol& t = sym::t();
  const GiNaC::symbol h("h");
  const numeric beta2 = beta * beta;
  ex rho = 0;
  for (const Pole& pole : poles_in(Y, t)) {
    const ex& tau = pole.tau;
    const ex W = pole.regular.subs(t == tau + h);
    for (int l = 1; l <= pole.order; ++l) {
      const ex c = taylor_coefficient(W, h, pole.order - l);  // of 1/(t - tau)^l
      for (int i = 1; i <= l; ++i) {
        const ex B = top ? beta * GiNaC::pow(-tau, -i) *
                               quadratic_moment(0, i, (-beta2 / tau).normal(), ((tau - beta2) / tau).normal())
                         : GiNaC::pow(beta, 1 - 2 * i) *
                               quadratic_moment(i - 1, i, (-tau / beta2).normal(), ((beta2 - tau) / beta2).normal());
        rho += 2 * c * B / GiNaC::pow(t - tau, l + 1 - i);
      }
    }
  }
  return rho;
}

// The moments of a piece of a profile built with abs() for a point on one side (full_contact.hpp):
// I_{j,l} and J_{j,l} over [0, beta] (top) or [beta, inf), with y of the Cauchy factor 1/(t - u^2).
struct Piece {
  numeric beta;
  bool top;
  // Int_piece du/(u^2 - tau)^i.
  ex power(const ex& tau, int i) const {
    const numeric beta2 = beta * beta;
    return top ? beta * GiNaC::pow(-tau, -i) *
                     quadratic_moment(0, i, (-beta2 / tau).normal(), ((tau - beta2) / tau).normal())
               : GiNaC::pow(beta, 1 - 2 * i) *
                     quadratic_moment(i - 1, i, (-tau / beta2).normal(), ((beta2 - tau) / beta2).normal());
  }
  // Int_piece du/(t - u^2) with t on the piece (principal value): Lambda/(2v) on [0, beta],
  // -Lambda/(2v) beyond, Lambda = log|(v + beta)/(v - beta)|.
  ex cauchy_on() const {
    const GiNaC::symbol& t = sym::t();
    const numeric beta2 = beta * beta;
    return top ? 1 / beta * quadratic_moment(0, 1, -t / beta2, (beta2 - t) / beta2)
               : -beta / t * quadratic_moment(0, 1, -beta2 / t, (t - beta2) / t);
  }
  // The same with t off the piece: Lambda/(2v) from [0, beta], -Lambda/(2v) from beyond.
  ex cauchy_off() const {
    const GiNaC::symbol& t = sym::t();
    const numeric beta2 = beta * beta;
    return top ? beta / t * quadratic_moment(0, 1, -beta2 / t, (t - beta2) / t)
               : -1 / beta * quadratic_moment(0, 1, -t / beta2, (beta2 - t) / beta2);
  }
  // Int_piece du/((u^2 - tau)^l (t - u^2)), t off the piece.
  ex cauchy_power(const ex& tau, int l) const {
    const GiNaC::symbol& t = sym::t();
    const numeric beta2 = beta * beta;
    return top ? beta / t * GiNaC::pow(-tau, -l) *
                     two_factor_moment(0, l, -beta2 / t, (t - beta2) / t, (-beta2 / tau).normal(),
                                       ((tau - beta2) / tau).normal())
               : -GiNaC::pow(beta, -1 - 2 * l) *
                     two_factor_moment(l, l, -t / beta2, (beta2 - t) / beta2, (-tau / beta2).normal(),
                                       ((beta2 - tau) / beta2).normal());
  }
};

// The partial fractions of F in the variable x: sum c/(x - tau)^l, each term passed to term(c, tau, l);
// returns the rest, F minus that sum.
ex partial_fractions(const ex& F, const GiNaC::symbol& x, const std::function<void(const ex&, const ex&, int)>& term) {
  const GiNaC::symbol h("h");
  ex rest = F;
  for (const Pole& pole : poles_in(F, x)) {
    const ex W = pole.regular.subs(x == pole.tau + h);
    for (int l = 1; l <= pole.order; ++l) {
      const ex c = taylor_coefficient(W, h, pole.order - l);
      term(c, pole.tau, l);
      rest -= c / GiNaC::pow(x - pole.tau, l);
    }
  }
  return rest.normal();
}

// Int_piece F(u^2)/(t - u^2) du for t on the piece (principal value), F rational and bounded
// at infinity: (F(s) - F(t))/(t - s), free of the pole at s = t, by partial fractions in s, plus
// F(t) times the piece's Cauchy integral with t on it.
ex own_piece(const ex& F, const Piece& piece) {
  const GiNaC::symbol& t = sym::t();
  const GiNaC::symbol s("s");
  const ex quotient = ((F.subs(t == s) - F) / (t - s)).normal();
  ex integral = 0;
  const ex rest = partial_fractions(quotient, s, [&](const ex& c, const ex& tau, int l) { integral += c * piece.power(tau, l); });
  if (!rest.is_zero()) throw std::logic_error("full_contact_pressure: the profile's slope is not bounded at x^ = pi");
  return integral + F * piece.cauchy_on();
}

// Int_piece F(u^2)/(t - u^2) du for t off the piece, the Cauchy factor kept beside each pole
// factor (J_{j,l}): no coefficient has a pole where t meets the pole of F, on the other side.
ex other_piece(const ex& F, const Piece& piece) {
  const GiNaC::symbol& t = sym::t();
  ex integral = 0;
  const ex constant = partial_fractions(F, t, [&](const ex& c, const ex& tau, int l) { integral += c * piece.cauchy_power(tau, l); });
  if (constant.has(t)) throw std::logic_error("full_contact_pressure: the profile's slope is not bounded at x^ = pi");
  return integral + constant * piece.cauchy_off();
}

// Rewrites the arguments of the atoms from t to Cx, each factored (1 + y, 1 + z as products
// such as (Cx - c)/(1 + Cx), which keep their digits where they vanish).
struct AtomsInCosine : GiNaC::map_function {
  ex operator()(const ex& e) override {
    if (GiNaC::is_a<GiNaC::function>(e)) {
      GiNaC::exvector arguments;
      for (const ex& argument : e) arguments.push_back(GiNaC::factor(in_cosine_of(argument)));
      GiNaC::function f = GiNaC::ex_to<GiNaC::function>(e);
      for (std::size_t i = 0; i < arguments.size(); ++i) f.let_op(i) = arguments[i];
      return f;
    }
    return e.map(*this);
  }
};

// tan(x^/2) at the branch point, rational (branches.hpp).
numeric branch_tangent(const numeric& cosine) {
  const ex beta = GiNaC::sqrt((1 - cosine) / (1 + cosine));
  if (!GiNaC::is_a<numeric>(beta) || !GiNaC::ex_to<numeric>(beta).is_rational()) {
    throw std::invalid_argument("full_contact_pressure: tan(x^/2) at the branch point is not rational");
  }
  return GiNaC::ex_to<numeric>(beta);
}

// num/den with both expanded and the sign fixed (canonical.hpp): the same expression on every run.
ex fixed_fraction(const ex& e) {
  const ex nd = e.normal().numer_denom();
  ex numerator = nd.op(0).expand(), denominator = nd.op(1).expand();
  if (leading_term_negative(denominator)) numerator = (-numerator).expand(), denominator = (-denominator).expand();
  return numerator / denominator;
}

// sum_k c_k A_k + c_0 for the atoms A_k (functions) of e, linear in them: each coefficient one
// rational function.
ex collect_atoms(const ex& e) {
  GiNaC::exset found;
  const std::function<void(const ex&)> visit = [&](const ex& sub) {
    if (GiNaC::is_a<GiNaC::function>(sub)) {
      found.insert(sub);
    } else {
      for (const ex& operand : sub) visit(operand);
    }
  };
  visit(e);
  GiNaC::exmap to_symbols;
  std::vector<std::pair<GiNaC::symbol, ex>> atoms;
  std::vector<ex> ordered(found.begin(), found.end());  // by canonical string: the same on every run
  std::sort(ordered.begin(), ordered.end(),
            [](const ex& a, const ex& b) { return canonical_string(a) < canonical_string(b); });
  for (const ex& atom : ordered) {
    atoms.emplace_back(GiNaC::symbol(), atom);
    to_symbols[atom] = atoms.back().first;
  }
  const ex linear = e.subs(to_symbols);
  GiNaC::exmap zero;
  for (const auto& [symbol, atom] : atoms) zero[symbol] = 0;
  ex sum = fixed_fraction(linear.subs(zero));
  for (const auto& [symbol, atom] : atoms) sum += fixed_fraction(linear.diff(symbol).subs(zero)) * atom;
  return sum;
}

}  // namespace

ex full_contact_pressure_on_side(const ex& R_own, const ex& R_other, const numeric& cosine, bool top) {
  const GiNaC::symbol& t = sym::t();
  const numeric beta = branch_tangent(cosine);
  const ex F_own = (t * in_square(R_own).diff(t)).normal(), F_other = (t * in_square(R_other).diff(t)).normal();
  const ex bracket = own_piece(F_own, Piece{beta, top}) + other_piece(F_other, Piece{beta, !top});
  // Collected by atom: a rational coefficient in Cx for each.
  AtomsInCosine atoms;
  const ex in_cosine = atoms(bracket.subs(t == (1 - sym::Cx()) / (1 + sym::Cx())) * 2 / (1 + sym::Cx()));
  return sym::E() / sym::b1() * collect_atoms(in_cosine);
}

REGISTER_FUNCTION(conjugate_logarithm, evalf_func(conjugate_logarithm_evalf))

ex full_contact_pressure(const ex& R) {
  const GiNaC::symbol& t = sym::t();
  const ex v = sym::v();
  const ex Y = in_square(R);
  const GiNaC::symbol h("h");
  ex in_cosine = 0;  // p_fc/((E*/2)(pi/b1)), summed over the poles
  for (const Pole& pole : poles_in(Y, t)) {
    const ex& tau = pole.tau;
    const int l = pole.order;
    // Res_{t=tau} Y(t) v/(sqrt(-t)(v^2 - t)) = (1/sqrt(-tau)) [h^(l-1)] W(tau + h) v (1 + h/tau)^(-1/2)/(v^2 - tau - h),
    // W = (t - tau)^l Y.
    const ex W = pole.regular.subs(t == tau + h);
    ex root_series = 0;  // (1 + h/tau)^(-1/2) to order l - 1: binomial(-1/2, n) (h/tau)^n
    numeric binomial = 1;
    for (int n = 0; n < l; ++n) {
      root_series += binomial * GiNaC::pow(h / tau, n);
      binomial = binomial * (numeric(-1, 2) - n) / (n + 1);
    }
    const ex residue = taylor_coefficient(W * root_series * v / (v * v - tau - h), h, l - 1);
    // (1 + v^2)/2 d/dv of the pole's part of H[Y], even in v: in t, then in Cx.
    const GiNaC::symbol& v_symbol = GiNaC::ex_to<GiNaC::symbol>(v);
    const ex even = even_in_square((residue.diff(v_symbol) * (1 + v * v) / 2).normal(), v_symbol, t);
    in_cosine += in_cosine_of(even) / GiNaC::sqrt(-tau);
  }
  return sym::E() / 2 * GiNaC::Pi / sym::b1() * in_cosine;
}

ex full_contact_pressure(const ex& R_top, const ex& R_flank, const numeric& cosine) {
  const GiNaC::symbol& t = sym::t();
  const numeric beta = branch_tangent(cosine), beta2 = beta * beta;
  const ex Y_top = in_square(R_top), Y_flank = in_square(R_flank);
  const ex D = (Y_top - Y_flank).normal(), slope = D.diff(t).normal();
  if (!D.subs(t == beta2).normal().is_zero() || !slope.subs(t == beta2).normal().is_zero()) {
    throw std::logic_error("full_contact_pressure: the branches or their slopes do not meet at the branch point");
  }
  const ex rho = piece_rho(Y_top, beta, true) + piece_rho(Y_flank, beta, false);
  const ex rational = in_cosine_of((1 + t) * (-2 * beta * D / (t - beta2) + rho + 2 * t * rho.diff(t)));
  const ex logarithm_coefficient = in_cosine_of((1 + t) * 2 * beta * slope * (t + beta2) / (t - beta2));
  const ex& Cx = sym::Cx();
  const ex xi = conjugate_logarithm((1 - Cx) * (1 + cosine), (1 - cosine) * (1 + Cx), 2 * (cosine - Cx));
  return sym::E() / (4 * sym::b1()) * (rational + logarithm_coefficient * xi);
}

}  // namespace wavecontact::derive
