#include "periodic_regime.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

namespace wavecontact::detail {

namespace {

constexpr double pi = boost::math::double_constants::pi;
constexpr unsigned max_depth = 12;
constexpr double tolerance = 1e-13;

// Adaptive 31-point Gauss-Kronrod over [lo, hi].
template <typename F>
double integrate(const F& f, double lo, double hi) {
  if (!(hi > lo)) return 0;
  return boost::math::quadrature::gauss_kronrod<double, 31>::integrate(f, lo, hi, max_depth,
                                                                       tolerance);
}

// The sum of the integrals over consecutive pieces of [breaks.front(), breaks.back()].
template <typename F>
double integrate_pieces(const F& f, std::vector<double> breaks) {
  std::sort(breaks.begin(), breaks.end());
  double sum = 0;
  for (std::size_t i = 1; i < breaks.size(); ++i) sum += integrate(f, breaks[i - 1], breaks[i]);
  return sum;
}

// g(v) of eq. 5 for the curve of eq. 2, both branches (normalised).
double slope_rhs(double m, double v) {
  const double v2 = v * v;
  const double q = 1 + v2 + m * std::fabs(1 - v2);
  return (m + 1) * v * (1 + v2) / (q * q);
}

// g'(v), one-sided at the kink.
double slope_rhs_derivative(double m, double v) {
  const double v2 = v * v;
  const double q = 1 + v2 + m * std::fabs(1 - v2);
  const double dq = 2 * v * (1 - (v2 < 1 ? m : -m));
  return (m + 1) * ((1 + 3 * v2) * q - 2 * v * (1 + v2) * dq) / (q * q * q);
}

}  // namespace

double periodic_pressure(double m, HalfAngles zone, HalfAngles point, double D) {
  // Eq. 12 with v = alpha cos(theta) (MATH.md section 4):
  // p(u) = sqrt(alpha^2 - u^2) (1/pi) Int_0^pi (g(alpha cos theta) - g(u))/(alpha cos theta - u).
  const double alpha = zone.s / zone.c, u = point.s / point.c;
  const double gu = slope_rhs(m, u);
  auto divided_difference = [&](double theta) {
    const double v = alpha * std::cos(theta);
    // Within ~sqrt(eps) of u the quotient has lost half its digits: the derivative at the
    // midpoint is then accurate to O((v - u)^2).
    if (std::fabs(v - u) <= 1e-8 * (1 + std::fabs(u))) return slope_rhs_derivative(m, (u + v) / 2);
    return (slope_rhs(m, v) - gu) / (v - u);
  };
  // Pieces: the kinks (v = +-1) and v = u, where the difference quotient loses its digits.
  std::vector<double> breaks{0, pi, std::acos(u / alpha)};
  if (alpha > 1) {
    const double kink = std::acos(1 / alpha);
    breaks.push_back(kink);
    breaks.push_back(pi - kink);
  }
  const double root = std::sqrt(D / 2) / (zone.c * point.c);  // sqrt(alpha^2 - u^2)
  return root / pi * integrate_pieces(divided_difference, breaks);
}

}  // namespace wavecontact::detail
