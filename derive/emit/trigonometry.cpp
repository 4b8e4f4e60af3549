#include "trigonometry.hpp"

#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "emit/cxx_emitter.hpp"
#include "emit/shared_pieces.hpp"
#include "formulas/minimax.hpp"

namespace wavecontact::derive {

using GiNaC::numeric;

namespace {

constexpr int working_digits = 50;
constexpr double epsilon = 2.220446049250313e-16;  // double's, 2^-52

struct WorkingPrecision {
  WorkingPrecision() : saved(GiNaC::Digits) { GiNaC::Digits = working_digits; }
  ~WorkingPrecision() { GiNaC::Digits = saved; }
  long saved;
};

std::string scientific(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1e", value);
  return text;
}

std::string fixed(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", value);
  return text;
}

// t (hi + (lo + u (c_1 + u (c_2 + ...)))), u = t^2: with fused multiply-adds (t hi exact in the
// last), or, for a CPU without them, with every product and sum rounded apart (sine.name +
// "_unfused": t hi then carries a rounding of its own).
std::string evaluator(const BoundedSine& sine, bool fused) {
  const std::vector<numeric>& c = sine.coefficients;
  const auto multiply_add = [fused](const std::string& a, const std::string& b, const std::string& c) {
    return fused ? "fma(" + a + ", " + b + ", " + c + ")" : "(" + a + " * " + b + " + " + c + ")";
  };
  std::string tail = "Scalar(" + double_literal(c.back()) + ")";
  for (std::size_t k = c.size() - 1; k-- > 1;) tail = multiply_add("u", tail, "Scalar(" + double_literal(c[k]) + ")");
  const std::string hi = "Scalar(" + double_literal(c[0]) + ")";
  const std::string low_and_tail = multiply_add("u", "tail", "Scalar(" + double_literal(sine.lead_low) + ")");
  std::ostringstream os;
  const int products = static_cast<int>(c.size());  // c.size() - 2 in the tail, lo's, hi's
  os << "// sin(pi t) for |t| <= " << sine.bound << ": degree " << c.size() - 1
     << " in u = t^2, relative error of the polynomial\n// with these coefficients "
     << scientific(sine.relative_error.to_double()) << " (" << fixed(sine.relative_error.to_double() / epsilon)
     << " eps); t outside the bound gives a finite, meaningless value.\n";
  if (fused) {
    os << "// Total ops: " << products + 2 << " (" << products << " fma, 2 mul)\n";
  } else {
    os << "// The same with every product and sum rounded apart, for a CPU without fused multiply-adds.\n"
       << "// Total ops: " << 2 * products + 2 << " (" << products << " add, " << products + 2 << " mul)\n";
  }
  os << "template <typename Scalar>\ninline Scalar " << sine.name << (fused ? "" : "_unfused")
     << "(const Scalar& t) {\n"
     << (fused ? "  using std::fma;\n" : "") << "  const Scalar u = t * t;\n"
     << "  const Scalar tail = " << tail << ";\n"
     << "  return " << (fused ? "fma(t, " + hi + ", t * " + low_and_tail + ")" : "t * " + hi + " + t * " + low_and_tail)
     << ";\n}\n";
  return os.str();
}

}  // namespace

numeric bounded_sine_tolerance() { return numeric(1, 1L << 55); }

BoundedSine bounded_sine(const std::string& name, const numeric& bound) {
  const WorkingPrecision precision;
  numeric pi = GiNaC::ex_to<numeric>(GiNaC::Pi.evalf());
  // sin(pi t)/t as a function of u = t^2.
  const Function sine_over_t = [&](const numeric& u) {
    if (u.is_zero()) return pi;
    const numeric root = GiNaC::sqrt(u);
    return GiNaC::sin(pi * root) / root;
  };
  const numeric top = bound * bound;
  for (int degree = 3; degree <= 16; ++degree) {
    const std::vector<numeric> exact = remez(sine_over_t, 0, top, degree);
    BoundedSine sine{name, bound, {}, 0, 0};
    for (const numeric& c : exact) sine.coefficients.push_back(nearest_double(c));
    sine.lead_low = nearest_double(exact[0] - sine.coefficients[0]);
    std::vector<numeric> evaluated = sine.coefficients;
    evaluated[0] += sine.lead_low;
    sine.relative_error = max_relative_error(sine_over_t, evaluated, 0, top);
    if (sine.relative_error <= bounded_sine_tolerance()) return sine;
  }
  throw std::runtime_error("bounded_sine: no degree up to 16 reaches the tolerance for " + name);
}

BoundedSine kernel_sine() { return bounded_sine("sinpi_quarter", numeric(1, 4)); }

std::string trigonometry_header(const BoundedSine& quarter, const std::string& command) {
  std::ostringstream os;
  os << banner("//", command)
     << "//\n// sin(pi t) at the bounded arguments of the array kernels' angle atoms "
        "(runtime/src/kernels/pressure_simd_kernels.hpp,\n// which take every atom from it by exact "
        "identities), without range reduction: a minimax\n// polynomial t p(t^2) in relative "
        "error for |t| <= 1/4 (Remez exchange at "
     << working_digits
     << " digits, derive/formulas/minimax.cpp),\n// the coefficients rounded to "
        "doubles, p's constant term as two doubles (hi + lo), and the error\n// measured again "
        "with the rounded values (bound: 2^-55 = eps/8). tests/trigonometry_test.cpp measures\n"
        "// it as evaluated: within 1 ulp, and 2 ulp without fused multiply-adds.\n"
        "#pragma once\n\n#include <cmath>\n\nnamespace wavecontact::generated {\n\n"
     << evaluator(quarter, true) << "\n"
     << evaluator(quarter, false) << "\n}  // namespace wavecontact::generated\n";
  return os.str();
}

}  // namespace wavecontact::derive
