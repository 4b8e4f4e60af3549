// The part of a zone's density that a kink of the surface inside it makes (docs/contact.md).
//
// Across a kink at s0 the right-hand side (E/2) y + C - (the other zones) is C^1 only: it is
// A(s) + B(s) H(s0 - s), A and B analytic, B = (E/2)(Y_beyond - Y_before) = O((s - s0)^2).
// The density then holds -(1/pi) B'(s) log|s - s0| (the Hilbert transform of the jump), which
// no Chebyshev series converges to. It is taken out in closed form, windowed:
//   q_k(t) = -(1/pi) B'(t) log|t - s0| W((t - s0)/r),  |t - s0| < r,
// W a polynomial, 1 - O(u^10) at 0 and zero to order K at |u| = 1: K = 20 (degree 48) for
// r >= 3e-4, K = 8 (degree 24) below (the rest of the density converges like N^-K; a steeper
// window needs more nodes for its own shape, kink_correction.cpp), r within the zone and
// within the branches' analyticity. Its potential is smooth on either side of s0 and of the
// window's edges: it is computed once per window (near the window by Gauss-Legendre quadrature
// after a sigmoidal substitution, beyond twice its radius by its moments' expansion) at the
// Chebyshev nodes of the pieces of [-1, 1] between them, and interpolated. A kink closer to an
// end than a millionth of the zone is left alone: the other branch holds on a sliver there,
// whose effect (about the sliver's width to the power 3.5: 3e-9 at 1.4e-5) is near the
// contact's rounding, while a window that narrow would need hundreds of thousands of nodes;
// nearer than a ten-thousandth, the window needs up to most_kinked_nodes (active_set.hpp).
#pragma once

#include <cmath>
#include <functional>
#include <memory>
#include <vector>

#include "surface_model.hpp"
#include "zone.hpp"

namespace wavecontact::detail {

class KinkCorrection {
 public:
  // The window radius for a zone: the largest of the geometric grid 0.5 R 2^-k (R the
  // branches' analyticity radius) within 0.9 of the room between the kink and the zone's
  // ends, for the kink the zone holds well inside; 0 for none. (At 0.9 R, the slope jump
  // varies on the window's own scale near its edges, and a zone ending near the kink had
  // Newton's method creep: sweeps 891 and 1232 of the campaign.)
  static double radius_for(const SurfaceModel& surface, const ZoneGeometry& zone);
  // The correction of radius r of the kink inside the zone (nullptr for r = 0 or none); each
  // window is computed once and kept by the kink.
  static std::shared_ptr<const KinkCorrection> of(const SurfaceModel& surface, const ZoneGeometry& zone, double r);
  // Whether the window of radius r lies within the zone (or r = 0 and no kink needs one).
  static bool fits(const SurfaceModel& surface, const ZoneGeometry& zone, double r);

  // q_k at s = cos x^ (0 outside the window).
  double density(double s) const;
  // -(1/pi) Int q_k(t) log|s - t| dt at s = cos x (any x^ in [0, pi]).
  double potential(double x) const;
  // The same at x[0 .. count) into out: a run of points on one piece summed side by side.
  void potentials(const double* x, std::size_t count, double* out) const;
  // Int q_k dt: its part of the zone's load.
  double load() const { return load_; }
  // How many of the zone's `nodes` Chebyshev nodes lie within the window: nodes/pi times the
  // angle acos(tau), tau = (s - m)/h, spans there.
  double nodes_within(const ZoneGeometry& zone, std::size_t nodes) const;

  KinkCorrection(const Kink& kink, double r);

 private:
  struct Piece {
    double lo, hi;
    std::vector<double> coefficients;  // of the potential in t = (2 s - lo - hi)/(hi - lo)
  };
  double direct_potential(double s) const;
  // The piece whose interpolant holds s (pieces_.size(): none, the direct potential there).
  std::size_t piece_of(double s) const;
  // The kink's position and slope jump, not the Kink itself: its windows hold this object.
  double s0_;
  std::function<double(double)> slope_jump_;
  double r_;
  int order_;  // of the window W at its edges
  std::vector<Piece> pieces_;
  std::vector<double> moments_;  // nu_k of the far field (kink_correction.cpp)
  double load_ = 0;
};

}  // namespace wavecontact::detail
