// High-precision (CLN, 40 digits) evaluation of derived expressions at double inputs,
// for the accuracy tests: the reference takes every double input as the exact rational
// it represents.
#pragma once

#include <cmath>
#include <string>

#include <ginac/ginac.h>

#include "core/symbols.hpp"
#include "engine/angle_form.hpp"

namespace wavecontact::test {

inline constexpr int reference_digits = 40;

// The exact rational value of a double.
inline GiNaC::numeric exact(double value) {
  int exponent = 0;
  const double mantissa = std::frexp(value, &exponent);
  const auto integer = static_cast<long long>(std::ldexp(mantissa, 53));
  return GiNaC::numeric(integer) * GiNaC::ex_to<GiNaC::numeric>(GiNaC::pow(GiNaC::numeric(2), exponent - 53));
}

// Values for the symbols of the v-form at the physical inputs (x, a, b1 and the rest
// exact): s = tan^2(pi x/(2 b1)), alpha = tan(pi a/(2 b1)), evaluated at 40 digits.
struct PhysicalPoint {
  double E, H1, b1, m, a, x;

  GiNaC::exmap v_variables() const {
    GiNaC::exmap map;
    const GiNaC::ex b = exact(b1);
    map[derive::sym::alpha()] = GiNaC::tan(GiNaC::Pi * exact(a) / (2 * b)).evalf();
    map[derive::sym::s()] = GiNaC::pow(GiNaC::tan(GiNaC::Pi * exact(x) / (2 * b)), 2).evalf();
    map[derive::sym::E()] = exact(E);
    map[derive::sym::H1()] = exact(H1);
    map[derive::sym::b1()] = b;
    map[derive::sym::m()] = exact(m);
    return map;
  }
};

// c * sqrt(r) at a point, as a 40-digit float.
inline GiNaC::numeric evaluate(const derive::RootTerm& term, const GiNaC::exmap& point) {
  const GiNaC::ex value = (term.rational.subs(point) * GiNaC::sqrt(term.radicand.subs(point))).evalf();
  return GiNaC::ex_to<GiNaC::numeric>(value);
}

// |computed - reference| / |reference| in units of double epsilon.
inline double error_in_eps(double computed, const GiNaC::numeric& reference) {
  const GiNaC::numeric difference = GiNaC::abs(exact(computed) - reference);
  const double relative = (difference / GiNaC::abs(reference)).to_double();
  return relative / 2.220446049250313e-16;
}

// Sets GiNaC's working precision for the lifetime of the object.
struct Precision {
  explicit Precision(int digits) : saved(GiNaC::Digits) { GiNaC::Digits = digits; }
  ~Precision() { GiNaC::Digits = saved; }
  long saved;
};

}  // namespace wavecontact::test
