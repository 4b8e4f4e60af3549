// An independent oracle for the contact solver: the FFT boundary-element method.
//
// The period 2 pi of x^ = pi x/b1 on M points, the pressure p^ at the points, the surface
// displacement by FFT (FFTW3) with u_k = 2 p_k/(E* |k|) (the periodic half-plane), and the
// contact found by Polonsky & Keer's constrained conjugate gradient (Wear 231, 1999): the
// gap (y_max - y) - delta + u >= 0, p >= 0, p gap = 0, mean pressure P/(2 pi). It shares no
// code with the runtime's solver: a different formulation (a quadratic programme on a grid
// rather than the bounded inversion), a different discretisation and different numerics.
// p(0) and the largest pressure converge like a power of the spacing: Richardson extrapolation
// over three grids gives them and their error estimates. The zone ends (p^2 fitted inside the
// zone and extrapolated to 0) err with changing sign from grid to grid: their estimate is
// the spread over the three grids, at least a fiftieth of the finest spacing.
#pragma once

#include <functional>
#include <vector>

namespace wavecontact::test {

struct BemContact {
  std::vector<double> zone_ends;  // lo, hi of every zone of [0, pi], sub-grid (x^)
  double contact_fraction;        // contact length / period
  double p0;                      // p^ at x^ = 0
  double max_pressure;            // normalised, the vertex of the parabola at the largest point
  double grid_max_pressure;       // the largest grid value
  int iterations;
};

// The contact of the profile y(x^) (even, period 2 pi) pressed with the load P (normalised:
// P = Int p^ dx^ over a period) against a half-plane of reduced modulus E, on M points;
// kinks: the x^ in [0, pi] where y' is not smooth.
BemContact bem_contact(const std::function<double(double)>& y, double E, double P, int M,
                       const std::vector<double>& kinks = {});

// Every quantity of bem_contact at M, 2M and 4M points, extrapolated, with an error estimate.
struct BemEstimate {
  std::vector<double> zone_ends, zone_ends_error;
  double contact_fraction, contact_fraction_error;
  double p0, p0_error;
  double max_pressure, max_pressure_error;
};
// Throws std::runtime_error if the three grids disagree on the number of zones.
BemEstimate bem_extrapolated(const std::function<double(double)>& y, double E, double P, int M,
                             const std::vector<double>& kinks = {});

}  // namespace wavecontact::test
