// The bounded expression input (derive/profile/expression_input.hpp): every limit is accepted at
// its value and refused one past it, naming what and why; decimals are read exactly.
#define BOOST_TEST_MODULE expression_input
#include <boost/test/unit_test.hpp>

#include <string>

#include "core/symbols.hpp"
#include "formulas/user_profile.hpp"
#include "profile/expression_input.hpp"

using namespace wavecontact::derive;
using GiNaC::ex;
using GiNaC::numeric;
namespace limits = wavecontact::derive::expression_limits;

namespace {

GiNaC::symtab profile_symbols() {
  GiNaC::symtab table;
  table["x"] = sym::x();
  table["Pi"] = GiNaC::Pi;
  return table;
}

ex parse(const std::string& text) { return parse_bounded_expression(text, profile_symbols()); }

// The message of the refusal of `text` by parsing and the order check, or "accepted".
std::string refusal(const std::string& text) {
  try {
    checked_order(parse(text), sym::x());
  } catch (const InputRefused& e) {
    return e.what();
  }
  return "accepted";
}

void refused_with(const std::string& text, const std::string& part) {
  const std::string message = refusal(text);
  BOOST_TEST(message.find(part) != std::string::npos,
             "input: " << text << "\n  expected a refusal containing: " << part << "\n  got: " << message);
}

std::string repeated(const std::string& text, int times) {
  std::string result;
  for (int i = 0; i < times; ++i) result += text;
  return result;
}

}  // namespace

BOOST_AUTO_TEST_CASE(empty_and_blank_are_refused) {
  refused_with("", "the expression is empty");
  refused_with(" \t ", "the expression is empty");
}

BOOST_AUTO_TEST_CASE(length_and_nesting_are_bounded) {
  std::string at_limit = "cos(x)";
  while (at_limit.size() + 2 <= limits::max_characters) at_limit += "+0";
  BOOST_TEST(at_limit.size() == limits::max_characters);
  BOOST_TEST(refusal(at_limit) == "accepted");
  refused_with(at_limit + "+0", "more than 2000");

  const std::string open = repeated("(", limits::max_nesting), close = repeated(")", limits::max_nesting);
  BOOST_TEST(refusal(repeated("(", limits::max_nesting - 1) + "cos(x)" + repeated(")", limits::max_nesting - 1)) ==
             "accepted");
  refused_with(open + "cos(x)" + close, "parentheses nest deeper than 16");
  refused_with("cos(x))", "unbalanced \")\"");
  refused_with("((cos(x)", "unbalanced \"(\": 2 not closed");
}

BOOST_AUTO_TEST_CASE(characters_and_functions_are_checked) {
  refused_with("cos(x)$", "character '$' at character 7 is not allowed");
  refused_with("cos(x);cos(x)", "character ';'");
  // GiNaC's parser calls cos without an argument for cos() and crashes (found by fuzzing).
  refused_with("cos()*sin(1*x)", "empty parentheses at character 4");
  refused_with("cos( )", "empty parentheses");
  refused_with("cos(x,x)", "character ','");
  refused_with("factorial(100000)*cos(x)", "function factorial at character 1");
  refused_with("zeta(3)*cos(x)", "the functions are cos, sin, sqrt");
  refused_with("2x", "the number 2x at character 1 is malformed");
  refused_with("cos(x)*y", "cannot parse it");  // an undeclared symbol
}

BOOST_AUTO_TEST_CASE(numbers_are_bounded_and_exact) {
  const std::string twenty_digits = "12345678901234567890";
  BOOST_TEST(refusal(twenty_digits + "*cos(x)") == "accepted");
  refused_with(twenty_digits + "1*cos(x)", "more than 20 significant digits");
  BOOST_TEST(refusal("0.000000000000000000000000000001*cos(x)") == "accepted");  // leading zeros
  BOOST_TEST(refusal("1e20*cos(x)") == "accepted");
  refused_with("1e21*cos(x)", "decimal exponent beyond +-20");
  refused_with("1e*cos(x)", "has an empty exponent");
  // Decimals are exact fractions (GiNaC alone would read floating-point numbers).
  BOOST_TEST((parse("0.1*cos(x)") - GiNaC::cos(sym::x()) / 10).is_zero());
  BOOST_TEST((parse("2.5e-3") - numeric(1, 400)).is_zero());
  BOOST_TEST((parse("1.5E2") - 150).is_zero());
  BOOST_TEST(parse_bounded_number("0.1") == numeric(1, 10));
  BOOST_TEST(parse_bounded_number("-3/4") == numeric(-3, 4));
  BOOST_CHECK_THROW(parse_bounded_number("H"), InputRefused);
  BOOST_CHECK_THROW(parse_bounded_number(""), InputRefused);
  BOOST_CHECK_THROW(parse_bounded_number("1/0"), InputRefused);
  // A product of literals past the coefficient bound (256 bits).
  refused_with(repeated(twenty_digits + "*", 13) + "cos(x)", "more than 256 bits");
}

BOOST_AUTO_TEST_CASE(exponents_are_integer_literals_within_the_bound) {
  BOOST_TEST(refusal("cos(x)^256") == "accepted");
  BOOST_TEST(refusal("1/(2+cos(x))^(-256)") == "accepted");
  refused_with("cos(x)^257", "the power ^257 at character 7 is beyond +-256");
  refused_with("cos(x)^1000000000", "is beyond +-256");
  refused_with("cos(x)+cos(x)^-5000000", "the power ^-5000000");
  refused_with("cos(x)^2.5", "must be an integer literal");
  refused_with("cos(x)^(1/2)", "must be an integer literal");
  refused_with("cos(x)^n", "must be an integer literal");
  // Powers of powers multiply their exponents; a number's power is evaluated at once.
  BOOST_TEST(refusal("(cos(x)^2+1)^128") == "accepted");
  refused_with("((2^32)^32)*cos(x)", "of a power gives an exponent beyond +-256");
  refused_with("((cos(x)^8)^8)^8", "of a power gives an exponent beyond +-256");
  refused_with("cos(x)^32^32", "of a power gives an exponent beyond +-256");
}

BOOST_AUTO_TEST_CASE(frequencies_are_integers_within_the_order) {
  BOOST_TEST(refusal("cos(256*x)") == "accepted");
  refused_with("cos(257*x)", "the frequency of cos(257*x) is beyond 256");
  refused_with("cos(x/2)", "is not an integer multiple k x of x");
  refused_with("cos(Pi*x)", "is not an integer multiple k x of x");
  refused_with("cos(2)*cos(x)", "the argument of cos(2) is not an integer multiple");
}

BOOST_AUTO_TEST_CASE(the_order_of_the_fraction_is_bounded) {
  BOOST_TEST(refusal("cos(x)^128*cos(2*x)^64") == "accepted");
  refused_with("cos(x)^200*cos(x)^57", "may reach 257, beyond 256");
  // Sums of fractions: 1/(2+cos x)^16 + 1/(3+cos x)^17 has a denominator of degree 33.
  BOOST_TEST(refusal("1/(2+cos(x))^16+1/(3+cos(x))^16") == "accepted");
  refused_with("1/(2+cos(x))^16+1/(3+cos(x))^17", "the order of its denominator");
  refused_with("1/(2+cos(x))^16+1/(3+cos(x))^17", "may reach 33, beyond 32");
  refused_with("1/((2+cos(x))^17*(3+cos(x))^16)", "may reach 33");
  // A sum over a denominator of degree 32 reaches 288 in the numerator.
  refused_with("cos(x)^256+1/(2+cos(x))^32", "may reach 288, beyond 256");
}

// A profile kept whole (its denominator's leading coefficient in cos x is a parameter) goes
// through partial fractions: its order is bounded at 16 after the split is decided.
BOOST_AUTO_TEST_CASE(profiles_kept_whole_are_bounded_at_their_order) {
  const std::vector<ProfileParameter> m{{"m", numeric(1, 2)}};
  // (Order 16, the bound, takes seconds; the test derives order 8.)
  BOOST_CHECK_NO_THROW(derive_profile({"p", "cos(x)^8/(m*cos(x)+1)", m}));
  try {
    derive_profile({"p", "cos(x)^17/(m*cos(x)+1)", m});
    BOOST_FAIL("order 17 kept whole accepted");
  } catch (const InputRefused& e) {
    BOOST_TEST(std::string(e.what()).find("its order in cos x is 17, beyond 16 for a profile "
                                          "whose denominator's leading coefficient") != std::string::npos,
               e.what());
  }
  // With a numeric leading coefficient, the cosine sum is split off: order 256 is accepted.
  BOOST_CHECK_NO_THROW(derive_profile({"p", "cos(x)^256/(2*cos(x)+3)", {}}));
}

BOOST_AUTO_TEST_CASE(profiles_name_the_input_and_bound_the_parameters) {
  std::vector<ProfileParameter> nine;
  for (int i = 0; i < 9; ++i) nine.push_back({"H" + std::to_string(i), numeric(1, 2)});
  try {
    derive_profile({"p", "H0*cos(x)", nine});
    BOOST_FAIL("nine parameters accepted");
  } catch (const InputRefused& e) {
    BOOST_TEST(std::string(e.what()) == "profile p = \"H0*cos(x)\": 9 parameters, more than 8");
  }
  BOOST_CHECK_THROW(parse_parameter("H=1e99"), InputRefused);
  BOOST_CHECK_THROW(parse_parameter("H=factorial(9999999)"), InputRefused);
}
