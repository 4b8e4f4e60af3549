#include "user_profile.hpp"

#include <algorithm>
#include <cmath>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/printed.hpp"
#include "core/symbols.hpp"
#include "engine/hilbert.hpp"
#include "engine/sub_interval.hpp"
#include "formulas/full_contact.hpp"
#include "profile/block_keer.hpp"
#include "profile/expression_input.hpp"

namespace wavecontact::derive {

using GiNaC::ex;
using GiNaC::numeric;

namespace {

const std::regex identifier("[A-Za-z][A-Za-z0-9_]{0,63}");

// Symbols of the derivation and of the emitted code, which a parameter may not shadow.
const std::set<std::string> reserved{"x",  "v",  "u",  "s",  "t", "alpha", "E", "b1",
                                     "Ca", "Sa", "Cx", "Sx", "D", "Pi",    "I", "Scalar"};

// Names a parameter (an argument of the emitted C++) may not take: the language's keywords
// and alternative tokens, the emitted code's own names (out, A, work, atoms, y, one_plus_y,
// the functions it calls unqualified, its namespaces) and lower-case macros of the C library.
const std::set<std::string> cpp_names{"alignas",
                                      "alignof",
                                      "and",
                                      "and_eq",
                                      "asm",
                                      "auto",
                                      "bitand",
                                      "bitor",
                                      "bool",
                                      "break",
                                      "case",
                                      "catch",
                                      "char",
                                      "char8_t",
                                      "char16_t",
                                      "char32_t",
                                      "class",
                                      "compl",
                                      "concept",
                                      "const",
                                      "consteval",
                                      "constexpr",
                                      "constinit",
                                      "const_cast",
                                      "continue",
                                      "co_await",
                                      "co_return",
                                      "co_yield",
                                      "decltype",
                                      "default",
                                      "delete",
                                      "do",
                                      "double",
                                      "dynamic_cast",
                                      "else",
                                      "enum",
                                      "explicit",
                                      "export",
                                      "extern",
                                      "false",
                                      "float",
                                      "for",
                                      "friend",
                                      "goto",
                                      "if",
                                      "inline",
                                      "int",
                                      "long",
                                      "mutable",
                                      "namespace",
                                      "new",
                                      "noexcept",
                                      "not",
                                      "not_eq",
                                      "nullptr",
                                      "operator",
                                      "or",
                                      "or_eq",
                                      "private",
                                      "protected",
                                      "public",
                                      "register",
                                      "reinterpret_cast",
                                      "requires",
                                      "return",
                                      "short",
                                      "signed",
                                      "sizeof",
                                      "static",
                                      "static_assert",
                                      "static_cast",
                                      "struct",
                                      "switch",
                                      "template",
                                      "this",
                                      "thread_local",
                                      "throw",
                                      "true",
                                      "try",
                                      "typedef",
                                      "typeid",
                                      "typename",
                                      "union",
                                      "unsigned",
                                      "using",
                                      "virtual",
                                      "void",
                                      "volatile",
                                      "wchar_t",
                                      "while",
                                      "xor",
                                      "xor_eq",
                                      "out",
                                      "A",
                                      "work",
                                      "atoms",
                                      "y",
                                      "one_plus_y",
                                      "sqrt",
                                      "fabs",
                                      "fma",
                                      "std",
                                      "wavecontact",
                                      "generated",
                                      "errno",
                                      "assert",
                                      "stdin",
                                      "stdout",
                                      "stderr",
                                      "offsetof",
                                      "main"};

// All capitals (NULL, EOF, INFINITY, M_PI, ...): left to macros.
bool macro_like(const std::string& name) {
  int capitals = 0;
  for (char c : name) {
    if (c >= 'A' && c <= 'Z') {
      ++capitals;
    } else if (!(c >= '0' && c <= '9') && c != '_') {
      return false;
    }
  }
  return capitals >= 2;
}

[[noreturn]] void refuse(const ProfileSpec& spec, const std::string& why) {
  const std::string& text = spec.expression;  // echoed up to 200 characters
  const std::string shown =
      text.size() <= 200 ? text : text.substr(0, 200) + "... (" + std::to_string(text.size()) + " characters)";
  throw InputRefused("profile " + spec.name + " = \"" + shown + "\": " + why);
}

// The first power with a non-integer exponent (sqrt(cos(x)), cos(x)^(1/3), ...), if any.
bool find_non_integer_power(const ex& e, ex& found) {
  if (GiNaC::is_a<GiNaC::power>(e)) {
    const ex exponent = e.op(1);
    if (!GiNaC::is_a<numeric>(exponent) || !GiNaC::ex_to<numeric>(exponent).is_integer()) {
      found = e;
      return true;
    }
  }
  for (const ex& operand : e) {
    if (find_non_integer_power(operand, found)) return true;
  }
  return false;
}

void check_names(const ProfileSpec& spec) {
  if (!std::regex_match(spec.name, identifier)) {
    refuse(spec,
           "the name must be a C++ identifier: a letter, then letters, digits or _ "
           "(at most 64 characters)");
  }
  if (spec.parameters.size() > expression_limits::max_parameters) {
    refuse(spec, std::to_string(spec.parameters.size()) + " parameters, more than " +
                     std::to_string(expression_limits::max_parameters));
  }
  std::set<std::string> seen;
  for (const auto& p : spec.parameters) {
    if (!std::regex_match(p.name, identifier)) {
      refuse(spec, "parameter \"" + p.name +
                       "\" is not an identifier (a letter, then "
                       "letters, digits or _)");
    }
    if (reserved.count(p.name)) {
      refuse(spec, "parameter \"" + p.name +
                       "\" is reserved (x is the coordinate; E, b1 and "
                       "the angle atoms Ca Sa Cx Sx D are arguments of the emitted evaluators)");
    }
    if (cpp_names.count(p.name)) {
      refuse(spec, "parameter \"" + p.name + "\" is a C++ keyword or a name of the emitted code; rename it");
    }
    if (macro_like(p.name)) {
      refuse(spec, "parameter \"" + p.name +
                       "\" is all capitals, which C and C++ leave to macros (NULL, "
                       "EOF, INFINITY); rename it");
    }
    if (!seen.insert(p.name).second) refuse(spec, "parameter \"" + p.name + "\" is given twice");
  }
}

// A profile without a separate cosine sum goes whole through the partial fractions.
void check_whole_order(const ProfileSpec& spec, const ex& Y) {
  const GiNaC::symbol& c = sym::Cx();
  const ex nd = Y.normal().numer_denom();
  const ex denominator = nd.op(1).expand();
  // A denominator led by a number (1/(2 + cos x)^32) keeps only the general bound.
  if (denominator.degree(c) == 0 || GiNaC::is_a<numeric>(denominator.lcoeff(c))) return;
  const long order = std::max(nd.op(0).degree(c), denominator.degree(c));
  if (order > expression_limits::max_whole_order) {
    refuse(spec, "its order in cos x is " + std::to_string(order) + ", beyond " +
                     std::to_string(expression_limits::max_whole_order) +
                     " for a profile whose denominator's leading coefficient in cos x depends "
                     "on a parameter (it has no separate cosine sum and goes whole through "
                     "partial fractions)");
  }
}

// A parameter-free pole of the profile at cos x = c0 in [lo, hi], the part of [-1, 1] where
// the branch R holds (refused before the engine meets it: at x = 0 it is a pole at v^2 = 0,
// where the moments divide by zero).
void check_poles_off_the_period(const ProfileSpec& spec, const ex& R, const numeric& lo = -1, const numeric& hi = 1) {
  const GiNaC::symbol& c = sym::Cx();
  const ex denominator = GiNaC::factor(R.normal().denom());
  const std::vector<ex> factors = GiNaC::is_a<GiNaC::mul>(denominator)
                                      ? std::vector<ex>(denominator.begin(), denominator.end())
                                      : std::vector<ex>{denominator};
  for (const ex& factor_power : factors) {
    const ex factor = GiNaC::is_a<GiNaC::power>(factor_power) ? factor_power.op(0) : factor_power;
    if (factor.degree(c) != 1) continue;
    const ex root = (-factor.coeff(c, 0) / factor.coeff(c, 1)).normal();
    if (!GiNaC::is_a<numeric>(root) || !GiNaC::ex_to<numeric>(root).is_real()) continue;
    const numeric c0 = GiNaC::ex_to<numeric>(root);
    if (c0 < lo || c0 > hi) continue;
    std::ostringstream os;
    os.precision(17);
    os << "the profile has a pole at cos x = " << c0;
    if (c0 > -1) os << " (g(v) at v^2 = " << (1 - c0) / (1 + c0) << ")";
    os << ", i.e. at x = +-" << std::acos(c0.to_double())
       << " of the period 2 pi: it is unbounded there, and a contact zone reaching it has no "
          "bounded solution";
    refuse(spec, os.str());
  }
}

// The poles tau = v^2 of the odd rational g that depend on the parameters.
std::vector<ex> parameter_pole_squares(const ex& g, const std::vector<GiNaC::realsymbol>& parameters) {
  const GiNaC::symbol& t = sym::t();
  const ex denominator = GiNaC::factor(even_in_square(g.normal().denom(), sym::v(), t));
  const std::vector<ex> factors = GiNaC::is_a<GiNaC::mul>(denominator)
                                      ? std::vector<ex>(denominator.begin(), denominator.end())
                                      : std::vector<ex>{denominator};
  std::vector<ex> poles;
  for (const ex& factor_power : factors) {
    const ex factor = GiNaC::is_a<GiNaC::power>(factor_power) ? factor_power.op(0) : factor_power;
    if (factor.degree(t) != 1) continue;
    const ex tau = (-factor.coeff(t, 0) / factor.coeff(t, 1)).normal();
    bool parametric = false;
    for (const auto& p : parameters) parametric = parametric || tau.has(p);
    if (parametric) poles.push_back(tau);
  }
  return poles;
}

// The branches of a profile built with abs() must meet with the same slope (g continuous at
// beta): a corner makes the pressure log-singular, beyond what the forms and the runtime's
// quadrature assume.
void check_slopes_meet(const ProfileSpec& spec, const BranchSplit& branches) {
  const ex jump = hilbert_rhs(branches.top) - hilbert_rhs(branches.flank);
  if (jump.subs(sym::v() == branches.beta).normal().is_zero()) return;
  std::ostringstream os;
  os << "its slope jumps at cos x = " << branches.cosine
     << ", where an abs() argument changes sign (a corner, under which the contact pressure is "
        "log-singular): the engine joins branches whose slopes meet, as in eq. 2, where |cos x| "
        "multiplies cos x";
  refuse(spec, os.str());
}

// The flank of a profile built with abs(): its height, its parameter-free poles (checked on
// cos x^ <= the branch's cosine), and the load and slope beyond the branch point.
void derive_flank(const ProfileSpec& spec, ProfileDerivation& d) {
  const BranchSplit& branches = d.branches;
  const ex flank = in_cosine(branches.flank);
  check_poles_off_the_period(spec, flank, -1, branches.cosine);
  d.flank_height = flank;
  d.flank_height_slope = flank.diff(sym::Cx()).normal();
  const ex flank_g = hilbert_rhs(branches.flank), top_g = hilbert_rhs(branches.top);
  d.flank_pole_squares = parameter_pole_squares(flank_g, d.parameters);
  d.beyond = derive_beyond_branch(top_g, flank_g, branches.beta, d.sample);
}

ex parse(const ProfileSpec& spec, const std::vector<GiNaC::realsymbol>& parameters) {
  GiNaC::symtab table;
  table["x"] = sym::x();
  table["Pi"] = GiNaC::Pi;
  for (const auto& p : parameters) table[p.get_name()] = p;
  try {
    ex y = parse_bounded_expression(spec.expression, table);
    checked_order(y, sym::x());
    return y;
  } catch (const InputRefused& e) {
    refuse(spec, e.what());
  }
}

}  // namespace

ProfileParameter parse_parameter(const std::string& text) {
  const auto equals = text.find('=');
  ProfileParameter p{text.substr(0, equals), numeric(1, 2)};
  if (equals == std::string::npos) return p;
  try {
    p.sample = parse_bounded_number(text.substr(equals + 1));
  } catch (const InputRefused& e) {
    throw InputRefused("--param " + text + ": " + e.what());
  }
  return p;
}

ProfileDerivation derive_profile(const ProfileSpec& spec) {
  check_names(spec);
  ProfileDerivation d;
  d.spec = spec;
  d.sample = sample_point_v();
  for (const auto& p : spec.parameters) {
    d.parameters.emplace_back(p.name);
    d.sample[d.parameters.back()] = p.sample;
  }
  const ex written = parse(spec, d.parameters);
  if (!written.has(sym::x())) refuse(spec, "it does not depend on x");
  try {
    d.branches = split_branches(written);
  } catch (const InputRefused& e) {
    refuse(spec, e.what());
  }
  const ex& y = d.branches.top;
  ex power;
  if (find_non_integer_power(y, power)) {
    refuse(spec, printed(power) +
                     " is a non-integer power: the profile must be rational in "
                     "cos(k x) and sin(k x) (integer k) and in the parameters");
  }
  ex y_v;
  try {
    y_v = in_half_angle_tangent(y);
  } catch (const std::invalid_argument& e) {
    refuse(spec, e.what());
  }
  if (!(y_v.subs(sym::v() == -sym::v()) - y_v).normal().is_zero()) {
    refuse(spec,
           "it is not even in x (y(-x) != y(x)); the contact zone |x| < a is centred "
           "on x = 0, a top of the profile");
  }
  try {
    if (d.branches.branched) check_slopes_meet(spec, d.branches);
    const HarmonicSplit parts = split_harmonic_part(in_cosine(y));
    if (parts.cosine.empty()) check_whole_order(spec, parts.rational);
    check_poles_off_the_period(spec, parts.rational, d.branches.branched ? d.branches.cosine : numeric(-1));
    d.forms = derive_closed_forms(y, parts, d.sample);
    if (d.branches.branched) {
      derive_flank(spec, d);
      const ex top = in_cosine(y);
      const numeric& cosine = d.branches.cosine;
      d.full_contact_pressure = full_contact_pressure(top, d.flank_height, cosine);
      d.full_contact_pressure_top = full_contact_pressure_on_side(top, d.flank_height, cosine, true);
      d.full_contact_pressure_flank = full_contact_pressure_on_side(top, d.flank_height, cosine, false);
    } else {
      d.full_contact_pressure = full_contact_pressure(parts.rational);
    }
  } catch (const InputRefused&) {
    throw;
  } catch (const std::invalid_argument& e) {
    refuse(spec, e.what());
  } catch (const std::logic_error& e) {
    refuse(spec, std::string(e.what()) + "; try other sample values --param NAME=VALUE");
  }

  const Radicals& radicals = d.forms.radicals;
  for (unsigned i = 0; i < radicals.size(); ++i) {
    const ex tau = radicals.pole(i);
    if (!GiNaC::is_a<numeric>(tau)) d.pole_squares.push_back(tau);
  }
  return d;
}

}  // namespace wavecontact::derive
