// Int_lo^hi f at GiNaC::Digits by the tanh-sinh rule: an independent high-precision
// quadrature for the symbolic tests' references.
#pragma once

#include <functional>

#include <ginac/ginac.h>

namespace wavecontact::test {

// Step 1/128, nodes until the weights fall below 10^-(Digits + 5); 1 - tanh(s) = 2/(e^2s + 1)
// keeps the nodes next to the ends apart from them. f must be smooth inside (lo, hi).
inline GiNaC::numeric tanh_sinh(const std::function<GiNaC::numeric(const GiNaC::numeric&)>& f, const GiNaC::numeric& lo,
                                const GiNaC::numeric& hi) {
  using GiNaC::numeric;
  const numeric half = (hi - lo) / 2, h(1, 128);
  const numeric pi_half = GiNaC::ex_to<numeric>((GiNaC::Pi / 2).evalf());
  const numeric small =
      GiNaC::ex_to<numeric>(GiNaC::pow(numeric(10), numeric(-static_cast<long>(GiNaC::Digits) - 5)).evalf());
  numeric sum = f(lo + half) * pi_half;  // t = 0: weight pi/2
  for (int k = 1;; ++k) {
    const numeric t = k * h, s = pi_half * GiNaC::sinh(t);
    const numeric gap = 2 / (GiNaC::exp(2 * s) + 1);  // 1 - tanh(s)
    const numeric weight = pi_half * GiNaC::cosh(t) / (GiNaC::cosh(s) * GiNaC::cosh(s));
    if (weight < small) break;
    sum += weight * (f(hi - half * gap) + f(lo + half * gap));
  }
  return sum * half * h;
}

}  // namespace wavecontact::test
