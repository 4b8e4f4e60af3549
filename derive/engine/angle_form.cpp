#include "angle_form.hpp"

#include <algorithm>
#include <map>
#include <sstream>
#include <stdexcept>

#include "core/canonical.hpp"
#include "core/symbols.hpp"

namespace wavecontact::derive {

using GiNaC::ex;
using GiNaC::numeric;

namespace {

// The polynomial p as monomial * rest, where no symbol divides rest.
std::pair<ex, ex> split_monomial(const ex& p) {
  ex rest = p.expand(), monomial = 1;
  GiNaC::exset symbols;
  for (auto it = rest.preorder_begin(); it != rest.preorder_end(); ++it) {
    if (GiNaC::is_a<GiNaC::symbol>(*it)) symbols.insert(*it);
  }
  for (const ex& symbol : symbols) {
    const int power = rest.ldegree(symbol);
    if (power > 0) {
      monomial *= GiNaC::pow(symbol, power);
      rest = (rest / GiNaC::pow(symbol, power)).expand();
    }
  }
  return {monomial, rest};
}

// Factors of a product (a lone non-product counts as one factor), with exponents.
// Pi is factored as an ordinary symbol. A monomial factor is taken out before GiNaC's
// factor: with it, factor's square-free gcds run in one variable more, and their cost
// depends on the run's hash order (2 to 22 s for the pi E P(Cx, Ca), P dense of degree 32,
// of the profile 1/(2 + cos x)^32); without it, 0.3 s on every run.
std::vector<std::pair<ex, int>> factor_list(const ex& e) {
  static const GiNaC::symbol pi("pi");
  std::vector<std::pair<ex, int>> list;
  const auto [monomial, rest] = split_monomial(e.subs(GiNaC::Pi == pi));
  const ex factored = (monomial * GiNaC::factor(rest)).subs(pi == GiNaC::Pi);
  const ex factors = GiNaC::is_a<GiNaC::mul>(factored) ? factored : GiNaC::lst{factored};
  for (const ex& f : factors) {
    if (GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<numeric>(f.op(1))) {
      list.emplace_back(f.op(0), GiNaC::ex_to<numeric>(f.op(1)).to_int());
    } else {
      list.emplace_back(f, 1);
    }
  }
  return list;
}

numeric value_at_sample(const ex& e, const GiNaC::exmap& sample) {
  const ex value = atoms_in_v_variables(e).subs(sample).evalf();
  if (!GiNaC::is_a<numeric>(value)) {
    std::ostringstream os;
    os << "angle form: cannot evaluate " << e
       << " at the sample point (every parameter "
          "needs a sample value)";
    throw std::logic_error(os.str());
  }
  return GiNaC::ex_to<numeric>(value);
}

// The atom that a factor is a rational multiple of, or the factor itself.
ex as_atom(const ex& f) {
  const std::pair<ex, ex> atoms[] = {
      {1 - sym::Ca(), sym::Sa()}, {1 - sym::Cx(), sym::Sx()}, {sym::Cx() - sym::Ca(), sym::D()}};
  for (const auto& [polynomial, atom] : atoms) {
    const ex ratio = (f / polynomial).normal();
    if (GiNaC::is_a<numeric>(ratio)) return ratio * atom;
  }
  return f;
}

// The square root of a rational number if it is rational, else 0.
numeric rational_root(const numeric& q) {
  if (!q.is_rational() || q.is_negative()) return 0;
  const numeric root_num = GiNaC::isqrt(q.numer()), root_den = GiNaC::isqrt(q.denom());
  if (root_num * root_num == q.numer() && root_den * root_den == q.denom()) {
    return root_num / root_den;
  }
  return 0;
}

}  // namespace

GiNaC::exmap sample_point_v() {
  // x^ = 0.4, a^ = 1.2 (below pi/2) as exact rationals of their half-angle tangents;
  // m = 1/2 and unit-ish physical parameters.
  GiNaC::exmap point;
  point[sym::s()] = numeric(1, 25);  // u = 1/5
  point[sym::u()] = numeric(1, 5);
  point[sym::alpha()] = numeric(7, 10);  // alpha = 0.7 -> a^ ~ 1.22
  point[sym::m()] = numeric(1, 2);
  point[sym::E()] = numeric(3, 2);
  point[sym::H1()] = numeric(2, 3);
  point[sym::b1()] = numeric(5, 4);
  return point;
}

ex atoms_in_v_variables(const ex& e) {
  const ex s = sym::s(), alpha2 = GiNaC::pow(sym::alpha(), 2);
  const ex Cx = (1 - s) / (1 + s), Ca = (1 - alpha2) / (1 + alpha2);
  return e.subs(
      GiNaC::lst{sym::Sa() == 1 - Ca, sym::Sx() == 1 - Cx, sym::D() == Cx - Ca, sym::Ca() == Ca, sym::Cx() == Cx});
}

std::vector<RootTerm> root_terms(const RadicalSum& closed, const Radicals& radicals, const ex& prefactor_square) {
  std::vector<RootTerm> terms;
  for (const auto& [mask, c] : closed.terms()) {
    ex radicand = prefactor_square;
    for (unsigned i = 0; i < radicals.size(); ++i) {
      if (mask & (RadicalSum::Mask{1} << i)) radicand *= radicals.square(i);
    }
    terms.push_back({c, radicand.normal()});
  }
  return terms;
}

namespace {

// p(s) with s = (1 - c)/(1 + c), times (1 + c)^degree: sum_k p_k (1 - c)^k (1 + c)^(degree - k),
// collected by powers of c with the integer coefficients
//   K(j, k) = [c^j] (1 - c)^k (1 + c)^(degree - k) = sum_i (-1)^i C(k, i) C(degree - k, j - i),
// so that no product of polynomials is expanded.
ex times_cosine_denominator(const ex& p, const ex& s, const ex& c, int degree) {
  std::vector<ex> p_k(degree + 1);
  for (int k = 0; k <= degree; ++k) p_k[k] = p.coeff(s, k);
  std::vector<std::vector<numeric>> binomial(degree + 1);
  for (int n = 0; n <= degree; ++n) {
    for (int i = 0; i <= n; ++i) binomial[n].push_back(GiNaC::binomial(numeric(n), numeric(i)));
  }
  ex sum = 0;
  for (int j = 0; j <= degree; ++j) {
    ex coefficient = 0;
    for (int k = 0; k <= degree; ++k) {
      if (p_k[k].is_zero()) continue;
      numeric K = 0;
      for (int i = std::max(0, j - (degree - k)); i <= std::min(k, j); ++i) {
        const numeric term = binomial[k][i] * binomial[degree - k][j - i];
        K += i % 2 == 0 ? term : -term;
      }
      if (!K.is_zero()) coefficient += K * p_k[k];
    }
    sum += coefficient * GiNaC::pow(c, j);
  }
  return sum.expand();
}

// A polynomial in s = tan^2(x^/2) and alpha (even in alpha, alpha^2 = tan^2(a^/2)) in the
// cosines: p = polynomial / ((1 + Cx)^degree_s (1 + Ca)^degree_alpha_squared). Each
// substitution is a Moebius map, so the polynomials of a fraction in lowest terms stay
// coprime and no gcd is needed.
struct AngleCosines {
  ex polynomial;
  int degree_s = 0, degree_alpha_squared = 0;
};

// (Not hilbert.hpp's even_in_square: p is already a polynomial, and its normal() of the whole
// polynomial made an order-32 derivation 40 % slower.)
AngleCosines in_angle_cosines(const ex& p) {
  static const GiNaC::symbol alpha_squared("alpha_squared");
  const ex expanded = p.expand();
  const ex alpha = sym::alpha(), s = sym::s();
  ex in_square = 0;
  for (int k = expanded.ldegree(alpha); k <= expanded.degree(alpha); ++k) {
    const ex c = expanded.coeff(alpha, k);
    if (c.is_zero()) continue;
    if (k % 2 != 0) {
      std::ostringstream os;
      os << "angle form: odd power of alpha in " << p;
      throw std::logic_error(os.str());
    }
    in_square += c * GiNaC::pow(alpha_squared, k / 2);
  }
  AngleCosines result;
  result.degree_s = in_square.degree(s);
  result.degree_alpha_squared = in_square.degree(alpha_squared);
  const ex in_Cx = times_cosine_denominator(in_square, s, sym::Cx(), result.degree_s);
  result.polynomial = times_cosine_denominator(in_Cx, alpha_squared, sym::Ca(), result.degree_alpha_squared);
  return result;
}

// A product coefficient * prod factor^exponent with every factor an irreducible
// polynomial over Q that is positive on the domain (or an atom), keyed by its
// canonical string: a deterministic factored form.
struct Product {
  explicit Product(const GiNaC::exmap& sample) : sample(sample) {}
  const GiNaC::exmap& sample;
  numeric coefficient = 1;
  std::map<std::string, std::pair<ex, int>> factors;

  void multiply(const ex& f, int exponent) {
    if (exponent == 0) return;
    const ex atom = as_atom(f);
    ex base = atom;
    numeric scale = 1;
    if (GiNaC::is_a<GiNaC::mul>(atom)) {  // c * atom
      for (const ex& part : atom) {
        if (GiNaC::is_a<numeric>(part)) scale *= GiNaC::ex_to<numeric>(part);
      }
      base = (atom / scale).normal();
    }
    base = base.expand();
    if (value_at_sample(base, sample).is_negative()) {
      base = (-base).expand();
      scale = -scale;
    }
    coefficient *= GiNaC::ex_to<numeric>(GiNaC::pow(scale, exponent));
    auto [it, inserted] = factors.emplace(canonical_string(base), std::make_pair(base, exponent));
    if (!inserted) it->second.second += exponent;
  }

  // Every factor of the polynomial p, to the power direction (1 or -1).
  void multiply_polynomial(const ex& p, int direction) {
    for (const auto& [f, power] : factor_list(p)) {
      if (GiNaC::is_a<numeric>(f)) {
        coefficient *= GiNaC::ex_to<numeric>(GiNaC::pow(f, direction * power));
      } else {
        multiply(f, direction * power);
      }
    }
  }

  // Every factor of a rational function of s and alpha, written in Cx and Ca.
  void multiply_in_angles(const ex& v_form) {
    const ex nd = v_form.numer_denom();
    const AngleCosines numerator = in_angle_cosines(nd.op(0));
    const AngleCosines denominator = in_angle_cosines(nd.op(1));
    multiply_polynomial(numerator.polynomial, 1);
    multiply_polynomial(denominator.polynomial, -1);
    multiply(1 + sym::Cx(), denominator.degree_s - numerator.degree_s);
    multiply(1 + sym::Ca(), denominator.degree_alpha_squared - numerator.degree_alpha_squared);
  }

  ex to_ex() const {
    ex result = coefficient;
    for (const auto& [key, factor] : factors) result *= GiNaC::pow(factor.first, factor.second);
    return result;
  }
};

}  // namespace

RootTerm to_angle_atoms(const RootTerm& term, const GiNaC::exmap& sample) {
  Product root(sample);
  root.multiply_in_angles(term.radicand);
  if (!root.coefficient.is_positive()) {
    std::ostringstream os;
    os << "angle form: radicand " << term.radicand
       << " is not positive at the sample point (x^ = 0.4, a^ = 1.22 and the parameters' "
          "sample values)";
    throw std::logic_error(os.str());
  }
  // Pull squares out of the root: sqrt(f^(2q + r)) = f^q sqrt(f^r), f > 0.
  Product outside(sample), inside(sample);
  outside.multiply_in_angles(term.rational);
  for (const auto& [key, factor] : root.factors) {
    const int q = factor.second / 2, r = factor.second % 2;
    outside.multiply(factor.first, q);
    inside.multiply(factor.first, r);
  }
  const numeric root_of_coefficient = rational_root(root.coefficient);
  if (root_of_coefficient.is_zero()) {
    inside.coefficient = root.coefficient;
  } else {
    outside.coefficient *= root_of_coefficient;
  }
  return {outside.to_ex(), inside.to_ex()};
}

ex as_ex(const RootTerm& term) {
  if (term.radicand.is_equal(1)) return term.rational;
  return term.rational * GiNaC::sqrt(term.radicand);
}

ex angle_form_residual(const RootTerm& v_form, const RootTerm& angle_form, bool& sign_agrees,
                       const GiNaC::exmap& sample) {
  const ex angle_rational = atoms_in_v_variables(angle_form.rational);
  const ex angle_radicand = atoms_in_v_variables(angle_form.radicand);
  ex residual =
      (GiNaC::pow(v_form.rational, 2) * v_form.radicand - GiNaC::pow(angle_rational, 2) * angle_radicand).normal();
  const ex point_v = v_form.rational.subs(sample).evalf();
  const ex point_angle = angle_rational.subs(sample).evalf();
  sign_agrees = GiNaC::is_a<numeric>(point_v) && GiNaC::is_a<numeric>(point_angle) &&
                GiNaC::ex_to<numeric>(point_v).is_negative() == GiNaC::ex_to<numeric>(point_angle).is_negative();
  return residual;
}

}  // namespace wavecontact::derive
