// Compiled with -mavx2 -mfma -fno-math-errno (runtime/CMakeLists.txt); called only where
// the CPU has both (simd_pressure_available()).
#include <immintrin.h>
#include <sleef.h>

#include <algorithm>
#include <cmath>

#include <boost/math/constants/constants.hpp>

#include "waviness.hpp"  // generated/
#include "pressure_simd.hpp"

namespace wavecontact::detail {

namespace {

constexpr std::size_t block = 256;  // points per pass; a multiple of 4

struct Atoms {
  alignas(32) double r[block], Cx[block], Sx[block], D[block];
};

// The atoms of angles.hpp for 4 points: r = |x| reduced to the period, q = r/b1 carried
// with its rounding residual e, Cx = cos(pi q), Sx = 1 - Cx = sin^2/(1 + cos) (q <= 1/2
// inside the zone), and D = 2 sin(A + h) sin(A - h), A = pi a/2b1, h = pi q/2: the first
// factor as sin A cos h + cos A sin h (no cancellation; cos h, sin h by half angles from
// cos(pi q) >= 0), the second by sinpi((a - r)/2b1) itself, exact as r -> a.
void atoms4(double zone_b1, double zone_a, double sin_A, double cos_A, const double* x,
            Atoms& out, std::size_t i) {  // x[0..3] -> out[i..i+3]
  // q = r (1/b1) need not be correctly rounded: e carries its actual residual.
  const __m256d b1 = _mm256_set1_pd(zone_b1), inv_b1 = _mm256_set1_pd(1 / zone_b1), a = _mm256_set1_pd(zone_a);
  const __m256d period = _mm256_set1_pd(2 * zone_b1), inv_period = _mm256_set1_pd(0.5 / zone_b1);
  const __m256d half = _mm256_set1_pd(0.5);
  const __m256d pi = _mm256_set1_pd(boost::math::double_constants::pi);
  const __m256d sign = _mm256_set1_pd(-0.0), one = _mm256_set1_pd(1.0);
  __m256d v = _mm256_loadu_pd(x);
  const __m256d turns = _mm256_round_pd(_mm256_mul_pd(v, inv_period), _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
  v = _mm256_fnmadd_pd(turns, period, v);
  const __m256d r = _mm256_andnot_pd(sign, v);
  const __m256d q = _mm256_mul_pd(r, inv_b1);
  const __m256d e = _mm256_mul_pd(_mm256_fnmadd_pd(q, b1, r), inv_b1);
  const Sleef___m256d_2 sc = Sleef_sincospid4_u35avx2(q);
  const __m256d slope = _mm256_mul_pd(_mm256_mul_pd(pi, sc.x), e);
  const __m256d one_plus_cos = _mm256_add_pd(one, sc.y);
  const __m256d Cx = _mm256_sub_pd(sc.y, slope);
  const __m256d Sx = _mm256_add_pd(_mm256_div_pd(_mm256_mul_pd(sc.x, sc.x), one_plus_cos), slope);
  const __m256d cos_h = _mm256_sqrt_pd(_mm256_mul_pd(half, one_plus_cos));
  const __m256d sin_h = _mm256_div_pd(_mm256_mul_pd(half, sc.x), cos_h);
  const __m256d plus = _mm256_fmadd_pd(_mm256_set1_pd(sin_A), cos_h, _mm256_mul_pd(_mm256_set1_pd(cos_A), sin_h));
  const __m256d minus = Sleef_sinpid4_u05avx2(_mm256_mul_pd(_mm256_sub_pd(a, r), inv_period));
  const __m256d D = _mm256_mul_pd(_mm256_add_pd(plus, plus), minus);
  _mm256_store_pd(out.r + i, r);
  _mm256_store_pd(out.Cx + i, Cx);
  _mm256_store_pd(out.Sx + i, Sx);
  _mm256_store_pd(out.D + i, D);
}

// For each block of points: the atoms, then evaluate_block(atoms, value) (branch-free over
// the whole block, so that it vectorises; outside the zone D < 0 and the value is
// discarded), then store(k, value) for the points of the zone and store(k, 0) elsewhere.
template <typename BlockEvaluator, typename Store>
void pressure_blocks(double b1, double a, const double* x, std::size_t count,
                     const BlockEvaluator& evaluate_block, const Store& store) {
  Atoms atoms{};  // the block loop reads past a short tail
  alignas(32) double padded[4], value[block];
  const double sin_A = Sleef_sinpi_u05(a / (2 * b1)), cos_A = Sleef_cospi_u05(a / (2 * b1));
  for (std::size_t start = 0; start < count; start += block) {
    const std::size_t n = std::min(block, count - start);
    std::size_t i = 0;
    for (; i + 4 <= n; i += 4) atoms4(b1, a, sin_A, cos_A, x + start + i, atoms, i);
    if (i < n) {  // the tail, padded with the zone's centre
      std::fill(padded, padded + 4, 0.0);
      std::copy(x + start + i, x + start + n, padded);
      atoms4(b1, a, sin_A, cos_A, padded, atoms, i);
    }
    evaluate_block(atoms, value);
    for (std::size_t k = 0; k < n; ++k) store(start + k, atoms.r[k] < a ? value[k] : 0.0);
  }
}

template <typename Evaluator>
void waviness_blocks(const WavinessZone& z, const double* x, double* p, std::size_t count,
                     const Evaluator& evaluate) {
  pressure_blocks(
      z.b1, z.a, x, count,
      [&](const Atoms& atoms, double* value) {
        for (std::size_t k = 0; k < block; ++k) value[k] = evaluate(atoms.Cx[k], atoms.Sx[k], atoms.D[k]);
      },
      [p](std::size_t i, double value) { p[i] = value; });
}

// sum_{j<n} P_{n-1-j}(Ca) V_j(Cx) for the whole block by Clenshaw's recurrence in Reinsch's
// form, d_j = (c_j + d_{j+1}) - 2 Sx b_{j+1}, b_j = d_j + b_{j+1}, as the generated
// roughness_n<N>_pressure does per point (derive/roughness.hpp): here the coefficients come
// once per zone and each step runs across the block's points.
void roughness_block(const RoughnessZone& z, const Atoms& atoms, double* value) {
  alignas(32) double b[block], d[block], two_Sx[block];
  for (std::size_t k = 0; k < block; ++k) b[k] = 0, d[k] = 0, two_Sx[k] = 2 * atoms.Sx[k];
  for (int j = z.n - 1; j >= 0; --j) {
    const double c = z.legendre[z.n - 1 - j];
    for (std::size_t k = 0; k < block; ++k) {
      const double d_j = (c + d[k]) - b[k] * two_Sx[k];
      b[k] += d_j;
      d[k] = d_j;
    }
  }
  for (std::size_t k = 0; k < block; ++k) {
    value[k] = z.scale * std::sqrt((1 + atoms.Cx[k]) * atoms.D[k]) * d[k];
  }
}

}  // namespace

void simd_pressure(const WavinessZone& z, Form form, const double* x, double* p,
                   std::size_t count) {
  const double E = z.E, H1 = z.H1, b1 = z.b1, m = z.m, Ca = z.Ca, Sa = z.Sa;  // not aliased by p
  if (form == Form::exact) {
    waviness_blocks(z, x, p, count, [=](double Cx, double Sx, double D) {
      return generated::waviness_pressure_exact(E, H1, b1, m, Ca, Sa, Cx, Sx, D);
    });
  } else {
    waviness_blocks(z, x, p, count, [=](double Cx, double Sx, double D) {
      return generated::waviness_pressure_paper(E, H1, b1, m, Ca, Sa, Cx, Sx, D);
    });
  }
}

void simd_add_roughness_pressure(const RoughnessZone& z, const double* x, double* p,
                                 std::size_t count) {
  pressure_blocks(
      z.b1, z.a, x, count, [&](const Atoms& atoms, double* value) { roughness_block(z, atoms, value); },
      [p](std::size_t i, double value) { p[i] += value; });
}

}  // namespace wavecontact::detail
