// Parameters of the two-scale profile (seed eqs. 1-3, 7).
#pragma once

namespace wavecontact {

// Which closed form to evaluate: the exact solution of eq. 12 (derived by
// wavecontact-derive) or the formulas as printed in the seed paper (eq. 13/14),
// which are exact only for m = 0.
enum class Form { exact, paper };

// The waviness: parametric wave curve w(x, m) = H1 (m+1) cos(pi x/b1) / (m |cos(pi x/b1)| + 1)
// (eq. 2), period L1 = 2 b1, pressed against an elastic half-plane of reduced modulus E.
struct WavinessParams {
  double H1;  // height of the wave [length]
  double b1;  // half-period (width at the midline) [length]
  double m;   // shape parameter, m >= 0: 0 sine, 0.2 ~ parabola, -> infinity flat punch
  double E;   // reduced modulus E* (eq. 7) [pressure]
};

// The ranges in which every result is a normal double that keeps its digits (outside them a
// result would overflow, underflow or lose them all, and is refused with std::domain_error
// naming the range): the dimensional parameters H1, b1, E and every roughness height
// (or 0) within [min_scale, max_scale]; the shape 0 <= m <= max_shape (the closed forms
// are within a few eps up to m = 1e15 against 50 digits, but beyond 1e6 the single zone's
// admissibility hangs on height differences of 1e-15 and less); a zone's half-width
// a >= min_half_width_ratio b1; x any finite value (reduced to the period exactly).
inline constexpr double min_scale = 1e-50, max_scale = 1e50;
inline constexpr double max_shape = 1e6;
inline constexpr double min_half_width_ratio = 1e-20;

// Eq. 7, plane strain: 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2.
// Throws std::domain_error for non-positive moduli or Poisson ratios outside (-1, 0.5].
double reduced_modulus(double E1, double nu1, double E2, double nu2);

// Throws std::domain_error naming `function` and the first invalid parameter.
void validate(const WavinessParams& params, const char* function);

}  // namespace wavecontact
