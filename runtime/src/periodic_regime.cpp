#include "periodic_regime.hpp"

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

// g(v) of eq. 5 for the curve of eq. 2 (normalised) on one branch: (m+1) N(v)/q(v)^2 with
// N = v (1 + v^2) and q = c0 + c1 v^2, the top (|v| <= 1, cos x^ >= 0: c0 = 1 + m,
// c1 = 1 - m) or the flank (c0 = 1 - m, c1 = 1 + m), each continued off its own side.
struct Branch {
  double m, c0, c1;

  static Branch of(double m, double v) {
    return std::fabs(v) <= 1 ? Branch{m, 1 + m, 1 - m} : Branch{m, 1 - m, 1 + m};
  }
  double q(double v) const { return c0 + c1 * v * v; }
  double g(double v) const {
    const double qv = q(v);
    return (m + 1) * v * (1 + v * v) / (qv * qv);
  }
  // (g(v) - g(u))/(v - u) with the factor v - u divided out of the numerator: no digits lost
  // as v -> u. N(v) q(u)^2 - N(u) q(v)^2 = (v - u) [q(u)^2 (v^2 + uv + u^2 + 1)
  // - N(u) c1 (v + u)(q(v) + q(u))].
  double divided_difference(double v, double u) const {
    const double qv = q(v), qu = q(u);
    const double numerator = qu * qu * (v * v + u * v + u * u + 1) - u * (1 + u * u) * c1 * (v + u) * (qv + qu);
    return (m + 1) * numerator / (qv * qv * qu * qu);
  }
};

// (g(v) - g(u))/(v - u) for g with the kink at v = +-1: the plain quotient where v - u is
// not small (the divided difference above cancels where u and v are large and apart). Else
// on one branch that divided difference; across the kink, |v - u| >= ||u| - 1|, g_B(v) -
// g_A(u) = [g_B(v) - g_B(u)]
// + [g_B(u) - g_A(u)], the second (m+1) N(u) (q_A^2 - q_B^2)/(q_A q_B)^2 with
// q_top(u) - q_flank(u) = 2m (1 - u)(1 + u) without cancellation, unless u sits near B's pole
// (q_B(u) small against q_A(u)), where v - u is no longer small and the plain quotient holds
// its digits.
double kinked_divided_difference(double m, double v, double u) {
  const Branch A = Branch::of(m, u), B = Branch::of(m, v);
  if (std::fabs(v - u) > (1 + std::fabs(u)) / 4) return (B.g(v) - A.g(u)) / (v - u);
  if (A.c0 == B.c0) return A.divided_difference(v, u);  // one branch, or m = 0
  const double qA = A.q(u), qB = B.q(u);
  if (!(std::fabs(qB) >= std::fabs(qA) / 2)) return (B.g(v) - A.g(u)) / (v - u);
  const double top_minus_flank = 2 * m * (1 - std::fabs(u)) * (1 + std::fabs(u));
  const double qA_minus_qB = std::fabs(u) <= 1 ? top_minus_flank : -top_minus_flank;
  const double jump = (m + 1) * u * (1 + u * u) * qA_minus_qB * (qA + qB) / (qA * qA * qB * qB);
  return B.divided_difference(v, u) + jump / (v - u);
}

}  // namespace

double periodic_pressure(double m, HalfAngles zone, HalfAngles point, double D) {
  // Eq. 12 with v = alpha cos(theta) (MATH.md section 4):
  // p(u) = sqrt(alpha^2 - u^2) (1/pi) Int_0^pi (g(alpha cos theta) - g(u))/(alpha cos theta - u).
  const double alpha = zone.s / zone.c, u = point.s / point.c;
  auto divided_difference = [&](double theta) { return kinked_divided_difference(m, alpha * std::cos(theta), u); };
  // Pieces: the kinks (v = +-1), where the integrand's slope jumps; for u within
  // delta = |1 - u| of the kink, across it the jump's term decays over a layer of width delta:
  // pieces growing by 4 from the kink resolve it. And v = u.
  std::vector<double> breaks{0, pi, std::acos(u / alpha)};
  if (alpha > 1) {
    const double kink = std::acos(1 / alpha);
    breaks.push_back(kink);
    breaks.push_back(pi - kink);
    const double delta = std::fabs(1 - u), side = u < 1 ? 1 : -1;
    for (double width = delta; width > 0 && width < 1; width *= 4) {
      const double v = 1 + side * width;
      if (v >= alpha || v <= 0) break;
      breaks.push_back(std::acos(v / alpha));
    }
  }
  const double root = std::sqrt(D / 2) / (zone.c * point.c);  // sqrt(alpha^2 - u^2)
  return root / pi * integrate_pieces(divided_difference, breaks);
}

}  // namespace wavecontact::detail
