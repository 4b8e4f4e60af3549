// Compiled with -mavx2 -mfma -fno-math-errno (runtime/CMakeLists.txt); called only where
// the CPU has both (simd_pressure_available()). The sincospi of the atoms runs 8 wide on
// CPUs with AVX-512 (pressure_simd_avx512.cpp).
#include <immintrin.h>
#include <sleef.h>

#include <algorithm>
#include <cmath>

#include <boost/math/constants/constants.hpp>

#include "waviness.hpp"  // generated/
#include "pressure_simd.hpp"

namespace wavecontact::detail {

namespace {

constexpr std::size_t block = simd_block;  // points per pass

// sin(pi t[k]) and cos(pi t[k]) for the block, four at a time (SLEEF, 3.5 ulp).
void sincospi_block_avx2(const double* t, double* s, double* c) {
  for (std::size_t k = 0; k < block; k += 4) {
    const Sleef___m256d_2 sc = Sleef_sincospid4_u35avx2(_mm256_load_pd(t + k));
    _mm256_store_pd(s + k, sc.x);
    _mm256_store_pd(c + k, sc.y);
  }
}

using SincospiBlock = void (*)(const double* t, double* s, double* c);

struct Atoms {
  alignas(64) double r[block], Cx[block], Sx[block], D[block];
  alignas(64) double q[block], e[block], d[block];       // arguments
  alignas(64) double sin_q[block], cos_q[block], sin_d[block], cos_d[block];
};

// The atoms of angles.hpp for a block of points (the loops vectorise): r = |x| reduced to
// the period, q = r/b1 carried with its rounding residual e, Cx = cos(pi q), Sx = 1 - Cx =
// sin^2/(1 + cos) (q <= 1/2 inside the zone; only if with_Sx, as the waviness forms do not
// use it), and D = cos x^ - cos a^ = 2 sin(a^ - d^) sin d^, d^ = pi d, d = (a - r)/2b1
// (a - r exact as r -> a), with sin(a^ - d^) = sin a^ cos d^ - cos a^ sin d^: for a <= b1/2
// the angle a^ - d^ lies in [a^/2, a^] within [0, pi/2] and the first term is at most twice
// the result, so no digits are lost. Two sincospi per point and no division but Sx's.
template <bool with_Sx>
void compute_atoms(double b1, double a, double sin_a, double cos_a, SincospiBlock sincospi_block,
                   const double* x, Atoms& out) {
  constexpr double pi = boost::math::double_constants::pi;
  const double inv_b1 = 1 / b1, period = 2 * b1, inv_period = 0.5 / b1;
  for (std::size_t k = 0; k < block; ++k) {
    const double r = std::fabs(std::fma(-std::nearbyint(x[k] * inv_period), period, x[k]));
    const double q = r * inv_b1;  // need not be correctly rounded: e carries its residual
    out.r[k] = r, out.q[k] = q, out.e[k] = std::fma(-q, b1, r) * inv_b1;
    out.d[k] = (a - r) * inv_period;
  }
  sincospi_block(out.q, out.sin_q, out.cos_q);
  sincospi_block(out.d, out.sin_d, out.cos_d);
  for (std::size_t k = 0; k < block; ++k) {
    const double slope = pi * out.sin_q[k] * out.e[k];
    out.Cx[k] = out.cos_q[k] - slope;
    const double sin_sum = sin_a * out.cos_d[k] - cos_a * out.sin_d[k];
    out.D[k] = 2 * sin_sum * out.sin_d[k];
    if constexpr (with_Sx) out.Sx[k] = out.sin_q[k] * out.sin_q[k] / (1 + out.cos_q[k]) + slope;
  }
}

// For each block of points: the atoms, then evaluate_block(atoms, value) (branch-free over
// the whole block, so that it vectorises; outside the zone D < 0 and the value is
// discarded), then store(k, value) for the points of the zone and store(k, 0) elsewhere.
template <bool with_Sx, typename BlockEvaluator, typename Store>
void pressure_blocks(double b1, double a, const double* x, std::size_t count,
                     const BlockEvaluator& evaluate_block, const Store& store) {
  Atoms atoms;  // every field read is written first
  alignas(64) double padded[block], value[block];
  const double sin_a = Sleef_sinpi_u05(a / b1), cos_a = Sleef_cospi_u05(a / b1);
  // The widest sincospi this CPU runs: AVX-512 (pressure_simd_avx512.cpp) where available.
  const SincospiBlock sincospi_block = avx512_available() ? &sincospi_block_avx512 : &sincospi_block_avx2;
  for (std::size_t start = 0; start < count; start += block) {
    const std::size_t n = std::min(block, count - start);
    const double* points = x + start;
    if (n < block) {  // the tail, padded with the zone's centre
      std::fill(std::copy(points, points + n, padded), padded + block, 0.0);
      points = padded;
    }
    compute_atoms<with_Sx>(b1, a, sin_a, cos_a, sincospi_block, points, atoms);
    evaluate_block(atoms, value);
    for (std::size_t k = 0; k < n; ++k) store(start + k, atoms.r[k] < a ? value[k] : 0.0);
  }
}

template <typename Evaluator>
void waviness_blocks(const WavinessZone& z, const double* x, double* p, std::size_t count,
                     const Evaluator& evaluate) {
  pressure_blocks<false>(
      z.b1, z.a, x, count,
      [&](const Atoms& atoms, double* value) {
        // Sx is not computed: the waviness forms leave it unused (accuracy_test would notice).
        for (std::size_t k = 0; k < block; ++k) value[k] = evaluate(atoms.Cx[k], 0.0, atoms.D[k]);
      },
      [p](std::size_t i, double value) { p[i] = value; });
}

// sum_{j<n} P_{n-1-j}(Ca) V_j(Cx) for the whole block by Clenshaw's recurrence in Reinsch's
// form, d_j = (c_j + d_{j+1}) - 2 Sx b_{j+1}, b_j = d_j + b_{j+1}, as the generated
// roughness_n<N>_pressure does per point (derive/roughness.hpp): here the coefficients come
// once per zone and each step runs across the block's points.
void roughness_block(const RoughnessZone& z, const Atoms& atoms, double* value) {
  alignas(64) double b[block], d[block], two_Sx[block];
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
  pressure_blocks<true>(
      z.b1, z.a, x, count, [&](const Atoms& atoms, double* value) { roughness_block(z, atoms, value); },
      [p](std::size_t i, double value) { p[i] += value; });
}

}  // namespace wavecontact::detail
