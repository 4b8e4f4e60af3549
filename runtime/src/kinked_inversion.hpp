// Eq. 12 by quadrature for a right-hand side g of eq. 5 that is piecewise analytic with a
// kink in its slope at v = +-beta: a profile built with |.| (eq. 2 beyond a = b1/2, or a user
// profile with abs()) whose contact zone reaches beyond the change of branch. With
// v = alpha cos(theta) (MATH.md section 4)
//   p^(u) = sqrt(alpha^2 - u^2) (1/pi) Int_0^pi (g(alpha cos theta) - g(u))/(alpha cos theta - u) dtheta,
// split at the kinks, at v = u, and in pieces growing by 4 from the kink across it, which
// resolve the layer of width |u - beta| that the jump in g' leaves there; 31-point
// Gauss-Kronrod on every piece, adaptive where its error exceeds 1e-14 of the integral of
// |.| over the zone.
#pragma once

#include <functional>

namespace wavecontact::detail {

// The zone in half-angles: s = sin(a^/2), c = cos(a^/2), a^ = pi a/b1 in (0, pi).
struct HalfAngles {
  double s, c;
};

// p^(x^) for the zone `zone` at the point with half-angles `point`, 0 <= x^ < a^, given
// (g(v) - g(u))/(v - u) of the piecewise g (on whichever branches v and u lie). D = cos x^ -
// cos a^ (computed without cancellation by the caller).
double kinked_pressure(const std::function<double(double v, double u)>& divided_difference, double beta,
                       HalfAngles zone, HalfAngles point, double D);

// (g(v) - g(u))/(v - u) of a g with branches A (|u| <= beta) and B, from the divided difference
// on one branch (with v - u divided out) and the jump g_B(u) - g_A(u): the plain quotient
// where v - u is not small (|v - u| > (1 + |u|)/4, where the one-branch forms may cancel) or
// where u sits near B's pole (|g_B(u)| > 2 |g_A(u)|, where the jump's term cancels instead).
struct PiecewiseDividedDifference {
  double beta;
  std::function<double(double v)> top_g, flank_g;
  std::function<double(double v, double u)> top_divided_difference, flank_divided_difference;
  std::function<double(double u)> jump;  // g_flank(u) - g_top(u)

  double operator()(double v, double u) const;
};

}  // namespace wavecontact::detail
