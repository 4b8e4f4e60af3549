// A user-supplied asperity shape through the engine: `wavecontact-derive --profile EXPR`.
//
// EXPR is the profile y(x) over one period 2 pi of the normalised coordinate x = pi x/b1,
// in GiNaC syntax, with the symbol x and the named parameters; rational in cos(k x) and
// sin(k x) for integer k. The contact zone |x| < a is centred on x = 0, so y must be even.
// The Block-Keer change of variables turns it into g(v), which must be odd and rational
// with poles, in t = v^2, at roots of factors linear in t; the engine (hilbert.hpp) then
// gives the pressure and the load in closed form, as for the built-in wave curve.
#pragma once

#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "closed_forms.hpp"

namespace wavecontact::derive {

struct ProfileParameter {
  std::string name;        // a C++ identifier, not one of the reserved symbols
  GiNaC::numeric sample;   // a typical value (rational), fixes the signs of square roots
};

struct ProfileSpec {
  std::string name;        // C++ identifier: evaluators are named <name>_pressure, ...
  std::string expression;  // y(x), GiNaC syntax
  std::vector<ProfileParameter> parameters;
};

// "NAME" or "NAME=VALUE" (VALUE a decimal or p/q; default 1/2).
ProfileParameter parse_parameter(const std::string& text);

struct ProfileDerivation {
  ProfileSpec spec;
  std::vector<GiNaC::realsymbol> parameters;  // in the order of spec.parameters
  GiNaC::exmap sample;                        // sample_point_v() and the parameters' samples
  ClosedForms forms;
  // The poles tau_i of g in t = v^2 that depend on the parameters: where real and > 0 they
  // bound the contact, x^ < 2 atan(sqrt(tau_i)). Parameter-free poles are checked here.
  std::vector<GiNaC::ex> pole_squares;
};

// Parses, checks and derives. Throws std::invalid_argument with the reason and the place
// when the name, a parameter or the expression is not acceptable: a parse error, a symbol
// that is not declared, a term not rational in cos(k x), sin(k x), a profile that is not
// even, a denominator the engine cannot factor into poles linear in v^2, or a pole of the
// profile on the real period (parameter-free) where the contact can reach it.
ProfileDerivation derive_profile(const ProfileSpec& spec);

}  // namespace wavecontact::derive
