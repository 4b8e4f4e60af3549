// A user-supplied asperity shape through the engine: `wavecontact-derive --profile EXPR`.
//
// EXPR is the profile y(x) over one period 2 pi of the normalised coordinate x = pi x/b1,
// in GiNaC syntax, with the symbol x and the named parameters; rational in cos(k x) and
// sin(k x) for integer k, and in abs() of parameter-free expressions in cos(k x) whose signs
// change at one point of 0 < x < pi at most (branches.hpp), where the slope of y stays
// continuous, as in eq. 2. The contact zone |x| < a is centred on x = 0, so y must be even.
// The Block-Keer change of variables turns it into g(v), which must be odd and rational
// with poles, in t = v^2, at roots of factors linear in t; the engine (hilbert.hpp) then
// gives the pressure and the load in closed form, as for the built-in wave curve.
#pragma once

#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "engine/closed_forms.hpp"
#include "formulas/beyond_branch.hpp"
#include "profile/branches.hpp"

namespace wavecontact::derive {

struct ProfileParameter {
  std::string name;       // a C++ identifier, not one of the reserved symbols
  GiNaC::numeric sample;  // a typical value (rational), fixes the signs of square roots
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
  // A profile built with abs() (branches.hpp): `forms` are those of its top branch, which
  // hold while the zone stays short of the sign change at v = branches.beta; beyond it the
  // load, its slope and the pressure are `beyond`'s. The flank's height in Cx and its parameter-dependent poles in v^2,
  // which bound the contact where they lie beyond beta (the top's where they lie short of it).
  BranchSplit branches;
  BeyondBranch beyond;
  // p_fc(x) of full contact (full_contact.hpp), in Cx: for the rational part R (a cosine sum's
  // part is the sum); for a profile built with abs() the whole of it over both branches, and the
  // forms of each side of the branch point (Cx above, below its cosine) with the other piece's
  // Cauchy factor kept.
  GiNaC::ex full_contact_pressure;
  GiNaC::ex full_contact_pressure_top, full_contact_pressure_flank;
  GiNaC::ex flank_height, flank_height_slope;
  std::vector<GiNaC::ex> flank_pole_squares;
};

// Parses, checks and derives. Throws std::invalid_argument with the reason and the place
// when the name, a parameter or the expression is not acceptable: a parse error, a symbol
// that is not declared, a term not rational in cos(k x), sin(k x), a profile that is not
// even, a denominator the engine cannot factor into poles linear in v^2, or a pole of the
// profile on the real period (parameter-free) where the contact can reach it, an abs() that
// branches.hpp refuses, or a profile whose moments beyond its branch point have more than
// one pole factor in v^2 (sub_interval.hpp), or whose slope jumps at its branch point.
ProfileDerivation derive_profile(const ProfileSpec& spec);

}  // namespace wavecontact::derive
