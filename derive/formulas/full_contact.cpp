#include "full_contact.hpp"

#include <algorithm>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "core/canonical.hpp"
#include "core/symbols.hpp"
#include "engine/hilbert.hpp"
#include "engine/sub_interval.hpp"

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
  if (difference.is_zero() || B.is_zero()) return 0;
  if (A.is_zero()) return -2;
  // s^2 = min/max, atanh(s) = log(1 + s) - log(1 - s^2)/2 with 1 - s^2 = |a - b|/max: exact
  // however close a and b are.
  const numeric larger = A > B ? A : B, s = GiNaC::sqrt((A > B ? B : A) / larger);
  const numeric atanh = GiNaC::log(1 + s) - GiNaC::log(GiNaC::abs(difference) / larger) / 2;
  return difference / (A + B) * (A > B ? 2 * s * atanh : 2 * atanh / s);
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

// A profile built with abs() (full_contact.hpp): F = t Y'(t) of a branch as N(t)/(a + b t)^L,
// N a polynomial of degree <= L, its one pole factor kept whole (no coefficient singular where
// b -> 0, the pole passing through infinity, as the top's of eq. 2 does at m = 1).
struct PoleForm {
  ex N, a = 1, b = 0;
  int L = 0;
};

PoleForm pole_form(const ex& F) {
  const GiNaC::symbol& t = sym::t();
  const ex fraction = F.normal().numer_denom();
  const ex denominator = GiNaC::factor(fraction.op(1));
  PoleForm form;
  ex constant = 1;
  for (const ex& factor_power : GiNaC::is_a<GiNaC::mul>(denominator)
                                    ? std::vector<ex>(denominator.begin(), denominator.end())
                                    : std::vector<ex>{denominator}) {
    const bool power = GiNaC::is_a<GiNaC::power>(factor_power);
    const ex factor = power ? factor_power.op(0) : factor_power;
    if (!factor.has(t)) {
      constant *= factor_power;
      continue;
    }
    if (form.L > 0 || factor.degree(t) != 1) {
      std::ostringstream os;
      os << "full_contact_pressure: the slope's denominator " << denominator
         << " has more than one pole factor, or one not linear in v^2";
      throw std::invalid_argument(os.str());
    }
    form.L = power ? GiNaC::ex_to<numeric>(factor_power.op(1)).to_int() : 1;
    form.a = factor.coeff(t, 0);
    form.b = factor.coeff(t, 1);
  }
  form.N = (fraction.op(0) / constant).expand();
  if (form.N.degree(t) > form.L) {
    throw std::invalid_argument("full_contact_pressure: the profile's slope is not bounded at x^ = pi");
  }
  return form;
}

// Sum_k p_k (1 - q)^k = P(q): the coefficients p_k of a polynomial in q in powers of 1 - q.
std::vector<ex> in_edge_powers(const ex& P, const GiNaC::symbol& q) {
  const GiNaC::symbol r("r");
  const ex in_r = P.subs(q == 1 - r).expand();
  std::vector<ex> p;
  for (int k = 0; k <= in_r.degree(r); ++k) p.push_back(in_r.coeff(r, k));
  return p;
}

// Moments over the piece [0, beta] (top, u = beta w) or [beta, inf) (u = beta/w) of a polynomial
// sum_j c_j s^j, s = u^2, over the pole factor: Int_0^1 P(q)/(1 + z q)^L dw, q = w^2, with the
// numerator in powers of 1 - q (the edge basis I'_{k,L}, J'_{k,L} of sub_interval.hpp). Where the
// pole factor nears the piece's end w = 1 (z -> -1, the poles of eq. 2 for large m next to the
// branch point) the I_{j,L}, J_{j,L} of the monomials all tend to one large value and their sum
// cancels; in the edge basis its terms fall off instead.
struct Piece {
  numeric beta;
  bool top;

  // P(q) = sum_j c_j beta^2j q^(e(j)) for the piece's substitution, and the sum of p_k atom(k).
  ex edge_sum(const ex& polynomial, const GiNaC::symbol& s, const std::function<int(int)>& exponent,
              const std::function<ex(int)>& atom) const {
    const GiNaC::symbol q("q");
    ex P = 0;
    for (int j = 0; j <= polynomial.degree(s); ++j) {
      P += polynomial.coeff(s, j) * GiNaC::pow(beta, 2 * j) * GiNaC::pow(q, exponent(j));
    }
    const std::vector<ex> p = in_edge_powers(P, q);
    ex sum = 0;
    for (std::size_t k = 0; k < p.size(); ++k) {
      if (!p[k].is_zero()) sum += p[k] * atom(static_cast<int>(k));
    }
    return sum;
  }
  // z and 1 + z of the pole factor a + b u^2 under the piece's substitution.
  ex z(const PoleForm& f) const {
    const numeric beta2 = beta * beta;
    return (top ? f.b * beta2 / f.a : f.a / (f.b * beta2)).normal();
  }
  ex one_plus_z(const PoleForm& f) const {
    const numeric beta2 = beta * beta;
    return ((f.a + f.b * beta2) / (top ? f.a : f.b * beta2)).normal();
  }

  // Int_piece c(u^2)/(a + b u^2)^L du for the polynomial c in s (degree < L on [beta, inf)).
  ex moment(const ex& c, const GiNaC::symbol& s, const PoleForm& f) const {
    const ex Z = z(f), W = one_plus_z(f);
    const int L = f.L;
    const auto atom = [&](int k) { return edge_moment(k, L, Z, W); };
    if (top)
      return beta * GiNaC::pow(f.a, -L) *
             edge_sum(
                 c, s, [](int j) { return j; }, atom);
    return GiNaC::pow(beta, 1 - 2 * L) * GiNaC::pow(f.b, -L) *
           edge_sum(
               c, s, [L](int j) { return L - 1 - j; }, atom);
  }
  // Int_piece du/(t - u^2), t on the piece (principal value): Lambda/(2v) on [0, beta],
  // -Lambda/(2v) beyond, Lambda = log|(v + beta)/(v - beta)|.
  ex cauchy_on() const {
    const GiNaC::symbol& t = sym::t();
    const numeric beta2 = beta * beta;
    return top ? 1 / beta * quadratic_moment(0, 1, -t / beta2, (beta2 - t) / beta2)
               : -beta / t * quadratic_moment(0, 1, -beta2 / t, (t - beta2) / t);
  }
  // Int_piece c(u^2)/((a + b u^2)^L (t - u^2)) du for the polynomial c in t, t off the piece: the Cauchy factor kept
  // beside the pole factor (J'_{k,L}; I'_{k,1} of the Cauchy factor alone where L = 0).
  ex cauchy_moment(const ex& c, const PoleForm& f) const {
    const GiNaC::symbol& t = sym::t();
    const numeric beta2 = beta * beta;
    const ex y = top ? -beta2 / t : -t / beta2, one_plus_y = top ? (t - beta2) / t : (beta2 - t) / beta2;
    const int L = f.L;
    const auto atom = [&](int k) {
      return L == 0 ? edge_moment(k, 1, y, one_plus_y)
                    : two_factor_edge_moment(k, L, y, one_plus_y, z(f), one_plus_z(f));
    };
    if (top)
      return beta * GiNaC::pow(f.a, -L) / t *
             edge_sum(
                 c, t, [](int j) { return j; }, atom);
    if (L == 0)
      return -1 / beta *
             edge_sum(
                 c, t, [](int) { return 0; }, atom);  // c constant
    return -GiNaC::pow(beta, -1 - 2 * L) * GiNaC::pow(f.b, -L) *
           edge_sum(
               c, t, [L](int j) { return L - j; }, atom);
  }
};

// Int_piece (F(s) - F(t))/(t - s) du, s = u^2, t anywhere: (F(s) - F(t))/(t - s) =
// P(s, t)/((a + b s)^L (a + b t)^L) with P a polynomial of degree < L in s.
ex jump_apart(const PoleForm& f, const Piece& piece) {
  if (f.L == 0) return 0;  // F constant
  const GiNaC::symbol& t = sym::t();
  const GiNaC::symbol s("s");
  const ex F = f.N / GiNaC::pow(f.a + f.b * t, f.L);
  const ex P = ((F.subs(t == s) - F) / (t - s) * GiNaC::pow(f.a + f.b * s, f.L) * GiNaC::pow(f.a + f.b * t, f.L))
                   .normal()
                   .expand();
  return piece.moment(P, s, f) / GiNaC::pow(f.a + f.b * t, f.L);
}

// Int_piece F(u^2)/(t - u^2) du for t off the piece, the Cauchy factor beside the pole factor.
ex cauchy_kept(const PoleForm& f, const Piece& piece) { return piece.cauchy_moment(f.N, f); }

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

// The atoms' arguments from t to Cx, each one fraction (1 + y, 1 + z such as 2 Cx/(1 + Cx) for
// eq. 2, whose numerators, linear in Cx, keep their digits where they vanish).
struct AtomsInCosine : GiNaC::map_function {
  ex operator()(const ex& e) override {
    if (GiNaC::is_a<GiNaC::function>(e)) {
      GiNaC::function f = GiNaC::ex_to<GiNaC::function>(e);
      for (std::size_t i = 0; i < f.nops(); ++i) f.let_op(i) = fixed_fraction(in_cosine_of(f.op(i)));
      return f;
    }
    return e.map(*this);
  }
};

// (E*/b1) sum_k c_k A_k + c_0 from (1 + t) times the bracket, in Cx: e linear in its atoms A_k, each
// coefficient one rational function, the atoms in the order of their canonical strings.
ex in_cosine_by_atom(const ex& bracket) {
  AtomsInCosine atoms_in_cosine;
  const ex e = atoms_in_cosine(bracket.subs(sym::t() == (1 - sym::Cx()) / (1 + sym::Cx())) * 2 / (1 + sym::Cx()));
  GiNaC::exset found;
  const std::function<void(const ex&)> visit = [&](const ex& sub) {
    if (GiNaC::is_a<GiNaC::function>(sub)) {
      found.insert(sub);
    } else {
      for (const ex& operand : sub) visit(operand);
    }
  };
  visit(e);
  std::vector<ex> atoms(found.begin(), found.end());
  std::sort(atoms.begin(), atoms.end(),
            [](const ex& x, const ex& y) { return canonical_string(x) < canonical_string(y); });
  std::vector<GiNaC::symbol> symbols(atoms.size());
  GiNaC::exmap to_symbols, zero;
  for (std::size_t k = 0; k < atoms.size(); ++k) to_symbols[atoms[k]] = symbols[k], zero[symbols[k]] = 0;
  const ex linear = e.subs(to_symbols);
  ex sum = fixed_fraction(linear.subs(zero));
  for (std::size_t k = 0; k < atoms.size(); ++k) sum += fixed_fraction(linear.diff(symbols[k]).subs(zero)) * atoms[k];
  return sym::E() / sym::b1() * sum;
}

struct Branches {
  numeric beta;
  PoleForm top, flank;
  ex F_top, F_flank;
};

Branches branches_of(const ex& R_top, const ex& R_flank, const numeric& cosine) {
  const GiNaC::symbol& t = sym::t();
  Branches b{branch_tangent(cosine),
             {},
             {},
             (t * in_square(R_top).diff(t)).normal(),
             (t * in_square(R_flank).diff(t)).normal()};
  const ex at_branch = b.beta * b.beta;
  if (!(in_square(R_top) - in_square(R_flank)).subs(t == at_branch).normal().is_zero() ||
      !(b.F_top - b.F_flank).subs(t == at_branch).normal().is_zero()) {
    throw std::logic_error("full_contact_pressure: the branches or their slopes do not meet at the branch point");
  }
  b.top = pole_form(b.F_top);
  b.flank = pole_form(b.F_flank);
  return b;
}

}  // namespace

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
    // Res_{t=tau} Y(t) v/(sqrt(-t)(v^2 - t)) = (1/sqrt(-tau)) [h^(l-1)] W(tau + h) v (1 + h/tau)^(-1/2)/(v^2 - tau -
    // h), W = (t - tau)^l Y.
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
  const Branches b = branches_of(R_top, R_flank, cosine);
  const numeric beta2 = b.beta * b.beta;
  const ex& Cx = sym::Cx();
  // (F_top - F_flank)(t) Lambda/(2v) = D~(t) (t + beta^2) Psi/(2 beta), D~ = (F_top - F_flank)/(t - beta^2).
  const ex psi = conjugate_logarithm(((1 - Cx) * (1 + cosine)).expand(), ((1 - cosine) * (1 + Cx)).expand(),
                                     (2 * (cosine - Cx)).expand());
  const ex jump = ((b.F_top - b.F_flank) / (t - beta2)).normal() * (t + beta2) / (2 * b.beta);
  return in_cosine_by_atom(jump_apart(b.top, Piece{b.beta, true}) + jump_apart(b.flank, Piece{b.beta, false}) +
                           jump * psi);
}

ex full_contact_pressure_on_side(const ex& R_top, const ex& R_flank, const numeric& cosine, bool top) {
  const Branches b = branches_of(R_top, R_flank, cosine);
  const Piece own{b.beta, top}, other{b.beta, !top};
  return in_cosine_by_atom(jump_apart(top ? b.top : b.flank, own) + (top ? b.F_top : b.F_flank) * own.cauchy_on() +
                           cauchy_kept(top ? b.flank : b.top, other));
}

}  // namespace wavecontact::derive
