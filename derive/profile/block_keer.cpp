#include "block_keer.hpp"

#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "core/symbols.hpp"

namespace wavecontact::derive {

using GiNaC::ex;
using GiNaC::numeric;

namespace {

// Real and imaginary parts of (1 + i v)^{2k}, k >= 0, by the binomial theorem.
ex de_moivre_part(long k, const ex& v, int parity) {
  ex sum = 0;
  for (long j = parity; j <= 2 * k; j += 2) {
    const long sign = ((j - parity) / 2) % 2 == 0 ? 1 : -1;
    sum += sign * GiNaC::binomial(numeric(2 * k), numeric(j)) * GiNaC::pow(v, j);
  }
  return sum;
}

// The integer k in an argument k*x, or throws.
long multiple_of_x(const ex& argument, const ex& original) {
  const ex k = (argument / sym::x()).normal();
  if (!GiNaC::is_a<numeric>(k) || !GiNaC::ex_to<numeric>(k).is_integer()) {
    std::ostringstream os;
    os << "profile is not rational in cos(k x), sin(k x) with integer k: " << argument << " in " << original;
    throw std::invalid_argument(os.str());
  }
  return GiNaC::ex_to<numeric>(k).to_long();
}

struct HalfAngleSubstitution : GiNaC::map_function {
  explicit HalfAngleSubstitution(const ex& original) : original(original) {}
  const ex& original;
  ex operator()(const ex& e) override {
    if (GiNaC::is_a<GiNaC::function>(e)) {
      const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
      if (name == "cos") return cos_multiple(multiple_of_x(e.op(0), original), sym::v());
      if (name == "sin") return sin_multiple(multiple_of_x(e.op(0), original), sym::v());
      std::ostringstream os;
      os << "profile contains " << e << ", which is not rational in cos(k x) and sin(k x): " << original;
      throw std::invalid_argument(os.str());
    }
    return e.map(*this);
  }
};

// cos(k x^) -> T_k(c), sin(k x^) -> sin(x^) U_(k-1)(c), with sin x^ a symbol.
struct CosineSubstitution : GiNaC::map_function {
  CosineSubstitution(const ex& original, ex c, ex sine) : original(original), c(std::move(c)), sine(std::move(sine)) {}
  const ex& original;
  const ex c, sine;
  // T_k (first) or U_k (second kind) by the three-term recurrence.
  ex chebyshev(long k, bool second) const {
    ex previous = 1, current = second ? 2 * c : c;
    if (k == 0) return previous;
    for (long i = 1; i < k; ++i) {
      const ex next = (2 * c * current - previous).expand();
      previous = current;
      current = next;
    }
    return current;
  }
  ex operator()(const ex& e) override {
    if (GiNaC::is_a<GiNaC::function>(e)) {
      const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
      const long k = multiple_of_x(e.op(0), original);
      if (name == "cos") return chebyshev(std::labs(k), false);
      if (name == "sin") return k == 0 ? ex(0) : (k < 0 ? -1 : 1) * sine * chebyshev(std::labs(k) - 1, true);
      std::ostringstream os;
      os << "profile contains " << e << ", which is not rational in cos(k x) and sin(k x): " << original;
      throw std::invalid_argument(os.str());
    }
    return e.map(*this);
  }
};

}  // namespace

ex cos_multiple(long k, const ex& v) {
  const long n = k < 0 ? -k : k;
  return de_moivre_part(n, v, 0) / GiNaC::pow(1 + GiNaC::pow(v, 2), n);
}

ex sin_multiple(long k, const ex& v) {
  const long n = k < 0 ? -k : k;
  const ex s = de_moivre_part(n, v, 1) / GiNaC::pow(1 + GiNaC::pow(v, 2), n);
  return k < 0 ? -s : s;
}

ex exp_i(const ex& v) { return (1 + GiNaC::I * v) / (1 - GiNaC::I * v); }

ex in_half_angle_tangent(const ex& y) {
  HalfAngleSubstitution substitute(y);
  ex result = substitute(y);
  const ex nd = result.normal().numer_denom();
  if (result.has(sym::x()) || !nd.op(0).is_polynomial(sym::v()) || !nd.op(1).is_polynomial(sym::v())) {
    std::ostringstream os;
    os << "profile is not a rational function of cos(k x), sin(k x): " << y;
    throw std::invalid_argument(os.str());
  }
  return result;
}

ex in_cosine(const ex& y) {
  const GiNaC::symbol sine("sine");
  const ex& c = sym::Cx();
  CosineSubstitution substitute(y, c, sine);
  const ex nd = substitute(y).normal().numer_denom();
  // A polynomial in sine as P0 + sine P1, with sine^2 = 1 - c^2.
  auto parts = [&](const ex& polynomial) {
    const ex p = polynomial.expand();
    ex even = 0, odd = 0;
    for (int i = 0; i <= p.degree(sine); ++i) {
      const ex term = p.coeff(sine, i) * GiNaC::pow(1 - c * c, i / 2);
      (i % 2 == 0 ? even : odd) += term;
    }
    return std::make_pair(even.expand(), odd.expand());
  };
  const auto [N0, N1] = parts(nd.op(0));
  const auto [D0, D1] = parts(nd.op(1));
  // (N0 + sine N1)/(D0 + sine D1) times (D0 - sine D1) over itself.
  const ex numerator = (N0 * D0 - (1 - c * c) * N1 * D1).expand();
  const ex odd = (N1 * D0 - N0 * D1).expand();
  const ex denominator = (D0 * D0 - (1 - c * c) * D1 * D1).expand();
  if (!odd.is_zero()) {
    std::ostringstream os;
    os << "profile is not even in x (y(-x) != y(x)): " << y;
    throw std::invalid_argument(os.str());
  }
  // x left outside cos(k x), sin(k x) (abs(x), x*cos(x), ...) is not rational in them either.
  if (!numerator.is_polynomial(c) || !denominator.is_polynomial(c) || numerator.has(sym::x()) ||
      denominator.has(sym::x())) {
    std::ostringstream os;
    os << "profile is not a rational function of cos(k x), sin(k x): " << y;
    throw std::invalid_argument(os.str());
  }
  const ex Y = (numerator / denominator).normal().numer_denom();
  return GiNaC::collect_common_factors(Y.op(0)) / GiNaC::collect_common_factors(Y.op(1));
}

ex hilbert_rhs(const ex& y) { return (-sym::E() / 2 * in_half_angle_tangent(y.diff(sym::x()))).normal(); }

}  // namespace wavecontact::derive
