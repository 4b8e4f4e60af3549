// The moments I_{j,l}(z) = Int_0^1 w^(2j) / (1 + z w^2)^l dw, z > -1, j >= 0, l >= 1: the
// transcendental atoms of the engine's integrals over part of a contact zone (derive/
// sub_interval.hpp), where a profile changes branch (|cos x| at x = b1/2). Such an
// integral, Int_0^T0 N(T^2)/(a + b T^2)^l dT with T = tan(phi), is a sum over the monomials
// of N of T0^(2j+1) a^-l I_{j,l}(b T0^2/a). In double precision for any z > -1:
//   -3/4 <= z <= 0: the power series sum_k C(l+k-1, k) (-z)^k/(2j+2k+1), of positive terms;
//   0 < z <= 7:     with y = z/(1+z) <= 7/8, 1 + z w^2 = (1+z)(1 - y(1 - w^2)), the series
//                   (1+z)^-l sum_k C(l+k-1, k) y^k B_{j,k}, B_{j,k} = Int_0^1 w^(2j)(1-w^2)^k dw
//                   = B_{j,k-1} 2k/(2j+2k+1), also of positive terms;
//   otherwise:      I_{0,1} = atan(sqrt z)/sqrt z, or atanh(sqrt(-z))/sqrt(-z) by log1p,
//                   I_{0,l+1} = 1/(2l (1+z)^l) + (2l-1)/(2l) I_{0,l}, I_{j,0} = 1/(2j+1),
//                   I_{j+1,l} = (I_{j,l-1} - I_{j,l})/z, which cancels little there.
// The series converge like (3/4)^k and (7/8)^k (a few hundred terms at most); tests/
// quadratic_moment_test.cpp measures j <= 3, l <= 4 against quadrature.
// dI_{j,l}/dz = -l I_{j+1,l+1}. Near z = -1 the moments grow like (1 + z)^(1/2 - l): the
// four-argument form takes 1 + z as computed without cancellation by the caller (a closed
// form's own expression for it), which the three-argument form computes as 1 + z.
#pragma once

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace wavecontact {

namespace detail {

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
    return positive_series(j, l, Scalar(-z), [j](int k) { return Scalar(2 * j + 2 * k - 1) / Scalar(2 * j + 2 * k + 1); });
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
  return (quadratic_moment_closed(j - 1, l - 1, z, one_plus_z) -
          quadratic_moment_closed(j - 1, l, z, one_plus_z)) / z;
}

}  // namespace detail

// I_{j,l}(z) for z > -1, j >= 0, l >= 1, with one_plus_z = 1 + z. Throws std::domain_error
// naming the argument otherwise.
template <typename Scalar>
Scalar quadratic_moment(int j, int l, const Scalar& z, const Scalar& one_plus_z) {
  // z itself may round to -1 where 1 + z, given apart, does not vanish (m ~ 1e17 and beyond).
  if (!(z >= -1) || !(one_plus_z > 0) || j < 0 || l < 1 || !std::isfinite(static_cast<double>(z))) {
    std::ostringstream os;
    os.precision(17);
    os << "wavecontact::quadratic_moment: j = " << j << ", l = " << l << ", z = "
       << static_cast<double>(z) << ", 1 + z = " << static_cast<double>(one_plus_z)
       << " are invalid (valid: j >= 0, l >= 1, z >= -1 finite, 1 + z > 0)";
    throw std::domain_error(os.str());
  }
  return z >= Scalar(-0.75) && z <= Scalar(7) ? detail::quadratic_moment_series(j, l, z, one_plus_z)
                                               : detail::quadratic_moment_closed(j, l, z, one_plus_z);
}

template <typename Scalar>
Scalar quadratic_moment(int j, int l, const Scalar& z) {
  return quadratic_moment(j, l, z, Scalar(1 + z));
}

}  // namespace wavecontact
