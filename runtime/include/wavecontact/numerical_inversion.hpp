// The independent numerical inversion of eq. 12 (docs/mathematics.md section 4): with v = alpha cos(theta),
//   p(u) = sqrt(alpha^2 - u^2) (1/pi) Int_0^pi (g(alpha cos theta) - g(u)) / (alpha cos theta - u) dtheta,
// a smooth periodic integrand for analytic g, so the midpoint rule converges
// geometrically. A reference for the closed forms and a fallback, not a substitute.
#pragma once

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace wavecontact {

// p(u) for the right-hand side g(v) of eq. 5 (normalised period 2 pi), |u| < alpha,
// with `nodes` midpoint nodes. g must be smooth on [-alpha, alpha].
template <typename G>
double numerical_inversion(const G& g, double alpha, double u, int nodes) {
  if (!(alpha > 0 && std::isfinite(alpha)) || !(std::fabs(u) < alpha) || nodes < 1) {
    std::ostringstream os;
    os.precision(17);
    os << "wavecontact::numerical_inversion: alpha = " << alpha << ", u = " << u << ", nodes = " << nodes
       << " are invalid (valid: 0 < alpha finite, |u| < alpha, nodes >= 1)";
    throw std::domain_error(os.str());
  }
  constexpr double pi = 3.14159265358979323846;
  const double gu = g(u);
  // The divided difference at v = u, should a node hit it: g'(u) by a central difference.
  const double h = 1e-6 * alpha;
  const double slope_at_u = (g(u + h) - g(u - h)) / (2 * h);
  double sum = 0;
  for (int k = 0; k < nodes; ++k) {
    const double v = alpha * std::cos(pi * (k + 0.5) / nodes);
    sum += v == u ? slope_at_u : (g(v) - gu) / (v - u);
  }
  return std::sqrt((alpha - u) * (alpha + u)) * sum / nodes;
}

}  // namespace wavecontact
