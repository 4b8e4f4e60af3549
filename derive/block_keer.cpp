#include "block_keer.hpp"

#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "symbols.hpp"

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
    os << "profile is not rational in cos(k x), sin(k x) with integer k: " << argument
       << " in " << original;
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
      os << "profile contains " << e << ", which is not rational in cos(k x) and sin(k x): "
         << original;
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
  const ex result = substitute(y);
  const ex nd = result.normal().numer_denom();
  if (result.has(sym::x()) || !nd.op(0).is_polynomial(sym::v()) ||
      !nd.op(1).is_polynomial(sym::v())) {
    std::ostringstream os;
    os << "profile is not a rational function of cos(k x), sin(k x): " << y;
    throw std::invalid_argument(os.str());
  }
  return result;
}

long highest_harmonic(const ex& y) {
  long highest = 0;
  if (GiNaC::is_a<GiNaC::function>(y)) {
    const std::string name = GiNaC::ex_to<GiNaC::function>(y).get_name();
    if (name == "cos" || name == "sin") highest = std::labs(multiple_of_x(y.op(0), y));
  }
  for (const ex& operand : y) highest = std::max(highest, highest_harmonic(operand));
  return highest;
}

ex hilbert_rhs(const ex& y) {
  return (-sym::E() / 2 * in_half_angle_tangent(y.diff(sym::x()))).normal();
}

}  // namespace wavecontact::derive
