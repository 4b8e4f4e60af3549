// The bounded reading of what a user types: the --profile expression and --param samples.
//
// Every input is checked before GiNaC sees it and again on the parsed tree, so that a
// derivation's time and memory are bounded by these limits whatever is typed. A refused
// input throws InputRefused, whose message names what and why in one line; the tool exits
// 2 and writes nothing.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

#include <ginac/ginac.h>

namespace wavecontact::derive {

struct InputRefused : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

namespace expression_limits {
inline constexpr std::size_t max_characters = 2000;  // of the expression
inline constexpr int max_nesting = 16;               // of parentheses
inline constexpr int max_digits = 20;                // significant digits of a number literal
inline constexpr int max_decimal_exponent = 20;      // |e| of 1.5e-3
inline constexpr int max_power = 256;                // |n| of ^n, an integer literal
// The profile's order: upper bounds on the degrees in (cos x, sin x) of the numerator and
// of the denominator once y is one fraction (cos(k x) counts k). A profile's cosine sum
// costs little whatever its order (derive/profile/harmonic_part.hpp); the rest goes through the
// engine's partial fractions, whose cost grows steeply with the order of the denominator
// (docs/performance.md, derivation times).
inline constexpr long max_order = 256;             // of the numerator; |k| of cos(k x)
inline constexpr long max_denominator_order = 32;  // of the denominator
// Of a profile kept whole (its denominator's leading coefficient in cos x depends on a
// parameter, so it has no separate cosine sum): numerator and denominator. Its pole at
// v^2 = -1 then carries the parameters, and order 16 takes seconds (docs/performance.md).
inline constexpr long max_whole_order = 16;
inline constexpr std::size_t max_parameters = 8;
inline constexpr long max_number_bits = 256;  // numerator and denominator of a coefficient
}  // namespace expression_limits

// Parses a profile y(x) over the symbols in `table` (x and the parameters), with the
// functions cos, sin and abs only (abs() as branches.hpp allows it). Refuses an empty or blank text, a text beyond the
// limits, a character other than letters, digits, _, blanks and + - * / ^ ( ) . (every function takes one argument),
// empty parentheses, an exponent that is not an integer literal within max_power, or a parse error. Decimal literals
// are read exactly (0.1 is 1/10).
GiNaC::ex parse_bounded_expression(const std::string& text, const GiNaC::symtab& table);

// Whether e is a call of abs().
inline bool is_abs(const GiNaC::ex& e) {
  return GiNaC::is_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_name() == "abs";
}

// A --param sample value: a real number (decimal, p/q, or an arithmetic of literals).
GiNaC::numeric parse_bounded_number(const std::string& text);

// Upper bounds on the degrees in (cos x, sin x) of y's numerator and denominator once y is
// one fraction (cos(k x) counting k), checked against max_order and max_denominator_order,
// with every trigonometric argument (an integer multiple k x, |k| <= max_order) and every
// coefficient (max_number_bits). Refuses what is beyond the limits, naming the subexpression.
struct ProfileOrder {
  long numerator = 0, denominator = 0;
};
ProfileOrder checked_order(const GiNaC::ex& y, const GiNaC::ex& x);

}  // namespace wavecontact::derive
