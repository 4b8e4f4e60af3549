// An independent reference for eq. 12 with a right-hand side that has a kink: a profile built
// with |.| whose contact zone reaches beyond its change of branch at x^ = kink (eq. 2 beyond
// b1/2, user profiles with abs()). Normalised: b1 = pi, so p is p^.
//
// Eq. 12 in x-space with sin(xi/2) = sin(a/2) sin(phi), which removes the edge singularities,
//   p(x) = sqrt(cos x - cos a)/(sqrt2 pi) Int_{-pi/2}^{pi/2} (G(xi) - G(x))/(cos(xi/2) sin((xi - x)/2)) dphi,
// G = -(E*/2) y' (both branches), in long double with a 61-point Gauss-Kronrod rule: nothing
// shared with the runtime's closed forms. Pieces: x, the kinks, and near the kink pieces graded
// from |x - kink|, over which the quotient changes across it. Also the benchmarks' baseline.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

// G(xi, branch) and G'(xi, branch) on the branch +1 (|xi| < kink) or -1 (beyond), each
// continued off its own side.
template <typename G_t, typename G_prime_t>
long double kinked_reference_pressure(const G_t& G_on, const G_prime_t& G_prime, long double kink, long double a,
                                      long double x) {
  using boost::math::long_double_constants::pi;
  using std::asin;
  using std::cos;
  using std::fabs;
  using std::sin;
  using std::sqrt;
  const auto branch_of = [&](long double xi) { return fabs(xi) <= kink ? 1 : -1; };
  const auto G = [&](long double xi) { return G_on(xi, branch_of(xi)); };
  const int branch = branch_of(x);
  const long double s = sin(a / 2), Gx = G(x);
  auto integrand = [&](long double phi) {
    const long double xi = 2 * asin(s * sin(phi));
    if (fabs(xi - x) < 1e-9L && branch_of(xi) == branch) {  // the quotient's limit
      return 2 * G_prime(x, branch) / cos(xi / 2);
    }
    return (G(xi) - Gx) / (cos(xi / 2) * sin((xi - x) / 2));
  };
  const long double half_pi = pi / 2;
  std::vector<long double> breaks{-half_pi, asin(sin(x / 2) / s), half_pi};
  const long double sine_at_kink = sin(kink / 2) / s;  // sin(phi) at xi = +-kink
  if (sine_at_kink < 1) {
    breaks.insert(breaks.end(), {asin(sine_at_kink), -asin(sine_at_kink)});
    // Across the kink from x the quotient changes over |x - kink|: pieces growing by 2 from it
    // (from 1e-12: a narrower layer weighs less than the tolerances here).
    const long double side = x < kink ? 1 : -1;
    for (long double width = std::max(fabs(x - kink), 1e-12L); width < 1; width *= 2) {
      const long double xi = kink + side * width;
      if (xi < a && xi > 0) breaks.push_back(asin(sin(xi / 2) / s));
    }
  }
  std::sort(breaks.begin(), breaks.end());
  long double sum = 0;
  for (std::size_t i = 1; i < breaks.size(); ++i) {
    // On [-1, 1]: Boost's error estimate is floored relative to the integral over [-1, 1].
    // Pieces narrower than 1e-6 next to the kink weigh less than their own rounding (G(xi) -
    // G(x) over xi - x down to 1e-12) lets the tolerance see: a few levels there.
    const long double mid = (breaks[i] + breaks[i - 1]) / 2, half = (breaks[i] - breaks[i - 1]) / 2;
    sum += half *
           boost::math::quadrature::gauss_kronrod<long double, 61>::integrate(
               [&](long double t) { return integrand(mid + half * t); }, -1.0L, 1.0L, half > 1e-6L ? 10 : 3, 1e-15L);
  }
  return sqrt(cos(x) - cos(a)) / (sqrt(2.0L) * pi) * sum;
}

// The reference for eq. 2: G(xi) = (m+1) sin(xi)/(2 (1 + m |cos xi|)^2), eq. 2 differentiated,
// both branches, with the kink at pi/2.
inline long double wave_curve_reference_pressure(long double m, long double a, long double x) {
  const auto G = [&](long double xi, int branch) {
    const long double q = 1 + m * branch * std::cos(xi);
    return (m + 1) * std::sin(xi) / (2 * q * q);
  };
  const auto G_prime = [&](long double xi, int branch) {
    const long double q = 1 + m * branch * std::cos(xi), dq = -m * branch * std::sin(xi);
    return (m + 1) * (std::cos(xi) * q - 2 * std::sin(xi) * dq) / (2 * q * q * q);
  };
  return kinked_reference_pressure(G, G_prime, 3.141592653589793238462643383279502884L / 2, a, x);
}
