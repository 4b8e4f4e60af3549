// The logarithmic atom of full contact for a profile built with abs() (derive/formulas/full_contact.hpp):
//   Psi(a, b, a - b) = ((a - b)/(a + b)) sqrt(b/a) log|(sqrt a + sqrt b)/(sqrt a - sqrt b)|,
// a, b >= 0, a + b > 0, with a - b passed as computed without cancellation by the caller. With
// s^2 = min(a, b)/max(a, b) it is ((a - b)/(a + b)) 2 s atanh(s) for a >= b and
// ((a - b)/(a + b)) 2 atanh(s)/s for a < b: bounded, 0 at a = b (where atanh(s) grows like a
// logarithm) and at b = 0, -2 at a = 0. Where s > 1/2, atanh(s) = log1p(s) - log(|a - b|/max)/2
// (1 - s^2 = |a - b|/max): all its digits as s -> 1.
#pragma once

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace wavecontact {

template <typename Scalar>
Scalar conjugate_logarithm(const Scalar& a, const Scalar& b, const Scalar& a_minus_b) {
  using std::abs;
  using std::atanh;
  using std::log;
  using std::log1p;
  using std::sqrt;
  if (!(a >= 0 && b >= 0 && a + b > 0)) {
    std::ostringstream os;
    os.precision(17);
    os << "wavecontact::conjugate_logarithm: a = " << a << ", b = " << b
       << " are invalid (valid: a >= 0, b >= 0, a + b > 0)";
    throw std::domain_error(os.str());
  }
  if (a_minus_b == 0 || b == 0) return Scalar(0);
  if (a == 0) return Scalar(-2);
  const bool a_larger = a >= b;
  const Scalar larger = a_larger ? a : b;
  const Scalar s = sqrt((a_larger ? b : a) / larger);
  const Scalar ratio = a_minus_b / (a + b);
  if (s == 0) return a_larger ? Scalar(0) : 2 * ratio;  // b/a or a/b below the smallest double
  const Scalar atanh_s = s > Scalar(0.5) ? log1p(s) - log(abs(a_minus_b) / larger) / 2 : atanh(s);
  return ratio * (a_larger ? 2 * s * atanh_s : 2 * atanh_s / s);
}

}  // namespace wavecontact
