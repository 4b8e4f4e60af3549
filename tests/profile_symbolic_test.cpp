// User profiles in derive/ (wavecontact-derive --profile): the derived closed forms against
// independent expectations, and every refusal with its reason (issue example (c)).
// GiNaC's exam style: (got - expected).normal() must be zero; failures print everything.
#define BOOST_TEST_MODULE profile_symbolic
#include <boost/test/unit_test.hpp>

#include <string>

#include "core/symbols.hpp"
#include "emit/shared_pieces.hpp"
#include "engine/angle_form.hpp"
#include "formulas/full_contact.hpp"
#include "formulas/user_profile.hpp"
#include "formulas/wave_curve.hpp"

using namespace wavecontact::derive;
using GiNaC::ex;
using GiNaC::numeric;

namespace {

void check_equal(const ex& got, const ex& expected, const std::string& what) {
  const ex difference = (got - expected).normal();
  BOOST_TEST(difference.is_zero(),
             what << "\n  got:      " << got << "\n  expected: " << expected << "\n  difference: " << difference);
}

// The user's parameter symbols renamed to the built-in ones of the same name.
ex as_built_in(const ex& e, const ProfileDerivation& d) {
  GiNaC::exmap map;
  for (const auto& p : d.parameters) {
    if (p.get_name() == "H1") map[p] = sym::H1();
    if (p.get_name() == "m") map[p] = sym::m();
  }
  return e.subs(map);
}

// Legendre polynomial P_k(c).
ex legendre(int k, const ex& c) {
  if (k == 0) return 1;
  ex previous = 1, current = c;
  for (int j = 1; j < k; ++j) {
    const ex next = ((2 * j + 1) * c * current - j * previous) / (j + 1);
    previous = current;
    current = next.expand();
  }
  return current;
}

std::string refusal(const std::string& expression, std::vector<ProfileParameter> parameters = {},
                    const std::string& name = "p") {
  try {
    derive_profile({name, expression, std::move(parameters)});
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

}  // namespace

// Example (a), symbolically: the wave curve typed as an expression gives the built-in
// closed forms (angle forms of pressure, load and dP/da), exactly.
BOOST_AUTO_TEST_CASE(wave_curve_expression_equals_the_built_in_derivation) {
  const ProfileDerivation d =
      derive_profile({"wave", "H1*(m+1)*cos(x)/(m*cos(x)+1)", {{"H1", numeric(1)}, {"m", numeric(1, 2)}}});
  const WavinessDerivation& w = [] {
    static const WavinessDerivation built_in = derive_waviness();
    return std::cref(built_in);
  }();
  check_equal(as_built_in(single_term(d.forms.pressure_angle), d), single_term(w.pressure_angle), "pressure");
  check_equal(as_built_in(single_term(d.forms.load_angle), d), single_term(w.load_angle), "load");
  check_equal(as_built_in(single_term(d.forms.load_slope_factor), d), single_term(w.load_slope_factor),
              "dP/dSa - dP/dCa");
  // Its one parameter-dependent pole, cos x = -1/m: v^2 = (m+1)/(m-1).
  BOOST_TEST_REQUIRE(d.pole_squares.size() == 1u);
  check_equal(as_built_in(d.pole_squares[0], d), (sym::m() + 1) / (sym::m() - 1), "pole");
}

// Example (b), symbolically: the load of H1 cos x + H3 cos 3x, derived whole by the engine's
// partial fractions, is the sum of the loads of its harmonics, each the Legendre form of a
// harmonic cos(k x) in contact (the form the roughness issue derived for cos(n x)):
// P_k = (pi/2) E* H k [P_{k-1}(cos a) - P_k(cos a)]. The profile's own derivation splits
// the cosine sum off (derive/profile/harmonic_part.hpp): A = (0, H1, 0, H3), nothing left.
BOOST_AUTO_TEST_CASE(two_harmonic_load_is_the_legendre_form) {
  const ProfileDerivation d =
      derive_profile({"two", "H1*cos(x)+H3*cos(3*x)", {{"H1", numeric(1)}, {"H3", numeric(1, 10)}}});
  const ex H1 = d.parameters[0], H3 = d.parameters[1], Ca = sym::Ca();
  BOOST_TEST_REQUIRE(d.forms.cosine.size() == 4u);
  check_equal(d.forms.cosine[1], H1, "A_1");
  check_equal(d.forms.cosine[3], H3, "A_3");
  BOOST_TEST((d.forms.cosine[0].is_zero() && d.forms.cosine[2].is_zero()));
  BOOST_TEST(d.forms.rational_height.is_zero());
  BOOST_TEST(d.pole_squares.empty());  // only the poles at v^2 = -1 of cos(k x)

  const ClosedForms whole = derive_closed_forms(d.forms.profile, {{}, d.forms.height}, d.sample);
  const ex expected = GiNaC::Pi / 2 * sym::E() *
                      (H1 * (legendre(0, Ca) - legendre(1, Ca)) + 3 * H3 * (legendre(2, Ca) - legendre(3, Ca)));
  check_equal(single_term(whole.load_angle).subs(sym::Sa() == 1 - Ca), expected, "load");
  // g(v) = -(E/2) y'(x) = (E/2)(H1 sin x + 3 H3 sin 3x), sin 3x = 3 sin x - 4 sin^3 x,
  // sin x = 2v/(1 + v^2).
  const ex v = sym::v(), sin_x = 2 * v / (1 + v * v);
  check_equal(whole.g, sym::E() / 2 * (H1 * sin_x + 3 * H3 * (3 * sin_x - 4 * GiNaC::pow(sin_x, 3))), "g");
}

// Example (c) and every other refusal, each naming what is wrong and where.
BOOST_AUTO_TEST_CASE(refusals_say_why_and_where) {
  const auto contains = [](const std::string& message, const std::string& part) {
    BOOST_TEST(message.find(part) != std::string::npos, "\"" << part << "\" not in: " << message);
  };
  contains(refusal("sqrt(cos(x))"), "sqrt(cos(x)) is a non-integer power");
  contains(refusal("H*cos(x)^(1/3)", {{"H", 1}}), "must be an integer literal");
  contains(refusal("sin(x)"), "not even in x");
  contains(refusal("tan(x)"), "function tan at character 1 is not rational in cos(k x) and sin(k x)");
  contains(refusal("cos(x/2)"), "the argument of cos(1/2*x) is not an integer multiple k x of x");
  contains(refusal("H*cos(x)"), "symbol \"H\" not found");
  contains(refusal("cos(x"), "unbalanced \"(\": 1 not closed");
  contains(refusal("cos(x)+"), "cannot parse it");
  contains(refusal("2"), "does not depend on x");
  contains(refusal("cos(x)/(2*cos(x)+1)"), "pole at cos x = -1/2 (g(v) at v^2 = 3), i.e. at x = +-2.094395");
  // At the top itself (found by the expression fuzzer: the moments divided by v^2 = 0, and
  // GiNaC leaked its operands), and at the valley.
  contains(refusal("H*cos(x)^3+c*cos(x)/(1-cos(x))", {{"H", 1}, {"c", numeric(-101, 20)}}),
           "pole at cos x = 1 (g(v) at v^2 = 0), i.e. at x = +-0 ");
  contains(refusal("1/(1+cos(x))"), "pole at cos x = -1, i.e. at x = +-3.14159");
  contains(refusal("1/(3+cos(x)+cos(2*x))"), "is not linear in v^2");
  contains(refusal("E*cos(x)", {{"E", 1}}), "parameter \"E\" is reserved");
  contains(refusal("H*cos(x)", {{"H", 1}, {"H", 2}}), "given twice");
  contains(refusal("cos(x)", {}, "9lives"), "must be a C++ identifier");
  BOOST_TEST(refusal("cos(x)+cos(2*x)/4") == "accepted");
  // abs() (derive/profile/branches.hpp): one parameter-free sign change, at a rational tan(x/2), where
  // the slope stays continuous; without a sign change it is its sign.
  contains(refusal("cos(x)+abs(cos(x))*abs(5*cos(x)-3)"), "change sign at cos x = 0, 3/5");
  contains(refusal("H*cos(x)+abs(5*cos(x)-3)", {{"H", 1}}), "its slope jumps at cos x = 3/5");
  BOOST_TEST(refusal("cos(x)+abs(2+cos(x))/4") == "accepted");
  BOOST_TEST(refusal("cos(x)+(5*cos(x)+3)*abs(5*cos(x)+3)/8") == "accepted");
}

// Full contact (derive/formulas/full_contact.hpp) against closed forms worked by hand: cos(3x) whole
// through the residues (its pole of order 3 at v^2 = -1) gives (E/2)(pi/b1) 3 T_3(Cx); and
// 1/(c - cos x), whose cosine coefficients are 2 rho^k/sqrt(c^2 - 1), rho = c - sqrt(c^2 - 1),
// gives (E/2)(pi/b1)(c Cx - 1)/(sqrt(c^2 - 1)(c - Cx)^2) (c = 5/4: a rational root; c = 2).
BOOST_AUTO_TEST_CASE(full_contact_closed_forms) {
  const ex C = sym::Cx(), scale = sym::E() / 2 * GiNaC::Pi / sym::b1();
  check_equal(full_contact_pressure(4 * GiNaC::pow(C, 3) - 3 * C), scale * 3 * (4 * GiNaC::pow(C, 3) - 3 * C),
              "cos(3x)");
  const long digits = GiNaC::Digits;
  GiNaC::Digits = 40;
  for (const numeric& c : {numeric(5, 4), numeric(2)}) {
    const ex expected = scale * (c * C - 1) / (GiNaC::sqrt(c * c - 1) * GiNaC::pow(c - C, 2));
    const ex got = full_contact_pressure(1 / (c - C));
    // sqrt(3) is not a rational: compare at 40 digits on a grid of Cx.
    for (const numeric& x : {numeric(-1), numeric(-1, 3), numeric(0), numeric(1, 2), numeric(1)}) {
      const GiNaC::exmap at{{C, x}, {sym::E(), 3}, {sym::b1(), 2}};
      const ex difference = (got.subs(at) - expected.subs(at)).evalf();
      BOOST_TEST(GiNaC::abs(GiNaC::ex_to<numeric>(difference)) <
                     numeric(1, 1000000000) * numeric(1, 1000000000) * numeric(1, 1000000000),
                 "1/(" << c << " - cos x) at Cx = " << x << ": " << got.subs(at).evalf() << " vs "
                       << expected.subs(at).evalf());
    }
  }
  GiNaC::Digits = digits;
}

// Eq. 2 typed with its |cos x|: the top branch is the analytic one, and beyond b1/2 the load
// and both slope forms are the built-in's, exactly (one derivation, beyond_branch.hpp).
BOOST_AUTO_TEST_CASE(eq2_with_abs_equals_the_built_in_beyond_half) {
  const ProfileDerivation d =
      derive_profile({"wave", "H1*(m+1)*cos(x)/(m*abs(cos(x))+1)", {{"H1", numeric(1)}, {"m", numeric(1, 2)}}});
  const WavinessDerivation& w = [] {
    static const WavinessDerivation built_in = derive_waviness();
    return std::cref(built_in);
  }();
  BOOST_TEST_REQUIRE(d.branches.branched);
  BOOST_TEST(d.branches.cosine == 0);
  check_equal(as_built_in(d.branches.top, d), parametric_wave_curve(), "top branch");
  check_equal(as_built_in(single_term(d.forms.pressure_angle), d), single_term(w.pressure_angle), "pressure");
  check_equal(as_built_in(d.beyond.flank_g, d), w.beyond_half.flank_g, "flank g");
  check_equal(as_built_in(as_ex(d.beyond.load_angle), d), as_ex(w.beyond_half.load_angle), "load beyond b1/2");
  check_equal(as_built_in(as_ex(d.beyond.load_slope_factor), d), as_ex(w.beyond_half.load_slope_factor),
              "dP/dSa - dP/dCa beyond b1/2");
  check_equal(as_built_in(as_ex(d.beyond.load_slope_factor_by_parts), d),
              as_ex(w.beyond_half.load_slope_factor_by_parts), "the same by parts");
  // The flank's pole, cos x = 1/m: v^2 = (m-1)/(m+1) < 1, on the top's side, where the top holds
  // (the runtime bounds the reach by a flank pole beyond beta^2 = 1 only).
  BOOST_TEST_REQUIRE(d.flank_pole_squares.size() == 1u);
  check_equal(as_built_in(d.flank_pole_squares[0], d), (sym::m() - 1) / (sym::m() + 1), "flank pole");
}

BOOST_AUTO_TEST_CASE(parameter_samples_parse) {
  BOOST_TEST(parse_parameter("H3").sample == numeric(1, 2));
  BOOST_TEST(parse_parameter("H3=1/4").sample == numeric(1, 4));
  BOOST_TEST(parse_parameter("H3=0.125").sample == numeric(1, 8));
  BOOST_TEST(parse_parameter("H3=0.1").sample == numeric(1, 10));  // exact, not the double
  BOOST_CHECK_THROW(parse_parameter("H3=abc"), std::invalid_argument);
}

// The emitted Y(Cx) of a profile is the profile in Cx = cos x^ (cos 3x^ = 4 Cx^3 - 3 Cx),
// its slope dY/dCx, and the highest harmonic is 3.
BOOST_AUTO_TEST_CASE(profile_height_in_cos) {
  const ProfileDerivation d =
      derive_profile({"two_harmonic", "H1*cos(x)+H3*cos(3*x)", {{"H1", 1}, {"H3", numeric(1, 10)}}});
  const ex H1 = d.parameters[0], H3 = d.parameters[1], C = sym::Cx();
  check_equal(d.forms.height, H1 * C + H3 * (4 * pow(C, 3) - 3 * C), "Y(Cx)");
  check_equal(d.forms.height_slope, H1 + H3 * (12 * pow(C, 2) - 3), "dY/dCx");
  BOOST_TEST(d.forms.harmonic == 3);
  // A profile with a denominator: y = cos x/(2 - cos x), Y(C) = C/(2 - C).
  const ProfileDerivation bump = derive_profile({"bump", "cos(x)/(2-cos(x))", {}});
  check_equal(bump.forms.height, C / (2 - C), "Y(Cx) of cos x/(2 - cos x)");
  check_equal(bump.forms.height_slope, 2 / pow(2 - C, 2), "dY/dCx of cos x/(2 - cos x)");
}
