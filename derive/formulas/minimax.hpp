// Minimax polynomial approximation by the Remez exchange algorithm, at high precision
// (CLN floats through GiNaC numerics): the bounded-range trigonometry of the array kernels.
#pragma once

#include <functional>
#include <vector>

#include <ginac/ginac.h>

namespace wavecontact::derive {

// A smooth function without zeros on an interval, evaluated at GiNaC::Digits.
using Function = std::function<GiNaC::numeric(const GiNaC::numeric&)>;

// The polynomial p of the given degree that minimises max |p(u)/f(u) - 1| over [lo, hi]
// (relative error), coefficients p_0..p_degree at working precision. Throws
// std::runtime_error if the exchange does not level the error within 60 iterations.
std::vector<GiNaC::numeric> remez(const Function& f, const GiNaC::numeric& lo, const GiNaC::numeric& hi, int degree);

// max over [lo, hi] of |p(u)/f(u) - 1| for the coefficients p_0..p_n: dense sampling, then
// golden-section refinement around every sampled local maximum.
GiNaC::numeric max_relative_error(const Function& f, const std::vector<GiNaC::numeric>& p, const GiNaC::numeric& lo,
                                  const GiNaC::numeric& hi);

// The double nearest to q, as the exact rational it denotes.
GiNaC::numeric nearest_double(const GiNaC::numeric& q);

}  // namespace wavecontact::derive
