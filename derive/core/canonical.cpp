#include "canonical.hpp"

#include <algorithm>
#include <functional>
#include <sstream>

namespace wavecontact::derive {

using GiNaC::ex;

namespace {

std::string plain(const ex& e) {
  std::ostringstream os;
  os << e;
  return os.str();
}

bool needs_parentheses(const ex& e) {
  return GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e) || GiNaC::is_a<GiNaC::power>(e) ||
         (GiNaC::is_a<GiNaC::numeric>(e) &&
          (GiNaC::ex_to<GiNaC::numeric>(e).is_negative() || !GiNaC::ex_to<GiNaC::numeric>(e).is_integer()));
}

std::string wrapped(const ex& e) {
  const std::string s = canonical_string(e);
  return needs_parentheses(e) ? "(" + s + ")" : s;
}

}  // namespace

std::vector<ex> sorted_operands(const ex& e) {
  std::vector<std::pair<std::string, ex>> keyed;
  for (const ex& operand : e) keyed.emplace_back(canonical_string(operand), operand);
  std::stable_sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<ex> operands;
  for (auto& [key, operand] : keyed) operands.push_back(operand);
  return operands;
}

std::string canonical_string(const ex& e) {
  if (GiNaC::is_a<GiNaC::add>(e)) {
    std::vector<std::string> terms;
    for (const ex& term : e) terms.push_back(canonical_string(term));
    std::sort(terms.begin(), terms.end());
    std::string s;
    for (const auto& term : terms) s += (s.empty() || term[0] == '-' ? "" : "+") + term;
    return s;
  }
  if (GiNaC::is_a<GiNaC::mul>(e)) {
    // Each factor sum^k with the sum's sign fixed (GiNaC may store a factor as -(sum) in one run
    // and (-sum) in the next), the sign carried into the coefficient.
    std::vector<std::string> factors;
    GiNaC::numeric sign = 1, number = 1;
    for (const ex& factor : e) {
      if (GiNaC::is_a<GiNaC::numeric>(factor)) {
        number = GiNaC::ex_to<GiNaC::numeric>(factor);
        continue;
      }
      const bool power = GiNaC::is_a<GiNaC::power>(factor);
      const ex base = power ? factor.op(0) : factor, exponent = power ? factor.op(1) : ex(1);
      if (GiNaC::is_a<GiNaC::add>(base) && GiNaC::is_a<GiNaC::numeric>(exponent) &&
          GiNaC::ex_to<GiNaC::numeric>(exponent).is_integer()) {
        // Written the same way whichever sign the sum was stored with.
        const GiNaC::numeric& k = GiNaC::ex_to<GiNaC::numeric>(exponent);
        const bool flip = leading_term_negative(base);
        if (flip && k.is_odd()) sign = -sign;
        const std::string fixed = canonical_string(flip ? (-base).expand() : base, k);
        factors.push_back(k == 1 ? "(" + fixed + ")" : fixed);
      } else {
        factors.push_back(wrapped(factor));
      }
    }
    const GiNaC::numeric value = sign * number;
    const std::string coefficient = value.is_equal(1) ? "" : plain(value);
    std::sort(factors.begin(), factors.end());
    std::string s = coefficient == "-1" ? "-" : coefficient.empty() ? "" : coefficient + "*";
    for (std::size_t i = 0; i < factors.size(); ++i) s += (i ? "*" : "") + factors[i];
    return s;
  }
  if (GiNaC::is_a<GiNaC::power>(e)) return wrapped(e.op(0)) + "^" + wrapped(e.op(1));
  if (GiNaC::is_a<GiNaC::function>(e)) {
    // A rational argument as one fraction with its signs fixed: GiNaC may store a factor of it as
    // -(sum) in one run and (-sum) in the next.
    std::string s = GiNaC::ex_to<GiNaC::function>(e).get_name() + "(";
    for (std::size_t i = 0; i < e.nops(); ++i) {
      const ex& argument = e.op(i);
      s += (i ? "," : "") + (argument.info(GiNaC::info_flags::rational_function) ? canonical_rational(argument)
                                                                                 : canonical_string(argument));
    }
    return s + ")";
  }
  return plain(e);
}

std::string canonical_string(const ex& base, const GiNaC::numeric& exponent) {
  if (exponent == 1) return canonical_string(base);
  return wrapped(base) + "^" + wrapped(exponent);
}

namespace {

// A rational in (1, 2) fixed by a string: the same on every run (libstdc++'s std::hash of a
// string has no seed).
GiNaC::numeric generic_value(const std::string& key) {
  const std::size_t h = std::hash<std::string>()(key);
  return GiNaC::numeric(1) + GiNaC::numeric(static_cast<long>(h % 999983) + 1, 999991);
}

// The value of e with every symbol at generic_value(its name), every function call at
// generic_value(its canonical string) and pi at 355/113: a function of e's value alone, however
// GiNaC stores it (run to run it may store a sum's terms with factors of opposite signs or
// differently combined). 0 if undefined there or not a real number.
GiNaC::numeric value_at_generic_point(const ex& e) {
  // The calls first (substituting into their arguments first could evaluate them off their domain).
  GiNaC::exmap calls, point;
  for (GiNaC::const_preorder_iterator i = e.preorder_begin(); i != e.preorder_end(); ++i) {
    if (GiNaC::is_a<GiNaC::function>(*i)) calls[*i] = generic_value(canonical_string(*i));
  }
  const ex without_calls = e.subs(calls, GiNaC::subs_options::no_pattern);
  for (GiNaC::const_preorder_iterator i = without_calls.preorder_begin(); i != without_calls.preorder_end(); ++i) {
    if (GiNaC::is_a<GiNaC::symbol>(*i)) point[*i] = generic_value(GiNaC::ex_to<GiNaC::symbol>(*i).get_name());
  }
  point[GiNaC::Pi] = GiNaC::numeric(355, 113);
  try {
    const ex value = without_calls.subs(point, GiNaC::subs_options::no_pattern).evalf();
    if (GiNaC::is_a<GiNaC::numeric>(value) && GiNaC::ex_to<GiNaC::numeric>(value).is_real()) {
      return GiNaC::ex_to<GiNaC::numeric>(value);
    }
  } catch (const std::exception&) {  // a pole at that point
  }
  return 0;
}

}  // namespace

bool leading_term_negative(const ex& sum) {
  // By value where it is defined: -sum gets the other answer whatever the form GiNaC chose.
  const GiNaC::numeric value = value_at_generic_point(sum);
  if (!value.is_zero()) return value.is_negative();
  std::string leading;
  const ex terms = GiNaC::is_a<GiNaC::add>(sum) ? sum : GiNaC::lst{sum};
  for (const ex& term : terms) {  // a constant term leads
    if (GiNaC::is_a<GiNaC::numeric>(term)) return GiNaC::ex_to<GiNaC::numeric>(term).is_negative();
  }
  for (const ex& term : terms) {
    const std::string s = canonical_string(term);
    const std::string unsigned_s = s[0] == '-' ? s.substr(1) : s;
    const std::string unsigned_leading = leading[0] == '-' ? leading.substr(1) : leading;
    if (leading.empty() || unsigned_s < unsigned_leading) leading = s;
  }
  return leading[0] == '-';
}

std::string canonical_rational(const ex& e) {
  const ex nd = e.normal().numer_denom();
  ex numerator = nd.op(0).expand(), denominator = nd.op(1).expand();
  if (leading_term_negative(denominator)) {
    numerator = (-numerator).expand();
    denominator = (-denominator).expand();
  }
  if (denominator.is_equal(1)) return canonical_string(numerator);
  return "(" + canonical_string(numerator) + ")/(" + canonical_string(denominator) + ")";
}

}  // namespace wavecontact::derive
