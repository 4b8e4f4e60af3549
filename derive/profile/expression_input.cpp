#include "expression_input.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <sstream>
#include <vector>

#include "core/printed.hpp"

namespace wavecontact::derive {

using GiNaC::ex;
using GiNaC::numeric;
namespace limits = expression_limits;

namespace {

[[noreturn]] void refuse(const std::string& why) { throw InputRefused(why); }

std::string position(std::size_t i) { return " at character " + std::to_string(i + 1); }

bool is_blank(char c) { return c == ' ' || c == '\t'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_letter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }

// One pass over the text: checks the characters, the nesting, the number literals and the
// exponents, and rewrites decimal literals as exact fractions for GiNaC (which would read
// them as floating-point numbers). `functions` are the names allowed before "(".
class Lexer {
 public:
  Lexer(const std::string& text, bool identifiers, std::vector<std::string> functions)
      : text_(text), identifiers_(identifiers), functions_(std::move(functions)) {}

  std::string rewrite() {
    std::size_t i = 0;
    while (i < text_.size()) {
      const char c = text_[i];
      if (is_blank(c)) {
        out_ += c;
        ++i;
      } else if (is_letter(c) || c == '_') {
        i = identifier(i);
      } else if (is_digit(c) || (c == '.' && i + 1 < text_.size() && is_digit(text_[i + 1]))) {
        i = number(i);
        last_product_ = 1;
      } else if (c == '(') {
        if (groups_.size() >= static_cast<std::size_t>(limits::max_nesting)) {
          refuse("parentheses nest deeper than " + std::to_string(limits::max_nesting) + position(i));
        }
        std::size_t next = i + 1;
        while (next < text_.size() && is_blank(text_[next])) ++next;
        // GiNaC's parser looks functions up by name alone when there is no argument and
        // calls cos with none (a crash): no empty parentheses.
        if (next < text_.size() && text_[next] == ')') refuse("empty parentheses" + position(i));
        groups_.push_back(1);
        out_ += c;
        ++i;
      } else if (c == ')') {
        if (groups_.empty()) refuse("unbalanced \")\"" + position(i));
        last_product_ = groups_.back();
        groups_.pop_back();
        raise(last_product_);
        out_ += c;
        ++i;
      } else if (c == '^') {
        i = exponent(i);
      } else if (c == '+' || c == '-' || c == '*' || c == '/') {
        last_product_ = 1;
        out_ += c;
        ++i;
      } else {
        std::ostringstream os;
        char code[8];
        std::snprintf(code, sizeof code, "\\x%02x", static_cast<unsigned>(static_cast<unsigned char>(c)));
        os << "character '" << (std::isprint(static_cast<unsigned char>(c)) ? std::string(1, c) : std::string(code))
           << "'" << position(i) << " is not allowed (letters, digits, _, blanks and + - * / ^ ( ) .)";
        refuse(os.str());
      }
    }
    if (!groups_.empty()) refuse("unbalanced \"(\": " + std::to_string(groups_.size()) + " not closed");
    return out_;
  }

 private:
  std::size_t identifier(std::size_t i) {
    const std::size_t start = i;
    while (i < text_.size() && (is_letter(text_[i]) || is_digit(text_[i]) || text_[i] == '_')) ++i;
    const std::string name = text_.substr(start, i - start);
    if (!identifiers_) refuse("\"" + name + "\"" + position(start) + ": a number is expected");
    std::size_t next = i;
    while (next < text_.size() && is_blank(text_[next])) ++next;
    if (next < text_.size() && text_[next] == '(' &&
        std::find(functions_.begin(), functions_.end(), name) == functions_.end()) {
      std::string allowed;
      for (const auto& f : functions_) allowed += (allowed.empty() ? "" : ", ") + f;
      refuse("function " + name + position(start) + " is not rational in cos(k x) and sin(k x); the functions are " +
             allowed);
    }
    out_ += name;
    last_product_ = 1;
    return i;
  }

  // digits [. digits] [(e|E) [+-] digits]; a decimal becomes (mantissa/10^k).
  std::size_t number(std::size_t i) {
    const std::size_t start = i;
    std::string mantissa;
    long fraction_digits = 0;
    while (i < text_.size() && is_digit(text_[i])) mantissa += text_[i++];
    bool decimal = false;
    if (i < text_.size() && text_[i] == '.') {
      decimal = true;
      ++i;
      while (i < text_.size() && is_digit(text_[i])) {
        mantissa += text_[i++];
        ++fraction_digits;
      }
    }
    long decimal_exponent = 0;
    if (i < text_.size() && (text_[i] == 'e' || text_[i] == 'E')) {
      decimal = true;
      ++i;
      int sign = 1;
      if (i < text_.size() && (text_[i] == '+' || text_[i] == '-')) sign = text_[i++] == '-' ? -1 : 1;
      std::string digits;
      while (i < text_.size() && is_digit(text_[i])) digits += text_[i++];
      if (digits.empty()) refuse("the number" + position(start) + " has an empty exponent");
      if (digits.size() > 3 || std::stol(digits) > limits::max_decimal_exponent) {
        refuse("the number " + text_.substr(start, i - start) + position(start) + " has a decimal exponent beyond +-" +
               std::to_string(limits::max_decimal_exponent));
      }
      decimal_exponent = sign * std::stol(digits);
    }
    const auto first_significant = mantissa.find_first_not_of('0');
    const std::size_t significant = first_significant == std::string::npos ? 0 : mantissa.size() - first_significant;
    if (significant > static_cast<std::size_t>(limits::max_digits) ||
        mantissa.size() > static_cast<std::size_t>(2 * limits::max_digits)) {
      refuse("the number " + text_.substr(start, i - start) + position(start) + " has more than " +
             std::to_string(limits::max_digits) + " significant digits");
    }
    if (i < text_.size() && (is_letter(text_[i]) || text_[i] == '_' || text_[i] == '.')) {
      refuse("the number " + text_.substr(start, i - start + 1) + position(start) +
             " is malformed (write 2*x for a product)");
    }
    if (!decimal) {
      out_ += mantissa;
      return i;
    }
    const long shift = decimal_exponent - fraction_digits;  // value = mantissa * 10^shift
    const std::string digits = significant ? mantissa.substr(first_significant) : "0";
    const std::string power_of_ten = "1" + std::string(static_cast<std::size_t>(std::labs(shift)), '0');
    out_ += shift >= 0 ? "(" + digits + "*" + power_of_ten + ")" : "(" + digits + "/" + power_of_ten + ")";
    return i;
  }

  // ^ n, ^(n), ^-n, ^(-n): an integer literal. Powers of powers multiply their exponents,
  // and GiNaC evaluates a number's power at once, so the product is bounded too.
  std::size_t exponent(std::size_t i) {
    const std::size_t start = i++;
    auto skip_blanks = [&] {
      while (i < text_.size() && is_blank(text_[i])) ++i;
    };
    skip_blanks();
    const bool parenthesised = i < text_.size() && text_[i] == '(';
    if (parenthesised) ++i;
    skip_blanks();
    bool negative = false;
    if (i < text_.size() && (text_[i] == '-' || text_[i] == '+')) negative = text_[i++] == '-';
    skip_blanks();
    std::string digits;
    while (i < text_.size() && is_digit(text_[i])) digits += text_[i++];
    skip_blanks();
    const bool closed = !parenthesised || (i < text_.size() && text_[i] == ')');
    const bool integer = !digits.empty() && closed && !(i < text_.size() && (text_[i] == '.' || is_letter(text_[i])));
    if (!integer) {
      refuse("the exponent after ^" + position(start) +
             " must be an integer literal (|n| <= " + std::to_string(limits::max_power) +
             "); the profile is rational in cos(k x), "
             "sin(k x)");
    }
    if (parenthesised) ++i;
    const long n = digits.size() > 4 ? limits::max_power + 1 : std::stol(digits);
    const long product = last_product_ * std::max(n, 1L);
    if (n > limits::max_power || product > limits::max_power) {
      refuse("the power ^" + std::string(negative ? "-" : "") + digits + position(start) +
             (n > limits::max_power ? std::string(" is beyond ") : " of a power gives an exponent beyond ") + "+-" +
             std::to_string(limits::max_power));
    }
    last_product_ = product;
    raise(product);
    out_ += "^(" + std::string(negative ? "-" : "") + digits + ")";
    return i;
  }

  void raise(long product) {
    if (!groups_.empty()) groups_.back() = std::max(groups_.back(), product);
  }

  const std::string& text_;
  const bool identifiers_;
  const std::vector<std::string> functions_;
  std::string out_;
  std::vector<long> groups_;  // per open "(": the largest exponent product inside
  long last_product_ = 1;     // the exponent product of the primary just read
};

void check_text(const std::string& text, const std::string& what) {
  if (text.find_first_not_of(" \t") == std::string::npos) refuse(what + " is empty");
  if (text.size() > limits::max_characters) {
    refuse(what + " has " + std::to_string(text.size()) + " characters, more than " +
           std::to_string(limits::max_characters));
  }
}

const GiNaC::prototype_table& profile_functions() {
  static const GiNaC::prototype_table table = [] {
    GiNaC::prototype_table t;
    const auto& all = GiNaC::get_default_reader();
    for (const char* name : {"cos", "sin", "sqrt", "abs"}) t.insert(*all.find({name, 1}));
    return t;
  }();
  return table;
}

// Saturating arithmetic for the degree bounds.
long add(long a, long b) { return std::min(a + b, 1L << 40); }
long times(long a, long n) { return a > (1L << 40) / std::max(n, 1L) ? 1L << 40 : a * n; }

struct Degrees {
  long numerator = 0, denominator = 0;
};

void check_coefficient(const numeric& q) {
  if (!q.is_rational()) refuse("the coefficient " + printed(q) + " is not a rational number");
  if (q.numer().int_length() > limits::max_number_bits || q.denom().int_length() > limits::max_number_bits) {
    refuse("a coefficient has more than " + std::to_string(limits::max_number_bits) +
           " bits in its numerator or denominator");
  }
}

Degrees degrees(const ex& e, const ex& x) {
  if (GiNaC::is_a<numeric>(e)) {
    check_coefficient(GiNaC::ex_to<numeric>(e));
    return {};
  }
  if (is_abs(e)) return degrees(e.op(0), x);  // branches.hpp
  if (GiNaC::is_a<GiNaC::function>(e)) {
    const ex k = (e.op(0) / x).normal();
    if (!GiNaC::is_a<numeric>(k) || !GiNaC::ex_to<numeric>(k).is_integer()) {
      refuse("the argument of " + printed(e) +
             " is not an integer multiple k x of x (a frequency "
             "k that is an integer, |k| <= " +
             std::to_string(limits::max_order) + ")");
    }
    const numeric frequency = GiNaC::abs(GiNaC::ex_to<numeric>(k));
    if (frequency > limits::max_order) {
      refuse("the frequency of " + printed(e) + " is beyond " + std::to_string(limits::max_order));
    }
    return {frequency.to_long(), 0};
  }
  if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
    std::vector<Degrees> terms;
    for (const ex& operand : e) terms.push_back(degrees(operand, x));
    Degrees d;
    for (const auto& t : terms) d.denominator = add(d.denominator, t.denominator);
    for (const auto& t : terms) {
      d.numerator = GiNaC::is_a<GiNaC::mul>(e) ? add(d.numerator, t.numerator)
                                               : std::max(d.numerator, add(t.numerator, d.denominator - t.denominator));
    }
    return d;
  }
  if (GiNaC::is_a<GiNaC::power>(e)) {
    const Degrees base = degrees(e.op(0), x);
    const ex exponent = e.op(1);
    if (!GiNaC::is_a<numeric>(exponent) || !GiNaC::ex_to<numeric>(exponent).is_integer()) {
      return base;  // refused by the profile's own check, which names it
    }
    const long n = GiNaC::ex_to<numeric>(exponent).to_long();
    return n >= 0 ? Degrees{times(base.numerator, n), times(base.denominator, n)}
                  : Degrees{times(base.denominator, -n), times(base.numerator, -n)};
  }
  return {};  // x, a parameter, Pi
}

}  // namespace

ex parse_bounded_expression(const std::string& text, const GiNaC::symtab& table) {
  check_text(text, "the expression");
  const std::string rewritten = Lexer(text, true, {"cos", "sin", "sqrt", "abs"}).rewrite();
  GiNaC::parser reader(table, true, profile_functions());
  try {
    return reader(rewritten);
  } catch (const std::exception& e) {
    const std::string what = e.what();
    refuse("cannot parse it (" + what.substr(0, what.find('\n')) + "); the symbols are x and the --param names");
  }
}

numeric parse_bounded_number(const std::string& text) {
  check_text(text, "the value");
  const std::string rewritten = Lexer(text, false, {}).rewrite();
  ex value;
  try {
    value = GiNaC::parser({}, true, {})(rewritten);
  } catch (const std::exception&) {
    refuse("the value \"" + text + "\" is not a number (e.g. 0.25 or 1/4)");
  }
  if (!GiNaC::is_a<numeric>(value) || !GiNaC::ex_to<numeric>(value).is_rational()) {
    refuse("the value \"" + text + "\" is not a real number (e.g. 0.25 or 1/4)");
  }
  check_coefficient(GiNaC::ex_to<numeric>(value));
  return GiNaC::ex_to<numeric>(value);
}

ProfileOrder checked_order(const ex& y, const ex& x) {
  const Degrees d = degrees(y, x);
  if (d.numerator > limits::max_order) {
    refuse(
        "its order (the degree in cos x, sin x of the numerator, cos(k x) counting k) may "
        "reach " +
        std::to_string(d.numerator) + ", beyond " + std::to_string(limits::max_order));
  }
  if (d.denominator > limits::max_denominator_order) {
    refuse(
        "the order of its denominator (the degree in cos x, sin x, cos(k x) counting k) may "
        "reach " +
        std::to_string(d.denominator) + ", beyond " + std::to_string(limits::max_denominator_order) +
        ": what is not a cosine sum goes through partial fractions");
  }
  return {d.numerator, d.denominator};
}

}  // namespace wavecontact::derive
