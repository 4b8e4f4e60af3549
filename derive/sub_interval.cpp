#include "sub_interval.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "canonical.hpp"
#include "hilbert.hpp"
#include "symbols.hpp"

namespace wavecontact::derive {

using GiNaC::ex;
using GiNaC::numeric;

namespace {

// I_{j,l}(z) at GiNaC::Digits.
numeric quadratic_moment_value(int j, int l, const numeric& z) {
  if (GiNaC::abs(z) <= numeric(1, 10)) {
    // sum_k C(l+k-1, k) (-z)^k/(2j+2k+1): terms fall by a tenth or more.
    const numeric tolerance =
        GiNaC::ex_to<numeric>(GiNaC::pow(numeric(10), -static_cast<long>(GiNaC::Digits) - 5));
    numeric sum = 0, coefficient = 1;
    for (int k = 0;; ++k) {
      const numeric term = coefficient / (2 * j + 2 * k + 1);
      sum += term;
      if (GiNaC::abs(term) <= tolerance * GiNaC::abs(sum) || k > 10000) return sum;
      coefficient = coefficient * (-z) * (l + k) / (k + 1);
    }
  }
  if (l == 0) return numeric(1, 2 * j + 1);
  if (j > 0) {
    return (quadratic_moment_value(j - 1, l - 1, z) - quadratic_moment_value(j - 1, l, z)) / z;
  }
  const numeric root = GiNaC::sqrt(GiNaC::abs(z));
  numeric moment = z.is_positive() ? GiNaC::atan(root) / root : GiNaC::atanh(root) / root;
  numeric power = 1;
  for (int k = 1; k < l; ++k) {
    power *= 1 + z;
    moment = 1 / (2 * k * power) + numeric(2 * k - 1, 2 * k) * moment;
  }
  return moment;
}

ex quadratic_moment_evalf(const ex& j, const ex& l, const ex& z, const ex& w) {
  const ex value = z.evalf();
  if (!GiNaC::is_a<numeric>(j) || !GiNaC::is_a<numeric>(l) || !GiNaC::is_a<numeric>(value) ||
      !GiNaC::ex_to<numeric>(value).is_real()) {
    return quadratic_moment(j, l, z, w).hold();
  }
  const numeric zz = GiNaC::ex_to<numeric>(value);
  if (zz <= -1) throw std::domain_error("quadratic_moment: z <= -1");
  // GiNaC evaluates the arguments first: j and l arrive as floats.
  const auto integer = [](const ex& e) { return static_cast<int>(std::lround(GiNaC::ex_to<numeric>(e).to_double())); };
  return quadratic_moment_value(integer(j), integer(l), zz);
}

ex quadratic_moment_derivative(const ex& j, const ex& l, const ex& z, const ex& w, unsigned parameter) {
  if (parameter < 2) throw std::logic_error("quadratic_moment: j and l are integers");
  // w is 1 + z written otherwise: the function depends on z, which carries the derivative.
  return parameter == 3 ? ex(0) : -l * quadratic_moment(j + 1, l + 1, z, w);
}

std::string str(const ex& e) {
  std::ostringstream os;
  os << e;
  return os.str();
}

// (2/pi) Int_0^T0 Psi(T^2) dT, Psi rational in S with denominator c (a + b S)^l, T0 =
// sqrt(T0_squared): terms (2/pi) n_j T0^(2j+1) a^-l I_{j,l}(b T0^2/a) / c.
std::vector<MomentTerm> moment_in_T(const ex& Psi, const GiNaC::symbol& S, const ex& T0_squared) {
  const ex nd = Psi.normal().numer_denom();
  const ex numerator = nd.op(0).expand();
  const ex factored = GiNaC::factor(nd.op(1));
  ex base = 1, constant = 1;
  int order = 0;
  const std::vector<ex> factors = GiNaC::is_a<GiNaC::mul>(factored)
                                      ? sorted_operands(factored)
                                      : std::vector<ex>{factored};
  for (const ex& f : factors) {
    const bool is_power = GiNaC::is_a<GiNaC::power>(f);
    const ex b = is_power ? f.op(0) : f;
    if (!b.has(S)) {
      constant *= f;
      continue;
    }
    if (order > 0 || b.degree(S) != 1) {
      throw std::invalid_argument("sub-interval moment: the denominator " + str(nd.op(1)) +
                                  " has more than one factor linear in tan^2(phi)");
    }
    base = b;
    order = is_power ? GiNaC::ex_to<numeric>(f.op(1)).to_int() : 1;
  }
  const ex a = order > 0 ? base.coeff(S, 0) : ex(1), b = order > 0 ? base.coeff(S, 1) : ex(0);
  const ex z = (b * T0_squared / a).normal(), one_plus_z = ((a + b * T0_squared) / a).normal();
  std::vector<MomentTerm> terms;
  for (int j = 0; j <= numerator.degree(S); ++j) {
    const ex n = numerator.coeff(S, j);
    if (n.is_zero()) continue;
    // Without a denominator in S, the moment is T0^(2j+1)/(2j+1).
    const ex scale = order > 0 ? GiNaC::pow(a, -order) : ex(numeric(1, 2 * j + 1));
    terms.push_back({(2 * n * GiNaC::pow(T0_squared, j) * scale / (constant * GiNaC::Pi)).normal(),
                     T0_squared.normal(), j, order, z, one_plus_z});
  }
  return terms;
}

}  // namespace

REGISTER_FUNCTION(quadratic_moment, evalf_func(quadratic_moment_evalf).derivative_func(quadratic_moment_derivative))

ex as_ex(const MomentTerm& term) {
  const ex factor = term.rational * GiNaC::sqrt(term.radicand);
  return term.l == 0 ? factor : factor * quadratic_moment(term.j, term.l, term.z, term.one_plus_z);
}

ex as_ex(const std::vector<MomentTerm>& terms) {
  ex sum = 0;
  for (const MomentTerm& term : terms) sum += as_ex(term);
  return sum;
}

std::vector<MomentTerm> large_argument_form(const MomentTerm& term) {
  if (term.l == 0 || term.l <= term.j) return {term};
  const int j = term.j, l = term.l;
  // K_{j,l} = Gamma(j+1/2) Gamma(n+1/2)/(2 Gamma(l)), n = l-j-1, with Gamma(k+1/2) =
  // (2k)! sqrt(pi)/(4^k k!): a rational multiple of pi.
  const int n = l - j - 1;
  const auto half_gamma = [](int k) {  // Gamma(k+1/2)/sqrt(pi)
    return GiNaC::factorial(2 * k) / (GiNaC::factorial(k) * GiNaC::pow(numeric(4), k));
  };
  const ex K = GiNaC::Pi * half_gamma(j) * half_gamma(n) / (2 * GiNaC::factorial(l - 1));
  const ex& z = term.z;
  return {{(term.rational * K * GiNaC::pow(z, -j)).normal(), (term.radicand / z).normal(), 0, 0, 0, 0},
          {(-term.rational * GiNaC::pow(z, -l)).normal(), term.radicand, l - j - 1, l,
           (1 / z).normal(), (term.one_plus_z / z).normal()}};
}

std::vector<MomentTerm> inner_moment(const ex& Phi, const ex& beta) {
  // v = alpha sin(phi), T = tan(phi): t = alpha^2 S/(1 + S), d(phi) = dT/(1 + S).
  const GiNaC::symbol S("S");
  const ex alpha2 = GiNaC::pow(sym::alpha(), 2);
  const ex Psi = Phi.subs(sym::t() == alpha2 * S / (1 + S)) / (1 + S);
  return moment_in_T(Psi, S, beta * beta / (alpha2 - beta * beta));
}

std::vector<MomentTerm> outer_moment(const ex& Phi, const ex& beta) {
  // v = alpha sin(phi), T = cot(phi): t = alpha^2/(1 + S), d(phi) = -dT/(1 + S).
  const GiNaC::symbol S("S");
  const ex alpha2 = GiNaC::pow(sym::alpha(), 2);
  const ex Psi = Phi.subs(sym::t() == alpha2 / (1 + S)) / (1 + S);
  return moment_in_T(Psi, S, (alpha2 - beta * beta) / (beta * beta));
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
