// The moments I_{j,l}(z) = Int_0^1 w^(2j) / (1 + z w^2)^l dw, z > -1, j >= 0, l >= 1: the
// transcendental atoms of the engine's integrals over part of a contact zone (derive/
// sub_interval.hpp), where a profile changes branch (|cos x| at x = b1/2). Such an
// integral, Int_0^T0 N(T^2)/(a + b T^2)^l dT with T = tan(phi), is a sum over the monomials
// of N of T0^(2j+1) a^-l I_{j,l}(b T0^2/a). In double precision for any z > -1:
//   -3/4 <= z <= 0: the power series sum_k C(l+k-1, k) (-z)^k/(2j+2k+1), of positive terms;
//   0 < z <= 7:     with y = z/(1+z) <= 7/8, 1 + z w^2 = (1+z)(1 - y(1 - w^2)), the series
//                   (1+z)^-l sum_k C(l+k-1, k) y^k B_{j,k}, B_{j,k} = Int_0^1 w^(2j)(1-w^2)^k dw
//                   = B_{j,k-1} 2k/(2j+2k+1), also of positive terms;
//   otherwise, and for j = 0 at any z != 0:
//                   I_{0,1} = atan(sqrt z)/sqrt z, or atanh(sqrt(-z))/sqrt(-z) by log1p,
//                   I_{0,l+1} = 1/(2l (1+z)^l) + (2l-1)/(2l) I_{0,l}, I_{j,0} = 1/(2j+1),
//                   I_{j+1,l} = (I_{j,l-1} - I_{j,l})/z, which cancels little there.
// The series converge like (3/4)^k and (7/8)^k (a few hundred terms at most); tests/
// quadratic_moment_test.cpp measures j <= 3, l <= 4 against quadrature.
// dI_{j,l}/dz = -l I_{j+1,l+1}. Near z = -1 the moments grow like (1 + z)^(1/2 - l): the
// four-argument form takes 1 + z as computed without cancellation by the caller (a closed
// form's own expression for it), which the three-argument form computes as 1 + z.
#pragma once

#include <cmath>
#include <initializer_list>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace wavecontact {

namespace detail {

// z >= -1 up to its rounding: where 1 + z is given apart (and > 0), z itself, formed from the
// same atoms, may round a few ulps below -1.
template <typename Scalar>
bool at_least_minus_one(const Scalar& z) {
  return z >= Scalar(-1) - Scalar(8) * Scalar(std::numeric_limits<double>::epsilon());
}

// Throws std::domain_error "wavecontact::<function>: j = .., l = .., <name> = <value>, ... are
// invalid (valid: <valid>)".
[[noreturn]] inline void invalid_arguments(const char* function, int j, int l,
                                           std::initializer_list<std::pair<const char*, double>> arguments,
                                           const char* valid) {
  std::ostringstream os;
  os.precision(17);
  os << "wavecontact::" << function << ": j = " << j << ", l = " << l;
  for (const auto& [name, value] : arguments) os << ", " << name << " = " << value;
  os << " are invalid (valid: " << valid << ")";
  throw std::domain_error(os.str());
}

// sum_k C(l+k-1, k) x^k c_k with c_0 = 1/(2j+1) and c_k = c_{k-1} ratio(k), to the last bit:
// the number of terms from a forward pass, then the nested form
// c_0 (1 + q_1 (1 + q_2 (1 + ...))), q_k = x (l+k-1)/k ratio(k), from the last term back, whose
// rounding does not accumulate along the terms as the forward products' does.
template <typename Scalar, typename Ratio>
Scalar positive_series(int j, int l, const Scalar& x, const Ratio& ratio) {
  const auto q = [&](int k) { return x * Scalar(l + k - 1) / Scalar(k) * ratio(k); };
  Scalar sum = 1, term = 1;
  int terms = 1;
  while (terms < 4000 && term > sum * Scalar(1e-19)) {
    term *= q(terms++);
    sum += term;
  }
  Scalar nested = 1;
  for (int k = terms - 1; k >= 1; --k) nested = 1 + q(k) * nested;
  return nested / Scalar(2 * j + 1);
}

template <typename Scalar>
Scalar quadratic_moment_series(int j, int l, const Scalar& z, const Scalar& one_plus_z) {
  if (z <= 0) {  // c_k = 1/(2j+2k+1)
    return positive_series(j, l, Scalar(-z),
                           [j](int k) { return Scalar(2 * j + 2 * k - 1) / Scalar(2 * j + 2 * k + 1); });
  }
  const Scalar y = z / one_plus_z;  // c_k = B_{j,k}
  return positive_series(j, l, y, [j](int k) { return Scalar(2 * k) / Scalar(2 * j + 2 * k + 1); }) /
         std::pow(one_plus_z, l);
}

// I_{0,1}(z), any z > -1.
template <typename Scalar>
Scalar atan_ratio(const Scalar& z, const Scalar& one_plus_z) {
  using std::atan;
  using std::log1p;
  using std::sqrt;
  if (z > 0) {
    const Scalar root = sqrt(z);
    return atan(root) / root;
  }
  const Scalar root = sqrt(-z);
  // atanh(y) = log1p(2y/(1 - y))/2 with 1 - y = (1 + z)/(1 + y), free of cancellation.
  return log1p(2 * root * (1 + root) / one_plus_z) / (2 * root);
}

template <typename Scalar>
Scalar quadratic_moment_closed(int j, int l, const Scalar& z, const Scalar& one_plus_z) {
  if (l == 0) return Scalar(1) / Scalar(2 * j + 1);
  if (j == 0) {
    Scalar moment = atan_ratio(z, one_plus_z), power = 1;  // I_{0,1}, (1+z)^(l'-1)
    for (int k = 1; k < l; ++k) {
      power *= one_plus_z;
      moment = Scalar(1) / (Scalar(2 * k) * power) + Scalar(2 * k - 1) / Scalar(2 * k) * moment;
    }
    return moment;
  }
  return (quadratic_moment_closed(j - 1, l - 1, z, one_plus_z) - quadratic_moment_closed(j - 1, l, z, one_plus_z)) / z;
}

}  // namespace detail

// I_{j,l}(z) for z > -1, j >= 0, l >= 1, with one_plus_z = 1 + z. Throws std::domain_error
// naming the argument otherwise.
template <typename Scalar>
Scalar quadratic_moment(int j, int l, const Scalar& z, const Scalar& one_plus_z) {
  // z itself may round to -1 where 1 + z, given apart, does not vanish (m ~ 1e17 and beyond).
  if (!detail::at_least_minus_one(z) || !(one_plus_z > 0) || j < 0 || l < 1 || !std::isfinite(static_cast<double>(z))) {
    detail::invalid_arguments("quadratic_moment", j, l,
                              {{"z", static_cast<double>(z)}, {"1 + z", static_cast<double>(one_plus_z)}},
                              "j >= 0, l >= 1, z >= -1 (up to 8 eps) finite, 1 + z > 0");
  }
  // I_{0,l} by its closed form wherever it is defined (z != 0): atan or atanh, then a recurrence of
  // positive terms; for j > 0 the recurrence in j cancels where |z| is small.
  const bool closed = j == 0 ? z != 0 : !(z >= Scalar(-0.75) && z <= Scalar(7));
  return closed ? detail::quadratic_moment_closed(j, l, z, one_plus_z)
                : detail::quadratic_moment_series(j, l, z, one_plus_z);
}

template <typename Scalar>
Scalar quadratic_moment(int j, int l, const Scalar& z) {
  return quadratic_moment(j, l, z, Scalar(1 + z));
}

namespace detail {

// B_j = Int_0^1 (1 - w^2)^j dw = prod_{i<=j} 2i/(2i+1).
template <typename Scalar>
Scalar edge_weight(int j) {
  Scalar b = 1;
  for (int i = 1; i <= j; ++i) b *= Scalar(2 * i) / Scalar(2 * i + 1);
  return b;
}

template <typename Scalar>
Scalar edge_moment_recurrence(int j, int l, const Scalar& z, const Scalar& one_plus_z) {
  if (l == 0) return edge_weight<Scalar>(j);
  if (j == 0) return quadratic_moment_closed(0, l, z, one_plus_z);
  return (edge_moment_recurrence(j - 1, l - 1, z, one_plus_z) -
          one_plus_z * edge_moment_recurrence(j - 1, l, z, one_plus_z)) /
         -z;
}

}  // namespace detail

// I'_{j,l}(z) = Int_0^1 (1 - w^2)^j / (1 + z w^2)^l dw for z > -1, j >= 0, l >= 0: the moments
// in powers of 1 - w^2 instead of w^2. Where z -> -1 (a pole factor's root just beyond the
// sub-interval's end w = 1) every I_{j,l} tends to the same (1 + z)^(1/2-l) and a sum of them
// cancels; the I'_{j,l}, of orders (1 + z)^(1/2+j-l), do not (derive/engine/sub_interval.hpp chooses
// the basis by the sign of z). In double precision:
//   -3/4 <= z <= 0: sum_k C(l+k-1, k) (-z)^k Int w^2k (1 - w^2)^j dw, positive terms;
//   0 < z <= 7:     (1+z)^-l sum_k C(l+k-1, k) (z/(1+z))^k B_{j+k}, positive terms;
//   otherwise:      I'_{0,l} = I_{0,l}, I'_{j,0} = B_j and, from 1 - w^2 = (1 + z w^2) - (1+z) w^2,
//                   I'_{j,l} = (I'_{j-1,l-1} - (1+z) I'_{j-1,l})/(-z), which cancels by at most
//                   a factor (l-1)/j as z -> -1.
// Throws std::domain_error naming the argument otherwise.
template <typename Scalar>
Scalar edge_moment(int j, int l, const Scalar& z, const Scalar& one_plus_z) {
  if (!detail::at_least_minus_one(z) || !(one_plus_z > 0) || j < 0 || l < 0 || !std::isfinite(static_cast<double>(z))) {
    detail::invalid_arguments("edge_moment", j, l,
                              {{"z", static_cast<double>(z)}, {"1 + z", static_cast<double>(one_plus_z)}},
                              "j >= 0, l >= 0, z >= -1 (up to 8 eps) finite, 1 + z > 0");
  }
  using std::pow;
  if (l == 0) return detail::edge_weight<Scalar>(j);
  if (z >= Scalar(-0.75) && z <= 0) {
    return detail::edge_weight<Scalar>(j) * detail::positive_series(0, l, Scalar(-z), [j](int k) {
             return Scalar(2 * k - 1) / Scalar(2 * k + 2 * j + 1);
           });
  }
  if (z > 0 && z <= Scalar(7)) {
    return detail::edge_weight<Scalar>(j) *
           detail::positive_series(0, l, Scalar(z / one_plus_z),
                                   [j](int k) { return Scalar(2 * (j + k)) / Scalar(2 * (j + k) + 1); }) /
           pow(one_plus_z, l);
  }
  return detail::edge_moment_recurrence(j, l, z, one_plus_z);
}

namespace detail {

// E_N = (1+x)^(L+N) I_{j+N,L+N}(x) for the backward recurrence. Where it contracts by at most
// 0.7 a step (|x|/(1+x) <= 0.7), from E_M ~ (1+x)/(2M) (the integrand concentrates at w = 1 as M
// grows; relative error O(1/M)) at the M > N where the product of the factors a_n falls below
// 1e-18 (Miller's way: the start's error dies out on the way down); elsewhere from the series.
template <typename Scalar>
Scalar diagonal_start(int j, int L, int N, const Scalar& x, const Scalar& one_plus_x) {
  using std::fabs;
  using std::pow;
  if (fabs(x) > Scalar(0.7) * one_plus_x) return quadratic_moment(j + N, L + N, x, one_plus_x) * pow(one_plus_x, L + N);
  const Scalar ratio = x / one_plus_x;
  int M = N;
  for (double product = 1; product > 1e-18 && M < N + 4000; ++M) {
    product *= static_cast<double>(fabs(Scalar(2 * (L + M)) * ratio / Scalar(2 * (j + M) + 1)));
  }
  Scalar E = one_plus_x / Scalar(2 * (j + M) + 1);
  for (int n = M - 1; n >= N; --n) E = (Scalar(2 * (L + n)) * ratio * E + 1) * (Scalar(1) / Scalar(2 * (j + n) + 1));
  return E;
}

// sum_n C(k+n-1, n) rho^n E_n (1+x)^-L, E_n = (1+x)^(L+n) I_{j+n,L+n}(x), |rho| < 1: the
// expansion of Int_0^1 w^2j (1 + x w^2)^-L (1 - rho (1+x) w^2/(1 + x w^2))^-k dw in the ratio
// rho (1+x) w^2/(1 + x w^2), at most |rho| in size. The diagonal E_n follows from integrating
// d/dw [w^(2i+1)/(1 + x w^2)^L'] by parts,
//   (2i+1) I_{i,L'} - 2L'x I_{i+1,L'+1} = (1+x)^-L',
// that is E_n = (1 + 2(L+n) x/(1+x) E_(n+1))/(2(j+n)+1), the factor a_n = 2(L+n)x/((1+x)(2(j+n)+1))
// on E_(n+1): forwards from E_0 while |a_n| >= 1 and backwards from E_N (diagonal_start) where
// it is below, each in the direction in which the recurrence does not amplify (0 < E_n <= 1: its
// integrand is w^(2j+2n) ((1+x)/(1 + x w^2))^(L+n) <= 1). The divisions by the indices are
// reciprocals off the chain of the recurrence, which then runs on multiplications alone.
template <typename Scalar>
Scalar diagonal_series(int j, int L, int k, const Scalar& x, const Scalar& one_plus_x, const Scalar& rho) {
  using std::fabs;
  using std::pow;
  // N terms: C(k+N-1, N) |rho|^N below 1e-18.
  const double r = static_cast<double>(fabs(rho));
  int N = 0;
  for (double bound = 1; bound > 1e-18 && N < 4000; ++N) bound *= r * (k + N) / (N + 1);
  const auto coefficient = [k](int n) { return Scalar(k + n - 1) / Scalar(n); };  // C_n / C_(n-1)
  const auto amplification = [&](int n) {
    return fabs(Scalar(2 * (L + n)) * x / (one_plus_x * Scalar(2 * (j + n) + 1)));
  };
  // Forwards over n < split.
  int split = 0;
  while (split < N && amplification(split) >= 1) ++split;
  Scalar sum = 0, power = 1;  // power = C_n rho^n
  if (split > 0) {
    const Scalar inverse_ratio = one_plus_x / x;
    Scalar E = quadratic_moment(j, L, x, one_plus_x) * pow(one_plus_x, L);
    for (int n = 0; n < split; ++n) {
      sum += power * E;
      E = (Scalar(2 * (j + n) + 1) * E - 1) * (inverse_ratio / Scalar(2 * (L + n)));
      power *= rho * coefficient(n + 1);
    }
  }
  if (split < N) {  // sum_{n >= split} C_n rho^n E_n = C_split rho^split (E_split + rho C_(split+1)/C_split (...))
    Scalar E = diagonal_start(j, L, N, x, one_plus_x), tail = E;
    const Scalar ratio = x / one_plus_x;
    for (int n = N - 1; n >= split; --n) {
      E = (Scalar(2 * (L + n)) * ratio * E + 1) * (Scalar(1) / Scalar(2 * (j + n) + 1));
      tail = E + rho * coefficient(n + 1) * tail;
    }
    sum += power * tail;
  }
  return sum / pow(one_plus_x, L);
}

}  // namespace detail

namespace detail {

// J_{j,l}(y, z): see two_factor_moment.
template <typename Scalar>
Scalar two_factor(int j, int l, const Scalar& y, const Scalar& one_plus_y, const Scalar& z, const Scalar& one_plus_z) {
  using std::fabs;
  using std::pow;
  // Near -1, y and z carry their rounding where 1 + y and 1 + z, given apart, do not.
  const Scalar difference = y < Scalar(-0.5) && z < Scalar(-0.5) ? Scalar(one_plus_y - one_plus_z) : Scalar(y - z);
  const bool about_y = one_plus_y > one_plus_z;
  const Scalar larger = about_y ? one_plus_y : one_plus_z;
  const bool near = l > 0 && fabs(difference) <= Scalar(0.8) * larger;
  if (j < 0 || l < 0 || !(one_plus_y > 0) || !(one_plus_z > 0) || !std::isfinite(static_cast<double>(y)) ||
      !std::isfinite(static_cast<double>(z)) || (near && larger > 5)) {
    invalid_arguments("two_factor_moment", j, l,
                      {{"y", static_cast<double>(y)},
                       {"1 + y", static_cast<double>(one_plus_y)},
                       {"z", static_cast<double>(z)},
                       {"1 + z", static_cast<double>(one_plus_z)}},
                      "j >= 0, l >= 0, y and z finite, 1 + y > 0, 1 + z > 0, and y, z <= 4 where "
                      "|y - z| <= (4/5) max(1 + y, 1 + z)");
  }
  if (l == 0) return quadratic_moment(j, 1, y, one_plus_y);
  if (near) {
    return about_y ? diagonal_series(j, l + 1, l, y, one_plus_y, Scalar(difference / one_plus_y))
                   : diagonal_series(j, l + 1, 1, z, one_plus_z, Scalar(-difference / one_plus_z));
  }
  Scalar moment = quadratic_moment(j, 1, y, one_plus_y);
  for (int i = 1; i <= l; ++i) moment = (y * moment - z * quadratic_moment(j, i, z, one_plus_z)) / difference;
  return moment;
}

// J'_{j,l}(y, z): see two_factor_edge_moment.
template <typename Scalar>
Scalar two_factor_edge(int j, int l, const Scalar& y, const Scalar& one_plus_y, const Scalar& z,
                       const Scalar& one_plus_z) {
  if (l == 0) return edge_moment(j, 1, y, one_plus_y);
  if (j == 0) return two_factor(0, l, y, one_plus_y, z, one_plus_z);
  const bool along_z = one_plus_z <= one_plus_y;
  if ((along_z ? z : y) > Scalar(-0.75)) {  // no factor peaks at w = 1: the J_{i,l} differ by O(1)
    Scalar sum = 0, binomial = 1;
    for (int i = 0; i <= j; ++i) {
      sum += (i % 2 == 0 ? binomial : -binomial) * two_factor(i, l, y, one_plus_y, z, one_plus_z);
      binomial = binomial * Scalar(j - i) / Scalar(i + 1);
    }
    return sum;
  }
  // 1 - w^2 = ((1+x) - (1 + x w^2))/x along the sharper factor x.
  if (along_z) {
    return (two_factor_edge(j - 1, l - 1, y, one_plus_y, z, one_plus_z) -
            one_plus_z * two_factor_edge(j - 1, l, y, one_plus_y, z, one_plus_z)) /
           -z;
  }
  return (edge_moment(j - 1, l, z, one_plus_z) - one_plus_y * two_factor_edge(j - 1, l, y, one_plus_y, z, one_plus_z)) /
         -y;
}

}  // namespace detail

// J_{j,l}(y, z) = Int_0^1 w^(2j) / ((1 + y w^2)(1 + z w^2)^l) dw for y, z > -1, j >= 0, l >= 0
// (J_{j,0}(y, z) = I_{j,1}(y)), with one_plus_y = 1 + y and one_plus_z = 1 + z computed without
// cancellation by the caller: the atom of a sub-interval moment whose integrand has a Cauchy
// factor 1/(t - s) beside a pole factor (the pressure beyond a change of branch,
// derive/engine/sub_interval.hpp). With d = y - z and r = |d|/max(1 + y, 1 + z):
//   r > 4/5:  partial fractions, J_{j,i} = (y J_{j,i-1} - z I_{j,i}(z))/d, whose terms then
//             cancel by a bounded factor (1 + y and 1 + z five times apart or more);
//   r <= 4/5: nearer, where those terms grow like d^-i while J stays finite, the series of
//             diagonal_series about the factor with the larger 1 + (.), ratio r: about z,
//             1/(1 + y w^2) = sum (-d w^2)^n/(1 + z w^2)^(n+1); about y, (1 + z w^2)^-l likewise
//             with binomial coefficients. Its base must be <= 4 (always so when y <= 0, as
//             the Cauchy factor's y of the moments is).
// Throws std::domain_error naming the arguments otherwise.
template <typename Scalar>
Scalar two_factor_moment(int j, int l, const Scalar& y, const Scalar& one_plus_y, const Scalar& z,
                         const Scalar& one_plus_z) {
  return detail::two_factor(j, l, y, one_plus_y, z, one_plus_z);
}

// J'_{j,l}(y, z) = Int_0^1 (1 - w^2)^j / ((1 + y w^2)(1 + z w^2)^l) dw: the same in the edge
// basis of edge_moment, for roots just beyond w = 1 (y or z -> -1), where the J_{j,l} all tend
// to one value. From J'_{0,l} = J_{0,l} and J'_{j,0} = I'_{j,1}(y) by 1 - w^2 = ((1+x) -
// (1 + x w^2))/x along the factor x of the two with the smaller 1 + x (the sharper peak, over
// which the other factor varies little: the two terms then cancel by a bounded factor); where
// that x > -3/4 (no sharp peak), sum_i C(j,i) (-1)^i J_{i,l}. Throws as two_factor_moment does.
template <typename Scalar>
Scalar two_factor_edge_moment(int j, int l, const Scalar& y, const Scalar& one_plus_y, const Scalar& z,
                              const Scalar& one_plus_z) {
  if (j < 0) return detail::two_factor(j, l, y, one_plus_y, z, one_plus_z);  // throws, naming the arguments
  return detail::two_factor_edge(j, l, y, one_plus_y, z, one_plus_z);
}

}  // namespace wavecontact
