// The surface as the contact solver sees it: an even profile y(x^) of period 2 pi, given by
// angle (docs/contact.md), with the points where its slope is not analytic.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

namespace wavecontact::detail {

// The kink corrections computed for one kink, by window (kink_correction.cpp).
struct KinkWindows;
std::shared_ptr<KinkWindows> make_kink_windows();
// The windows of every kink whose position and slope jump `key` determines, shared by the
// surfaces that have it (those of one waviness and any roughness: the roughness is analytic
// across the kink and leaves its slope jump as it is). The last 32 keys' windows are kept.
std::shared_ptr<KinkWindows> shared_kink_windows(const std::vector<double>& key);

// A point x^0 where the profile changes branch (eq. 2's |cos x^| at x^ = pi/2, a profile built
// with abs()): y is C^1 there, and the branches continued across it differ by
// D(s) = Y_beyond(s) - Y_before(s), s = cos x^ (Y_before holds for s > s0, towards the top).
struct Kink {
  double angle = 0, s = 0;
  // (E*/2) D'(s): analytic within `radius` of s0, where the branches' continuations have
  // their nearest pole.
  std::function<double(double)> slope_jump;
  double radius = 0;
  std::shared_ptr<KinkWindows> windows = make_kink_windows();
};

struct SurfaceModel {
  std::function<double(double)> height;  // y(x^), 0 <= x^ <= pi
  std::function<double(double)> slope;   // dy/dx^
  // out[i] = y(x) - y(x0) at the points x = x0 + delta[i] in x^, s = cos x0 + ds[i] in s,
  // i < count, each offset given both ways and each to its own relative precision (the
  // waviness takes ds, the harmonics delta), without the cancellation of the plain
  // difference; one call for a zone's nodes, whatever concerns x0 computed once. With
  // `slopes`, also dy/ds at the points (to a few digits), from sin x^ there (`sines`).
  std::function<void(double x0, const double* ds, const double* delta, std::size_t count, double* out,
                     const double* sines, double* slopes)>
      height_steps;
  // The same at angles x[i] (the offsets from them).
  void height_differences(const double* x, std::size_t count, double x0, double* out) const;
  // The same at the points s = cos x0 + ds[i], x[i] their angles to a few ulps (which the
  // offsets in x^ take only as relative factors): a zone's Chebyshev nodes, placed exactly in
  // s whatever the rounding of their angles; with `slopes`, dy/ds there as well.
  void height_offsets(const double* x, const double* ds, std::size_t count, double x0, double* out,
                      double* slopes = nullptr) const;
  std::vector<Kink> kinks;
  double resolution = 0;  // half the shortest wavelength, in x^: pi / (highest harmonic)
  double E = 0;           // reduced modulus E*
  double scale = 0;       // an upper bound of max |y|
  // The highest point (x^), the curvature -y'' there and max y - min y: locate_top().
  double top_angle = 0, top_curvature = 0, height_range = 0;
  // y(x) - y(x0) at one point.
  double height_difference(double x, double x0) const {
    double difference = 0;
    height_differences(&x, 1, x0, &difference);
    return difference;
  }
  // y(x) - y(top_angle): the heights the solver works with (y near the top keeps its digits).
  double depth(double x) const { return height_difference(x, top_angle); }
};

// Fills top_angle, top_curvature and height_range: a scan of 16 points a resolution, the
// highest refined by Brent's method.
void locate_top(SurfaceModel& surface);

}  // namespace wavecontact::detail
