// The array kernels' bodies, included by each per-ISA unit (pressure_simd_avx2.cpp,
// pressure_simd_avx512.cpp, pressure_simd_scalar.cpp) and compiled there with its flags: plain
// loops over blocks of points that the compiler vectorises for that ISA (but in the scalar
// unit, which it keeps scalar). Everything here has internal linkage,
// so no out-of-line copy compiled for one ISA can serve another unit
// (tests/simd_units_export_entry_points_only.cmake checks the symbols).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include <immintrin.h>

#include "wavecontact/generated/bounded_trigonometry.hpp"
#include "kernels/pressure_simd.hpp"
#include "wavecontact/angles.hpp"
#include "wavecontact/generated/waviness_evaluators.hpp"

namespace wavecontact::detail {
namespace {

constexpr std::size_t block = simd_block;  // points per pass

// The unit's arithmetic: fused multiply-adds and the derived sine built on them where its ISA
// has FMA (AVX2, AVX-512), else every product and sum rounded apart (the scalar unit, for CPUs
// without FMA; sinpi_quarter_unfused, within 2 ulp). Where the kernels call multiply_add, the
// product is at most twice the result or the sum does not cancel, so that unfused it costs a
// rounding of about the result's size, no more.
inline double multiply_add(double a, double b, double c) {
#if defined(__FMA__)
  return std::fma(a, b, c);
#else
  return a * b + c;
#endif
}

inline double bounded_sinpi(double t) {
#if defined(__FMA__)
  return generated::sinpi_quarter(t);
#else
  return generated::sinpi_quarter_unfused(t);
#endif
}

// r = |x| reduced to the period 2 b1, exactly: x - n 2 b1 with one rounding. Without FMA in the
// ISA, the points of the central period (n = 0) as they are and the others by std::fma, which
// the C library rounds correctly in software where the CPU cannot.
inline double reduced_distance(double x, double b1) {
  const double period = 2 * b1, inv_period = 0.5 / b1;
#if defined(__FMA__)
  return std::fabs(std::fma(-std::nearbyint(x * inv_period), period, x));
#else
  return std::fabs(x) <= b1 ? std::fabs(x) : std::fabs(std::fma(-std::nearbyint(x * inv_period), period, x));
#endif
}

struct Atoms {
  alignas(64) double r[block], Cx[block], Sx[block], D[block];
};

// The atoms of angles.hpp for a block of points, from the derived sin(pi t), |t| <= 1/4
// (generated/bounded_trigonometry.hpp: no range reduction), by exact identities. With r = |x|
// reduced to the period, h = r/(2 b1) = x^/(2 pi) and d = (a - r)/(2 b1) = (a^ - x^)/(2 pi):
//   D  = cos x^ - cos a^ = 2 sin(pi d) sin(a^ - pi d)
//      = 2 sin(pi d) (sin a^ cos(pi d) - cos a^ sin(pi d)),  cos(pi d) = 1 - 2 sin^2(pi d/2),
//   Cx = cos x^ = cos a^ + D (with_cosine: the waviness's),
//   Sx = 1 - cos x^ = 2 sin^2(pi h) (without: the roughness's, which takes 1 + cos x^ as 2 - Sx).
// In the zone (r < a <= b1/2) h, d <= 1/4; each argument carries a relative error of a few eps
// at most (a - r is exact for r >= a/2), which sin(pi t) does not amplify there; the
// subtraction in D loses nothing (a^ - pi d lies in [a^/2, a^], within [0, pi/2], so its first
// term is at most twice the result), and Cx adds two terms >= 0 (cos a^ >= 0 for a <= b1/2,
// D >= 0 in the zone): every atom keeps its relative accuracy, Cx where cos x^ -> 0, D at the
// zone's edge, Sx at its centre. Outside the zone the values are finite and discarded. sin_a =
// sin a^, cos_a = cos a^. With the cosine, Sx is 1 - Cx, which the waviness's closed forms do
// not read (accuracy_test would show one that did: it loses Sx's relative accuracy near the
// centre); without, Cx is 0. atoms_at is one point's, the loop's body, inlined there so that
// the loop vectorises.
struct PointAtoms {
  double r, Cx, Sx, D;
};

template <bool with_cosine>
inline PointAtoms atoms_at(double b1, double a, double sin_a, double cos_a, double x) {
  const double inv_period = 0.5 / b1;
  PointAtoms out;
  out.r = reduced_distance(x, b1);
  const double d = (a - out.r) * inv_period;
  const double sin_d = bounded_sinpi(d);
  const double sin_half_d = bounded_sinpi(d * 0.5);
  const double cos_d = multiply_add(-2 * sin_half_d, sin_half_d, 1.0);
  out.D = 2 * sin_d * multiply_add(sin_a, cos_d, -cos_a * sin_d);
  if constexpr (with_cosine) {
    out.Cx = cos_a + out.D;
    out.Sx = 1 - out.Cx;
  } else {
    const double sin_h = bounded_sinpi(out.r * inv_period);
    out.Sx = 2 * sin_h * sin_h;
    out.Cx = 0;
  }
  return out;
}

template <bool with_cosine>
void compute_atoms(double b1, double a, double sin_a, double cos_a, const double* x, Atoms& out) {
  for (std::size_t k = 0; k < block; ++k) {
    const PointAtoms atoms = atoms_at<with_cosine>(b1, a, sin_a, cos_a, x[k]);
    out.r[k] = atoms.r;
    out.Sx[k] = atoms.Sx;
    if constexpr (with_cosine) out.Cx[k] = atoms.Cx;
    out.D[k] = atoms.D;
  }
}

// sin(pi t) for 0 <= t <= 1/2 given also c = 1/2 - t (each with its own relative rounding):
// sin(pi t) = cos(pi c) = 1 - 2 sin^2(pi c/2) beyond t = 1/4, where it is >= 1/sqrt2.
inline double sinpi_half(double t, double c) {
  const double s = bounded_sinpi(0.5 * c);
  return t <= 0.25 ? bounded_sinpi(t) : multiply_add(-2 * s, s, 1.0);
}

// The atoms of angles.hpp for a block of points of any zone 0 < a <= b1 (the zone beyond b1/2,
// where the arguments above exceed 1/4), by the same identities with the complements to 1/2
// formed in physical units: with h = r/(2 b1), w = (b1 - 2r)/(2 b1), d = (a - r)/(2 b1) and
// s = (a + r)/(2 b1),
//   Sx = 2 sin^2(pi h) up to h = 1/4, beyond 2 - 2 sin^2(pi (b1 - r)/(2 b1)) (>= 1),
//   Cx = sin(pi w) where |w| <= 1/4, else 1 - Sx (|Cx| >= 1/sqrt2),
//   D  = cos x^ - cos a^ = 2 sin(pi s) sin(pi d), sin(pi s) = sin(pi (2 b1 - a - r)/(2 b1)) for s > 1/2,
// each sine by sinpi_half. b1 - 2r, b1 - r, b1 - (a - r) and a + r - b1 are exact where they are
// used (Sterbenz), a - r for r >= a/2: every atom keeps its relative accuracy, as angles.cpp's do
// (point_angles: D from the same product, Cx with the rounding of x/b1 corrected to first order).
// atoms_any_at is one point's, the loop's body, inlined there so that the loop vectorises.
inline PointAtoms atoms_any_at(double b1, double a, double x) {
  const double period = 2 * b1, inv_period = 0.5 / b1;
  const double r = reduced_distance(x, b1);
  const double h = r * inv_period, w = (b1 - 2 * r) * inv_period;
  const double sin_h = bounded_sinpi(h), sin_rest = bounded_sinpi((b1 - r) * inv_period);
  const double Sx = h <= 0.25 ? 2 * sin_h * sin_h : multiply_add(-2 * sin_rest, sin_rest, 2.0);
  const double difference = a - r, sum = a + r;
  const double d = difference * inv_period, d_rest = (b1 - difference) * inv_period;
  const double s = (sum <= b1 ? sum : period - sum) * inv_period, s_rest = std::fabs(b1 - sum) * inv_period;
  PointAtoms out;
  out.r = r;
  out.Sx = Sx;
  out.Cx = std::fabs(w) <= 0.25 ? bounded_sinpi(w) : 1 - Sx;
  out.D = 2 * sinpi_half(s, s_rest) * sinpi_half(d, d_rest);
  return out;
}

void compute_atoms_any(double b1, double a, const double* x, Atoms& out) {
  for (std::size_t k = 0; k < block; ++k) {
    const PointAtoms atoms = atoms_any_at(b1, a, x[k]);
    out.r[k] = atoms.r;
    out.Sx[k] = atoms.Sx;
    out.Cx[k] = atoms.Cx;
    out.D[k] = atoms.D;
  }
}

// The atoms of the points x[i], i < count, of the zone 0 < a <= b1 (compute_atoms_any), into
// angles[i] where r = |x| reduced to the period is < a, inside[i] = whether it is. A few points
// (a tail below block/8) are taken one by one, with the same arithmetic.
void point_angles_kernel(double b1, double a, const double* x, std::size_t count, PointAngles* angles,
                         unsigned char* inside) {
  Atoms atoms;
  alignas(64) double padded[block];
  for (std::size_t start = 0; start < count; start += block) {
    const std::size_t n = std::min(block, count - start);
    if (n < block / 8) {
      for (std::size_t k = start; k < count; ++k) {
        const PointAtoms point = atoms_any_at(b1, a, x[k]);
        inside[k] = point.r < a;
        angles[k] = {point.Cx, point.Sx, point.D};
      }
      return;
    }
    const double* points = x + start;
    if (n < block) {
      std::fill(std::copy(points, points + n, padded), padded + block, 0.0);
      points = padded;
    }
    compute_atoms_any(b1, a, points, atoms);
    for (std::size_t k = 0; k < n; ++k) {
      inside[start + k] = atoms.r[k] < a;
      angles[start + k] = {atoms.Cx[k], atoms.Sx[k], atoms.D[k]};
    }
  }
}

// For each block of points: the atoms (Cx only with_cosine), then evaluate_block(atoms, value) (branch-free over
// the whole block, so that it vectorises; outside the zone D < 0 and the value is
// discarded), then store(k, value) for the points of the zone and store(k, 0) elsewhere.
template <bool with_cosine, typename BlockEvaluator, typename Store>
void pressure_blocks(double b1, double a, double Ca, double Sa, const double* x, std::size_t count,
                     const BlockEvaluator& evaluate_block, const Store& store) {
  Atoms atoms;  // every field read is written first
  alignas(64) double padded[block], value[block];
  const double sin_a = std::sqrt(Sa * (1 + Ca));  // no cancellation: 1 + Ca >= 1 for a <= b1/2
  for (std::size_t start = 0; start < count; start += block) {
    const std::size_t n = std::min(block, count - start);
    const double* points = x + start;
    if (n < block) {  // the tail, padded with the zone's centre
      std::fill(std::copy(points, points + n, padded), padded + block, 0.0);
      points = padded;
    }
    compute_atoms<with_cosine>(b1, a, sin_a, Ca, points, atoms);
    evaluate_block(atoms, value);
    for (std::size_t k = 0; k < n; ++k) store(start + k, atoms.r[k] < a ? value[k] : 0.0);
  }
}

template <typename Evaluator>
void waviness_blocks(const SimdWavinessZone& z, const double* x, double* p, std::size_t count,
                     const Evaluator& evaluate) {
  pressure_blocks<true>(
      z.b1, z.a, z.Ca, z.Sa, x, count,
      [&](const Atoms& atoms, double* value) {
        for (std::size_t k = 0; k < block; ++k) value[k] = evaluate(atoms.Cx[k], atoms.Sx[k], atoms.D[k]);
      },
      [p](std::size_t i, double value) { p[i] = value; });
}

#if defined(__AVX2__)  // the roughness's kernel, on the vector units' intrinsics
// sum_{j<n} P_{n-1-j}(Ca) V_j(Cx) by Clenshaw's recurrence in Reinsch's form,
// d_j = (c_j + d_{j+1}) - 2 Sx b_{j+1}, b_j = d_j + b_{j+1}, as the generated
// roughness_n<N>_pressure does per point (derive/formulas/roughness.hpp): here the coefficients come
// once per zone and each step runs across the block's points (3 operations a point and a
// step, the bound of the cost at large n).
// Written on the unit's vector registers: groups of vectors of points (7 of 4 with AVX2, then
// one; 8 of 8 with AVX-512) go through all the steps with b and d held in registers, 2 Sx read
// from memory by the multiply-add, which the loop across the whole block, storing b and d at
// every step, could not (it ran at the rate of its stores). A step waits 7 cycles on the one
// before (multiply-add, then addition): the more vectors a group, the more of that time is
// used, as far as the registers go (on AVX2, 4 vectors 38.6 ns a point at n = 256, 6: 28.7,
// 7: 26.3, 8 spill: 40). Every other step forms c_j + d_{j+1} as fma(d_{j+1}, 1, c_j) (the
// same value, exactly): AVX-512 then shares its additions between the adders and the FMA units
// (n = 256: 20.2 -> 18.7 ns a point on this project's AVX-512 machine).
void roughness_block(const RoughnessZone& z, const Atoms& atoms, double* value) {
#if defined(__AVX512F__)
  using Vector = __m512d;
  constexpr std::size_t lanes = 8, vectors = 8, tail_vectors = 8;  // of 32 registers: b, d, c, 1
  const auto load = [](const double* p) { return _mm512_load_pd(p); };
  const auto store = [](double* p, Vector v) { _mm512_store_pd(p, v); };
  const auto broadcast = [](double c) { return _mm512_set1_pd(c); };
  const auto add = [](Vector a, Vector b) { return _mm512_add_pd(a, b); };
  const auto minus_product_plus = [](Vector a, Vector b, Vector c) { return _mm512_fnmadd_pd(a, b, c); };
  const auto product_plus = [](Vector a, Vector b, Vector c) { return _mm512_fmadd_pd(a, b, c); };
#else
  using Vector = __m256d;
  constexpr std::size_t lanes = 4, vectors = 7, tail_vectors = 1;  // of 16 registers: b, d, c, 1
  const auto load = [](const double* p) { return _mm256_load_pd(p); };
  const auto store = [](double* p, Vector v) { _mm256_store_pd(p, v); };
  const auto broadcast = [](double c) { return _mm256_set1_pd(c); };
  const auto add = [](Vector a, Vector b) { return _mm256_add_pd(a, b); };
  const auto minus_product_plus = [](Vector a, Vector b, Vector c) { return _mm256_fnmadd_pd(a, b, c); };
  const auto product_plus = [](Vector a, Vector b, Vector c) { return _mm256_fmadd_pd(a, b, c); };
#endif
  static_assert(block % (vectors * lanes) % (tail_vectors * lanes) == 0, "whole groups of vectors per block");
  alignas(64) double sum[block], two_Sx[block];
  for (std::size_t k = 0; k < block; ++k) two_Sx[k] = 2 * atoms.Sx[k];
  const Vector one = broadcast(1.0);
  // The points from start on, count vectors of them, through every step.
  const auto group = [&](std::size_t start, auto count) {
    constexpr std::size_t group_vectors = decltype(count)::value;
    Vector b[group_vectors], d[group_vectors];
    for (std::size_t v = 0; v < group_vectors; ++v) b[v] = broadcast(0.0), d[v] = broadcast(0.0);
    const auto step = [&](int j, bool on_fma) {
      const Vector c = broadcast(z.legendre[z.n - 1 - j]);
      for (std::size_t v = 0; v < group_vectors;
           ++v) {  // d_j = c_j + d_{j+1} - 2 Sx b_{j+1}, one rounding for the product
        const Vector sum_cd = on_fma ? product_plus(d[v], one, c) : add(c, d[v]);
        const Vector d_j = minus_product_plus(b[v], load(two_Sx + start + v * lanes), sum_cd);
        b[v] = add(b[v], d_j);
        d[v] = d_j;
      }
    };
    int j = z.n - 1;
    for (; j >= 1; j -= 2) step(j, false), step(j - 1, true);
    if (j == 0) step(0, false);
    for (std::size_t v = 0; v < group_vectors; ++v) store(sum + start + v * lanes, d[v]);
  };
  std::size_t start = 0;
  for (; start + vectors * lanes <= block; start += vectors * lanes)
    group(start, std::integral_constant<std::size_t, vectors>{});
  if constexpr (block % (vectors * lanes) != 0) {
    for (; start < block; start += tail_vectors * lanes)
      group(start, std::integral_constant<std::size_t, tail_vectors>{});
  }
  for (std::size_t k = 0; k < block; ++k) {  // 1 + cos x^ = 2 - Sx, in [1, 2] in the zone
    value[k] = z.scale * std::sqrt((2 - atoms.Sx[k]) * atoms.D[k]) * sum[k];
  }
}

#endif

// Whether every x[i], i < count, is finite: its exponent bits not all set (integer tests that
// vectorise, with no branch until the end).
bool all_finite_kernel(const double* x, std::size_t count) {
  constexpr std::uint64_t exponent = 0x7ff0000000000000;
  std::uint64_t non_finite = 0;
  for (std::size_t i = 0; i < count; ++i) {
    std::uint64_t bits;
    std::memcpy(&bits, x + i, sizeof bits);
    non_finite |= (bits & exponent) == exponent;
  }
  return non_finite == 0;
}

void pressure_kernel(const SimdWavinessZone& z, Form form, const double* x, double* p, std::size_t count) {
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

// p at one point x, |x| <= b1 (the caller reduces it to the period), by the arithmetic of
// pressure_kernel: one call's latency, not a block's.
double point_pressure_kernel(const SimdWavinessZone& z, Form form, double x) {
  const PointAtoms atoms = atoms_at<true>(z.b1, z.a, z.sin_a, z.Ca, x);
  if (!(atoms.r < z.a)) return 0;
  return form == Form::exact
             ? generated::waviness_pressure_exact(z.E, z.H1, z.b1, z.m, z.Ca, z.Sa, atoms.Cx, atoms.Sx, atoms.D)
             : generated::waviness_pressure_paper(z.E, z.H1, z.b1, z.m, z.Ca, z.Sa, atoms.Cx, atoms.Sx, atoms.D);
}

#if defined(__AVX2__)
void add_roughness_kernel(const RoughnessZone& z, const double* x, double* p, std::size_t count) {
  pressure_blocks<false>(
      z.b1, z.a, z.Ca, z.Sa, x, count, [&](const Atoms& atoms, double* value) { roughness_block(z, atoms, value); },
      [p](std::size_t i, double value) { p[i] += value; });
}
#endif

}  // namespace
}  // namespace wavecontact::detail
