#include "sub_interval.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "core/canonical.hpp"
#include "core/printed.hpp"
#include "core/symbols.hpp"
#include "engine/hilbert.hpp"

namespace wavecontact::derive {

using GiNaC::ex;
using GiNaC::numeric;

namespace {

// I_{j,l}(z) at GiNaC::Digits.
numeric quadratic_moment_value(int j, int l, const numeric& z) {
  if (GiNaC::abs(z) <= numeric(1, 10)) {
    // sum_k C(l+k-1, k) (-z)^k/(2j+2k+1): terms fall by a tenth or more.
    const numeric tolerance = GiNaC::ex_to<numeric>(GiNaC::pow(numeric(10), -static_cast<long>(GiNaC::Digits) - 5));
    numeric sum = 0, coefficient = 1;
    for (int k = 0;; ++k) {
      const numeric term = coefficient / (2 * j + 2 * k + 1);
      sum += term;
      if (GiNaC::abs(term) <= tolerance * GiNaC::abs(sum) || k > 10000) return sum;
      coefficient = coefficient * (-z) * (l + k) / (k + 1);
    }
  }
  if (l == 0) return numeric(1, 2 * j + 1);
  // I_{0,l'} for l' <= l (atan or atanh, then up in l'), then row by row
  // I_{i,l'} = (I_{i-1,l'-1} - I_{i-1,l'})/z, I_{i,0} = 1/(2i+1): O(j l) values.
  const numeric root = GiNaC::sqrt(GiNaC::abs(z));
  std::vector<numeric> row(l + 1);
  row[0] = 1;
  if (l >= 1) row[1] = z.is_positive() ? GiNaC::atan(root) / root : GiNaC::atanh(root) / root;
  numeric power = 1;
  for (int k = 1; k + 1 <= l; ++k) {
    power *= 1 + z;
    row[k + 1] = 1 / (2 * k * power) + numeric(2 * k - 1, 2 * k) * row[k];
  }
  for (int i = 1; i <= j; ++i) {
    for (int k = l; k >= 1; --k) row[k] = (row[k - 1] - row[k]) / z;
    row[0] = numeric(1, 2 * i + 1);
  }
  return row[l];
}

// GiNaC evaluates the arguments first: j and l arrive as floats.
int small_integer(const ex& e) { return static_cast<int>(std::lround(GiNaC::ex_to<numeric>(e).to_double())); }

ex quadratic_moment_evalf(const ex& j, const ex& l, const ex& z, const ex& w) {
  const ex value = z.evalf();
  if (!GiNaC::is_a<numeric>(j) || !GiNaC::is_a<numeric>(l) || !GiNaC::is_a<numeric>(value) ||
      !GiNaC::ex_to<numeric>(value).is_real()) {
    return quadratic_moment(j, l, z, w).hold();
  }
  const numeric zz = GiNaC::ex_to<numeric>(value);
  if (zz <= -1) throw std::domain_error("quadratic_moment: z <= -1");
  return quadratic_moment_value(small_integer(j), small_integer(l), zz);
}

ex quadratic_moment_derivative(const ex& j, const ex& l, const ex& z, const ex& w, unsigned parameter) {
  if (parameter < 2) throw std::logic_error("quadratic_moment: j and l are integers");
  // w is 1 + z written otherwise: the function depends on z, which carries the derivative.
  return parameter == 3 ? ex(0) : -l * quadratic_moment(j + 1, l + 1, z, w);
}

// Restores GiNaC::Digits on leaving a scope that raised it.
struct ExtraDigits {
  long saved = GiNaC::Digits;
  explicit ExtraDigits(long extra) { GiNaC::Digits = saved + extra; }
  ~ExtraDigits() { GiNaC::Digits = saved; }
};

// J_{j,l}(y, z) at GiNaC::Digits (the runtime's two_factor_moment, evaluated otherwise: no
// recurrence along the diagonal).
numeric two_factor_moment_value(int j, int l, const numeric& y, const numeric& z) {
  if (l == 0) return quadratic_moment_value(j, 1, y);
  const numeric difference = y - z, larger = 1 + y > 1 + z ? 1 + y : 1 + z;
  const numeric ratio = GiNaC::abs(difference) / larger;
  const long digits = GiNaC::Digits;
  if (ratio < numeric(1, 1000000)) {
    // Taylor in y - z about z: sum_n (-(y - z))^n I_{j+n,l+1+n}(z); terms fall by 1e-6 or more.
    // (I_{j,l}'s recursion in j cancels up to a digit a step.)
    const int terms = digits / 6 + 4;
    const ExtraDigits extra(10 + j + terms);
    numeric sum = 0, power = 1;
    for (int n = 0; n < terms; ++n) {
      sum += power * quadratic_moment_value(j + n, l + 1 + n, z);
      power *= -difference;
    }
    return sum;
  }
  // Partial fractions J_{j,k} = (y J_{j,k-1} - z I_{j,k}(z))/(y - z) cancel like ratio^-k.
  const ExtraDigits extra(10 + static_cast<long>(l * std::ceil(-std::log10(ratio.to_double()))));
  numeric moment = quadratic_moment_value(j, 1, y);
  for (int k = 1; k <= l; ++k) moment = (y * moment - z * quadratic_moment_value(j, k, z)) / difference;
  return moment;
}

bool all_real(std::initializer_list<ex> values) {
  for (const ex& e : values) {
    if (!GiNaC::is_a<numeric>(e) || !GiNaC::ex_to<numeric>(e).is_real()) return false;
  }
  return true;
}

// sum_i C(j, i) (-1)^i moment(i): a moment in the edge basis (numerator (1 - w^2)^j) from those
// of w^2i, with the digits the sum cancels (like gap^-j, gap the smaller 1 + argument) added.
numeric in_edge_basis(int j, const numeric& gap, const std::function<numeric(int)>& moment) {
  const double g = gap.to_double();
  const ExtraDigits extra(10 + (g < 1 ? static_cast<long>(std::ceil(-j * std::log10(g))) : 0));
  numeric sum = 0;
  for (int i = 0; i <= j; ++i) {
    const numeric term = GiNaC::binomial(numeric(j), numeric(i)) * moment(i);
    sum += i % 2 == 0 ? term : -term;
  }
  return sum;
}

// J_{j,l}(y, z), or J'_{j,l}(y, z) with edge.
ex two_factor_evalf(bool edge, const ex& j, const ex& l, const ex& y, const ex& one_plus_y, const ex& z,
                    const ex& one_plus_z) {
  const ex y_value = y.evalf(), z_value = z.evalf();
  if (!all_real({j, l, y_value, z_value})) {
    return (edge ? two_factor_edge_moment(j, l, y, one_plus_y, z, one_plus_z)
                 : two_factor_moment(j, l, y, one_plus_y, z, one_plus_z))
        .hold();
  }
  const numeric yy = GiNaC::ex_to<numeric>(y_value), zz = GiNaC::ex_to<numeric>(z_value);
  if (yy <= -1 || zz <= -1) throw std::domain_error("two_factor_moment: y <= -1 or z <= -1");
  const int jj = small_integer(j), ll = small_integer(l);
  if (!edge) return two_factor_moment_value(jj, ll, yy, zz);
  return in_edge_basis(jj, 1 + (yy < zz ? yy : zz), [&](int i) { return two_factor_moment_value(i, ll, yy, zz); });
}

ex two_factor_moment_evalf(const ex& j, const ex& l, const ex& y, const ex& one_plus_y, const ex& z,
                           const ex& one_plus_z) {
  return two_factor_evalf(false, j, l, y, one_plus_y, z, one_plus_z);
}

ex two_factor_edge_moment_evalf(const ex& j, const ex& l, const ex& y, const ex& one_plus_y, const ex& z,
                                const ex& one_plus_z) {
  return two_factor_evalf(true, j, l, y, one_plus_y, z, one_plus_z);
}

ex edge_moment_evalf(const ex& j, const ex& l, const ex& z, const ex& one_plus_z) {
  const ex value = z.evalf();
  if (!all_real({j, l, value})) return edge_moment(j, l, z, one_plus_z).hold();
  const numeric zz = GiNaC::ex_to<numeric>(value);
  if (zz <= -1) throw std::domain_error("edge_moment: z <= -1");
  const int ll = small_integer(l);
  return in_edge_basis(small_integer(j), 1 + zz, [&](int i) { return quadratic_moment_value(i, ll, zz); });
}

// (2/pi) Int_0^T0 Psi(T^2) dT, Psi rational in S with denominator c (a + b S)^l, and perhaps
// the Cauchy factor (a' + b' S) (the one with sym::s()), T0 = sqrt(T0_squared): terms
// (2/pi) n_j T0^(2j+1) a^-l I_{j,l}(b T0^2/a) / c, or with a'^-1 J_{j,l}(b' T0^2/a', b T0^2/a).
std::vector<MomentTerm> moment_in_T(const ex& Psi, const GiNaC::symbol& S, const ex& T0_squared, bool edge_basis) {
  const ex nd = Psi.normal().numer_denom();
  const ex numerator = nd.op(0).expand();
  const ex factored = GiNaC::factor(nd.op(1));
  ex base = 1, constant = 1, cauchy = 0;
  int order = 0;
  const std::vector<ex> factors =
      GiNaC::is_a<GiNaC::mul>(factored) ? sorted_operands(factored) : std::vector<ex>{factored};
  for (const ex& f : factors) {
    const bool is_power = GiNaC::is_a<GiNaC::power>(f);
    const ex b = is_power ? f.op(0) : f;
    if (!b.has(S)) {
      constant *= f;
      continue;
    }
    if (b.has(sym::s()) && !is_power && cauchy.is_zero() && b.degree(S) == 1) {
      cauchy = b;
      continue;
    }
    if (order > 0 || b.degree(S) != 1) {
      throw std::invalid_argument("sub-interval moment: the denominator " + printed(nd.op(1)) +
                                  " has more than one factor linear in tan^2(phi)");
    }
    base = b;
    order = is_power ? GiNaC::ex_to<numeric>(f.op(1)).to_int() : 1;
  }
  // The argument of a factor a + b S and 1 + it.
  const auto argument = [&S, &T0_squared](const ex& factor) {
    const ex a = factor.coeff(S, 0), b = factor.coeff(S, 1);
    return std::make_pair((b * T0_squared / a).normal(), ((a + b * T0_squared) / a).normal());
  };
  const ex a = order > 0 ? base.coeff(S, 0) : ex(1);
  const auto [z, one_plus_z] = order > 0 ? argument(base) : std::make_pair(ex(0), ex(1));
  std::vector<MomentTerm> terms;
  if (edge_basis && order > 0) {
    // S = T0^2 w^2 = T0^2 (1 - q): N in powers of q, each Int_0^T0 q^j/(a + b S)^l dT =
    // T0 a^-l I'_{j,l}(z) (with a Cauchy factor a' + b' S: T0 a'^-1 a^-l J'_{j,l}(y, z)).
    const GiNaC::symbol q("q");
    const ex in_q = numerator.subs(S == T0_squared * (1 - q)).expand();
    for (int j = 0; j <= in_q.degree(q); ++j) {
      const ex n = in_q.coeff(q, j);
      if (n.is_zero()) continue;
      MomentTerm term = moment_term((2 * n * GiNaC::pow(a, -order) / (constant * GiNaC::Pi)).normal(),
                                    T0_squared.normal(), j, order, z, one_plus_z);
      term.edge = true;
      if (!cauchy.is_zero()) {
        std::tie(term.y, term.one_plus_y) = argument(cauchy);
        term.cauchy = true;
        term.rational = (term.rational / cauchy.coeff(S, 0)).normal();
      }
      terms.push_back(term);
    }
    return terms;
  }
  for (int j = 0; j <= numerator.degree(S); ++j) {
    const ex n = numerator.coeff(S, j);
    if (n.is_zero()) continue;
    // Without a denominator in S, the moment is T0^(2j+1)/(2j+1).
    const ex scale = order > 0 || !cauchy.is_zero() ? GiNaC::pow(a, -order) : ex(numeric(1, 2 * j + 1));
    MomentTerm term = moment_term((2 * n * GiNaC::pow(T0_squared, j) * scale / (constant * GiNaC::Pi)).normal(),
                                  T0_squared.normal(), j, order, z, one_plus_z);
    if (!cauchy.is_zero()) {
      const auto [y, one_plus_y] = argument(cauchy);
      term.rational = (term.rational / cauchy.coeff(S, 0)).normal();
      if (order == 0) {  // the Cauchy factor alone: I_{j,1}(y)
        term.l = 1;
        term.z = y;
        term.one_plus_z = one_plus_y;
      } else {
        term.cauchy = true;
        term.y = y;
        term.one_plus_y = one_plus_y;
      }
    }
    terms.push_back(term);
  }
  return terms;
}

}  // namespace

REGISTER_FUNCTION(quadratic_moment, evalf_func(quadratic_moment_evalf).derivative_func(quadratic_moment_derivative))
REGISTER_FUNCTION(two_factor_moment, evalf_func(two_factor_moment_evalf))
REGISTER_FUNCTION(edge_moment, evalf_func(edge_moment_evalf))
REGISTER_FUNCTION(two_factor_edge_moment, evalf_func(two_factor_edge_moment_evalf))

MomentTerm moment_term(ex rational, ex radicand, int j, int l, ex z, ex one_plus_z) {
  MomentTerm term;
  term.rational = std::move(rational);
  term.radicand = std::move(radicand);
  term.j = j;
  term.l = l;
  term.z = std::move(z);
  term.one_plus_z = std::move(one_plus_z);
  return term;
}

ex moment_atom(const MomentTerm& term) {
  if (term.cauchy) {
    return term.edge ? two_factor_edge_moment(term.j, term.l, term.y, term.one_plus_y, term.z, term.one_plus_z)
                     : two_factor_moment(term.j, term.l, term.y, term.one_plus_y, term.z, term.one_plus_z);
  }
  if (term.edge) return edge_moment(term.j, term.l, term.z, term.one_plus_z);
  return term.l == 0 ? ex(1) : quadratic_moment(term.j, term.l, term.z, term.one_plus_z);
}

ex as_ex(const MomentTerm& term) { return term.rational * GiNaC::sqrt(term.radicand) * moment_atom(term); }

ex as_ex(const std::vector<MomentTerm>& terms) {
  ex sum = 0;
  for (const MomentTerm& term : terms) sum += as_ex(term);
  return sum;
}

std::vector<MomentTerm> large_argument_form(const MomentTerm& term) {
  if (term.l == 0 || term.l <= term.j || term.cauchy || term.edge) return {term};
  const int j = term.j, l = term.l;
  // K_{j,l} = Gamma(j+1/2) Gamma(n+1/2)/(2 Gamma(l)), n = l-j-1, with Gamma(k+1/2) =
  // (2k)! sqrt(pi)/(4^k k!): a rational multiple of pi.
  const int n = l - j - 1;
  const auto half_gamma = [](int k) {  // Gamma(k+1/2)/sqrt(pi)
    return GiNaC::factorial(2 * k) / (GiNaC::factorial(k) * GiNaC::pow(numeric(4), k));
  };
  const ex K = GiNaC::Pi * half_gamma(j) * half_gamma(n) / (2 * GiNaC::factorial(l - 1));
  const ex& z = term.z;
  return {moment_term((term.rational * K * GiNaC::pow(z, -j)).normal(), (term.radicand / z).normal(), 0, 0, 0, 0),
          moment_term((-term.rational * GiNaC::pow(z, -l)).normal(), term.radicand, l - j - 1, l, (1 / z).normal(),
                      (term.one_plus_z / z).normal())};
}

std::vector<MomentTerm> inner_moment(const ex& Phi, const ex& beta, bool edge_basis) {
  // v = alpha sin(phi), T = tan(phi): t = alpha^2 S/(1 + S), d(phi) = dT/(1 + S).
  const GiNaC::symbol S("S");
  const ex alpha2 = GiNaC::pow(sym::alpha(), 2);
  const ex Psi = Phi.subs(sym::t() == alpha2 * S / (1 + S)) / (1 + S);
  return moment_in_T(Psi, S, beta * beta / (alpha2 - beta * beta), edge_basis);
}

std::vector<MomentTerm> outer_moment(const ex& Phi, const ex& beta, bool edge_basis) {
  // v = alpha sin(phi), T = cot(phi): t = alpha^2/(1 + S), d(phi) = -dT/(1 + S).
  const GiNaC::symbol S("S");
  const ex alpha2 = GiNaC::pow(sym::alpha(), 2);
  const ex Psi = Phi.subs(sym::t() == alpha2 / (1 + S)) / (1 + S);
  return moment_in_T(Psi, S, (alpha2 - beta * beta) / (beta * beta), edge_basis);
}

ex load_integrand(const ex& g) {
  const GiNaC::symbol& v = sym::v();
  return even_in_square(v * g / (1 + v * v), v, sym::t());
}

ex load_slope_integrand(const ex& g) {
  const GiNaC::symbol& v = sym::v();
  return even_in_square(((1 + v * v) * g.diff(v) + v * g).normal(), v, sym::t());
}

}  // namespace wavecontact::derive
