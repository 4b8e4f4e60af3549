#include "kinked_inversion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

namespace wavecontact::detail {

namespace {

constexpr double pi = boost::math::double_constants::pi;
constexpr unsigned max_depth = 12;
constexpr double tolerance = 1e-14;

using Rule = boost::math::quadrature::gauss_kronrod<double, 31>;

// The sum of the integrals over consecutive pieces of [breaks.front(), breaks.back()], to the
// tolerance relative to the integral of |f| over the whole: 31-point Gauss-Kronrod on every
// piece, then adaptive bisection on the pieces whose error estimate exceeds that. (Tiny pieces
// next to the kink carry integrands whose evaluation has lost digits to v - u, harmless to
// the whole but not to a tolerance relative to the piece.) Each piece is mapped onto
// [-1, 1]: Boost's rule floors its error estimate at 2 eps times the integral over [-1, 1]
// but compares it with the tolerance times the integral over the piece, so that a piece
// shorter than about 2 eps/tolerance could never stop short of max_depth.
template <typename F>
double integrate_pieces(const F& f, std::vector<double> breaks) {
  std::sort(breaks.begin(), breaks.end());
  struct Piece {
    double mid, half, estimate, error;
  };
  std::vector<Piece> pieces;
  double sum = 0, magnitude = 0;
  for (std::size_t i = 1; i < breaks.size(); ++i) {
    if (!(breaks[i] > breaks[i - 1])) continue;
    Piece piece{(breaks[i] + breaks[i - 1]) / 2, (breaks[i] - breaks[i - 1]) / 2, 0, 0};
    double L1 = 0;
    piece.estimate = piece.half * Rule::integrate([&](double t) { return f(piece.mid + piece.half * t); },
                                                  -1.0, 1.0, 0, tolerance, &piece.error, &L1);
    piece.error *= piece.half;
    sum += piece.estimate;
    magnitude += piece.half * L1;
    pieces.push_back(piece);
  }
  for (const Piece& piece : pieces) {
    if (piece.error <= tolerance * magnitude) continue;
    const double relative =
        tolerance * magnitude / std::max(std::fabs(piece.estimate), std::numeric_limits<double>::min());
    sum += piece.half * Rule::integrate([&](double t) { return f(piece.mid + piece.half * t); }, -1.0, 1.0,
                                        max_depth, relative) -
           piece.estimate;
  }
  return sum;
}

}  // namespace

double PiecewiseDividedDifference::operator()(double v, double u) const {
  const bool u_top = std::fabs(u) <= beta, v_top = std::fabs(v) <= beta;
  const auto g = [&](bool top, double w) { return top ? top_g(w) : flank_g(w); };
  if (std::fabs(v - u) > (1 + std::fabs(u)) / 4) return (g(v_top, v) - g(u_top, u)) / (v - u);
  if (u_top == v_top) return u_top ? top_divided_difference(v, u) : flank_divided_difference(v, u);
  // Across the kink: g_B(v) - g_A(u) = [g_B(v) - g_B(u)] + [g_B(u) - g_A(u)].
  if (std::fabs(g(v_top, u)) > 2 * std::fabs(g(u_top, u))) return (g(v_top, v) - g(u_top, u)) / (v - u);
  const double B_minus_A = v_top ? -jump(u) : jump(u);
  return (v_top ? top_divided_difference(v, u) : flank_divided_difference(v, u)) + B_minus_A / (v - u);
}

double kinked_pressure(const std::function<double(double v, double u)>& divided_difference, double beta,
                       HalfAngles zone, HalfAngles point, double D) {
  const double alpha = zone.s / zone.c, u = point.s / point.c;
  auto integrand = [&](double theta) { return divided_difference(alpha * std::cos(theta), u); };
  // Pieces: the kinks (v = +-beta), where the integrand's slope jumps; for u within
  // delta = |beta - u| of the kink, across it the jump's term decays over a layer of width
  // delta: pieces growing by 4 from the kink resolve it. And v = u.
  std::vector<double> breaks{0, pi, std::acos(u / alpha)};
  if (alpha > beta) {
    const double kink = std::acos(beta / alpha);
    breaks.push_back(kink);
    breaks.push_back(pi - kink);
    const double delta = std::fabs(beta - u), side = u < beta ? 1 : -1;
    for (double width = delta; width > 0 && width < beta; width *= 4) {
      const double v = beta + side * width;
      if (v >= alpha || v <= 0) break;
      breaks.push_back(std::acos(v / alpha));
    }
  }
  const double root = std::sqrt(D / 2) / (zone.c * point.c);  // sqrt(alpha^2 - u^2)
  return root / pi * integrate_pieces(integrand, breaks);
}

}  // namespace wavecontact::detail
