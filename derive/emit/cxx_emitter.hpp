// The C++ emitter. GiNaC has no common-subexpression elimination (print_csrc repeats
// subexpressions and prints sqrt as pow(x, 0.5)), so expressions are lowered to a
// hash-consed graph: identical subexpressions become one node, nodes used twice
// become `const Scalar _tmpN` temporaries. Integer powers become products (by
// squaring), q^(k/2) becomes q^((k-1)/2) * sqrt(q), polynomials of degree >= 2 are
// evaluated in Horner form, the terms of a sum over one denominator share its division, and
// rational constants become exact double literals.
#pragma once

#include <string>
#include <vector>

#include <ginac/ginac.h>

namespace wavecontact::derive {

struct OpCounts {
  int additions = 0, multiplications = 0, divisions = 0, square_roots = 0, negations = 0;
  int calls = 0;  // of the atoms: quadratic_moment, two_factor_moment (sub_interval.hpp), conjugate_logarithm
  int temporaries = 0;
  int total() const { return additions + multiplications + divisions + square_roots + negations + calls; }
};

// An intermediate result: `const Scalar target = value;`, where value may use the
// arguments and earlier targets (all symbols).
struct Statement {
  GiNaC::ex target;
  GiNaC::ex value;
};

// One emitted evaluator: `template <typename Scalar> Scalar name(const Scalar& arg...)`,
// a straight-line program of statements followed by the returned value. With outputs
// instead, `void name(const Scalar& arg..., Scalar* out)` stores out[k] = outputs[k], and
// `inline constexpr int name_outputs` gives their number. After the arguments, each array
// `const Scalar* array` whose elements array_element(array, k) the expressions may use.
struct EmittedFunction {
  std::string name;
  std::string doc;                   // comment lines above the function
  std::vector<GiNaC::ex> arguments;  // symbols; parameter names are their names
  GiNaC::ex value;
  std::vector<Statement> statements = {};
  std::vector<GiNaC::ex> outputs = {};  // if not empty, value is unused
  std::vector<std::string> arrays = {};
};

// The symbol that denotes array[k] of an EmittedFunction's arrays.
GiNaC::ex array_element(const std::string& array, int k);

// The C++ source of one function, with its op counts in a comment.
std::string emit_function(const EmittedFunction& function, OpCounts* counts = nullptr);

// A literal that denotes exactly the double nearest to the rational q.
std::string double_literal(const GiNaC::numeric& q);

}  // namespace wavecontact::derive
