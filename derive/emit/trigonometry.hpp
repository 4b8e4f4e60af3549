// The array kernels' trigonometry (runtime/src/kernels/pressure_simd_kernels.hpp): their angle atoms
// need sin(pi t) only, by exact identities, at arguments bounded by construction
// (|t| <= 1/4), so no range reduction: a minimax polynomial t p(t^2) derived here by the
// Remez exchange at 50 digits (minimax.hpp), its coefficients rounded to doubles and the
// error measured again with the rounded ones.
#pragma once

#include <string>
#include <vector>

#include <ginac/ginac.h>

namespace wavecontact::derive {

struct BoundedSine {
  std::string name;                          // of the emitted function
  GiNaC::numeric bound;                      // |t| <= bound
  std::vector<GiNaC::numeric> coefficients;  // of u = t^2, each a double (exact rational)
  GiNaC::numeric lead_low;                   // p_0 = coefficients[0] + lead_low (double-double)
  GiNaC::numeric relative_error;             // max |t p(t^2)/sin(pi t) - 1| with these values
};

// Relative error the rounded polynomials must reach: 2^-55, an eighth of double's epsilon.
GiNaC::numeric bounded_sine_tolerance();

// sin(pi t) for |t| <= bound at the lowest degree in t^2 whose polynomial, with double
// coefficients, is within bounded_sine_tolerance().
BoundedSine bounded_sine(const std::string& name, const GiNaC::numeric& bound);

// generated/bounded_trigonometry.hpp: sinpi_quarter (|t| <= 1/4), with its degree and
// measured error, and sinpi_quarter_unfused, the same without fused multiply-adds.
std::string trigonometry_header(const BoundedSine& quarter, const std::string& command);

// The polynomial of generated/: sinpi_quarter, |t| <= 1/4.
BoundedSine kernel_sine();

}  // namespace wavecontact::derive
