// The cosine sum y(x^) = sum_{k=0}^{K} A_k cos(k x^) in contact: the Legendre-Dirichlet form
// of every harmonic (derive/profile/harmonic_part.hpp), summed so that double precision is enough
// for any K. The evaluators of a user profile with a harmonic part call these with the
// coefficients A_k that wavecontact-derive emitted (profile_<name>.hpp); work holds K values.
//
//   p(x)  = (pi/b1) (E*/2) sqrt(D (1 + Cx)) sum_{j<K} B_j V_j(Cx),  B_j = sum_{k>j} k A_k P_{k-1-j}(Ca),
//           summed in O(K) (below),
//   P     = (pi/2) E* sum_k k A_k [P_{k-1}(Ca) - P_k(Ca)],
//   dP/da = (pi/b1) sin(a^) (pi/2) E* sum_k k A_k [P'_k(Ca) - P'_{k-1}(Ca)],
//   Y(Cx) = sum_k A_k T_k(Cx),  dY/dCx = sum_k k A_k U_{k-1}(Cx),
//   full contact: p_fc(x) = (pi/b1)(E*/2) sum_k k A_k T_k(Cx),
// P_k Legendre's polynomials (three-term recurrence, |P_k| <= 1), V_j, T_k, U_k Chebyshev's
// of the third, first and second kinds, summed by Clenshaw's recurrence in Reinsch's form
// (from the atom Sx = 1 - Cx for Cx >= 0, from 1 + Cx below), which does not amplify
// rounding near Cx = +-1. O(K) operations each.
#pragma once

#include <cmath>

namespace wavecontact {

namespace detail {

// P_0..P_{count-1}(Ca) into P.
template <typename Scalar>
void legendre_values(const Scalar& Ca, int count, Scalar* P) {
  if (count > 0) P[0] = Scalar(1);
  if (count > 1) P[1] = Ca;
  for (int k = 1; k + 1 < count; ++k) {
    P[k + 1] = (Scalar(2 * k + 1) * Ca * P[k] - Scalar(k) * P[k - 1]) / Scalar(k + 1);
  }
}

// Clenshaw's recurrence b_j = c_j + 2x b_{j+1} - b_{j+2} for sum_{j<count} c_j F_j(x),
// c_j = coefficient(j), in Reinsch's form: around x = 1 (from Sx = 1 - x) for x >= 0 it
// carries r_j = b_j - b_{j+1}, around x = -1 below r_j = b_j + b_{j+1}. Then
// sum c_j V_j = r_0 (x >= 0) or r_0 - 2 b_1; sum c_j T_j = r_0 + (1 - x) b_1 or
// r_0 - (1 + x) b_1; sum c_j U_j = b_0. visit(j, b_j - b_{j+1}) is called at every step.
template <typename Scalar>
struct Clenshaw {
  Scalar b0 = 0, b1 = 0, r0 = 0;
  bool upper = true;  // x >= 0
};

template <typename Scalar, typename Coefficient, typename Visit>
Clenshaw<Scalar> clenshaw_reinsch(const Coefficient& coefficient, int count, const Scalar& x, const Scalar& Sx,
                                  const Visit& visit) {
  Clenshaw<Scalar> c;
  c.upper = x >= 0;
  const Scalar twice_gap = c.upper ? Scalar(-2 * Sx) : Scalar(2 * (Scalar(1) + x));
  const Scalar sign = c.upper ? Scalar(1) : Scalar(-1);
  Scalar b = 0, r = 0;  // b_{j+1}, r_{j+1}
  for (int j = count - 1; j >= 0; --j) {
    r = coefficient(j) + twice_gap * b + sign * r;
    visit(j, c.upper ? r : Scalar(r - 2 * b));
    c.b1 = b;
    b = r + sign * b;
  }
  c.b0 = b;
  c.r0 = r;
  return c;
}

template <typename Scalar, typename Coefficient>
Clenshaw<Scalar> clenshaw_reinsch(const Coefficient& coefficient, int count, const Scalar& x, const Scalar& Sx) {
  return clenshaw_reinsch(coefficient, count, x, Sx, [](int, const Scalar&) {});
}

}  // namespace detail

// p(x) in physical units for |x| < a, from the angle atoms of angles.hpp. With
// V_j = U_j - U_{j-1}, summation by parts turns the double sum into one pass:
//   sum_j B_j V_j(Cx) = sum_{m<K} P_m(Ca) (b_m - b_{m+1}),  b_m = sum_{i>=0} c_{m+1+i} U_i(Cx),
// c_k = k A_k, the b_m by Clenshaw's recurrence (Reinsch's form): O(K) a point.
template <typename Scalar>
Scalar harmonic_series_pressure(const Scalar* A, int K, Scalar* work, const Scalar& E, const Scalar& b1,
                                const Scalar& Ca, const Scalar& Cx, const Scalar& Sx, const Scalar& D) {
  using std::sqrt;
  Scalar* P = work;
  detail::legendre_values(Ca, K, P);
  Scalar series = 0;  // sum_j B_j V_j(Cx)
  detail::clenshaw_reinsch([&](int m) { return Scalar(m + 1) * A[m + 1]; }, K, Cx, Sx,
                           [&](int m, const Scalar& difference) { series += P[m] * difference; });
  const Scalar pi = Scalar(3.141592653589793238462643383279502884L);
  return pi / b1 * E / 2 * sqrt(D * (Scalar(1) + Cx)) * series;
}

// The load per unit length P (eq. 6); the differences P_{k-1} - P_k by
// D_{k+1} = (k D_k + (2k+1) Sa P_k)/(k+1), D_1 = Sa, free of cancellation near Ca = 1.
template <typename Scalar>
Scalar harmonic_series_load(const Scalar* A, int K, Scalar* work, const Scalar& E, const Scalar& Ca, const Scalar& Sa) {
  Scalar* P = work;
  detail::legendre_values(Ca, K, P);
  Scalar sum = 0, difference = Sa;  // D_k = P_{k-1} - P_k, k = 1
  for (int k = 1; k <= K; ++k) {
    sum += Scalar(k) * A[k] * difference;
    if (k < K) {
      difference = (Scalar(k) * difference + Scalar(2 * k + 1) * Sa * P[k]) / Scalar(k + 1);
    }
  }
  const Scalar pi = Scalar(3.141592653589793238462643383279502884L);
  return pi / 2 * E * sum;
}

// dP/dSa - dP/dCa: dP/da = (pi/b1) sin(a^) times this; P'_k - P'_{k-1} by
// F_{k+1} = (2k+1) P_k - F_k, F_1 = 1.
template <typename Scalar>
Scalar harmonic_series_load_slope_factor(const Scalar* A, int K, Scalar* work, const Scalar& E, const Scalar& Ca) {
  Scalar* P = work;
  detail::legendre_values(Ca, K, P);
  Scalar sum = 0, F = 1;
  for (int k = 1; k <= K; ++k) {
    sum += Scalar(k) * A[k] * F;
    if (k < K) F = Scalar(2 * k + 1) * P[k] - F;
  }
  const Scalar pi = Scalar(3.141592653589793238462643383279502884L);
  return pi / 2 * E * sum;
}

// Full contact: p_fc(x) = (pi/b1)(E*/2) sum_k k A_k T_k(Cx) (derive/formulas/full_contact.hpp).
template <typename Scalar>
Scalar harmonic_series_full_contact_pressure(const Scalar* A, int K, const Scalar& E, const Scalar& b1,
                                             const Scalar& Cx) {
  const Scalar Sx = Scalar(1) - Cx;
  const detail::Clenshaw<Scalar> c = detail::clenshaw_reinsch([&](int k) { return Scalar(k) * A[k]; }, K + 1, Cx, Sx);
  const Scalar pi = Scalar(3.141592653589793238462643383279502884L);
  return pi / b1 * E / 2 * (c.upper ? c.r0 + Sx * c.b1 : c.r0 - (Scalar(1) + Cx) * c.b1);
}

// Y(Cx) = sum_{k<=K} A_k T_k(Cx).
template <typename Scalar>
Scalar harmonic_series_height(const Scalar* A, int K, const Scalar& Cx) {
  const Scalar Sx = Scalar(1) - Cx;
  const detail::Clenshaw<Scalar> c = detail::clenshaw_reinsch([&](int k) { return A[k]; }, K + 1, Cx, Sx);
  return c.upper ? c.r0 + Sx * c.b1 : c.r0 - (Scalar(1) + Cx) * c.b1;
}

// dY/dCx = sum_{k<=K} k A_k U_{k-1}(Cx).
template <typename Scalar>
Scalar harmonic_series_height_slope(const Scalar* A, int K, const Scalar& Cx) {
  return detail::clenshaw_reinsch([&](int j) { return Scalar(j + 1) * A[j + 1]; }, K, Cx, Scalar(1) - Cx).b0;
}

}  // namespace wavecontact
