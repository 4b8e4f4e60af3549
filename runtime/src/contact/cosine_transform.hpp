// FFTW's cosine transforms, in place. The DCT-I of N + 1 points,
//   y_k = x_0 + (-1)^k x_N + 2 sum_{j=1}^{N-1} x_j cos(pi j k / N),
// the discrete Fourier transform of an even sequence of period 2N held as its half period,
// and its own inverse up to the factor 2N: the contact solver's grid guess and its cosine
// series on uniform grids take it. It is taken as just that, FFTW's complex transform of the
// 2N real points (r2c): FFTW's own DCT-I (REDFT00), as FFTW_ESTIMATE plans it, took 1.45 to 2.4
// times as long at N = 256 to 4096 and 16384, 4 to 9 times at 8192, 32768, 65536 and 131072 (3.3 ms
// against 0.62 ms at 65536, the seed grid of n > 2048), with the same rounding; its
// halfcomplex transform (R2HC) of the 2N points, 2 to 4 times as long as r2c (2026-11-30).
// The DCT-II (REDFT10) of N points,
//   y_k = 2 sum_{j=0}^{N-1} x_j cos(pi k (j + 1/2) / N),
// takes values at Chebyshev's nodes of the first kind to their series (chebyshev.hpp), and the
// DCT-III (REDFT01) of N points, y_k = x_0 + 2 sum_{j=1}^{N-1} x_j cos(pi j (k + 1/2) / N),
// a series back to its values there.
#pragma once

#include <cstddef>
#include <vector>

#include <fftw3.h>

namespace wavecontact::detail {

class CosineTransform {
 public:
  enum class Kind { dct1, dct2, dct3 };
  explicit CosineTransform(std::size_t points, Kind kind = Kind::dct1);  // dct1: N + 1 >= 2
  ~CosineTransform();
  CosineTransform(const CosineTransform&) = delete;
  CosineTransform& operator=(const CosineTransform&) = delete;

  std::vector<double>& data() { return data_; }
  void apply();  // on data(), in place

 private:
  std::vector<double> data_;
  // The DCT-I's even extension (2N points) and its spectrum (N + 1 values), FFTW's aligned
  // buffers; the other kinds run on data() itself.
  double* extension_ = nullptr;
  fftw_complex* spectrum_ = nullptr;
  fftw_plan plan_;
};

// The transform of this size and kind, planned once a thread: planning (FFTW_ESTIMATE) costs
// 0.06 to 1.1 ms, running one of the contact solver's sizes a few microseconds. The plans of
// at most 64 sizes a thread are kept (zones take many sizes over a long run; a plan of 32768
// points holds 256 KB, a DCT-I's five times as much with its real transform's buffers). The
// reference is valid until this thread's next call.
CosineTransform& planned_transform(std::size_t points, CosineTransform::Kind kind);

// sum_j c_j cos(j pi k / N) at k = 0 .. N, for c of at most N + 1 terms.
std::vector<double> cosine_series_on_grid(const std::vector<double>& c, std::size_t N);

}  // namespace wavecontact::detail
