// The harmonic part of a profile (derive/profile/harmonic_part.hpp): y = sum_k A_k cos(k x^) + R(cos x^).
// - the profile in cos x^ and its cosine coefficients reproduce the profile exactly, up to
//   order 256;
// - the split derivation (Legendre-Dirichlet form of the cosine sum + the engine's closed
//   form of R) equals the whole profile through the engine's partial fractions: pressure,
//   load, dP/da, height and slope agree to 35 digits at points of the domain;
// - what is split and what is kept whole.
#define BOOST_TEST_MODULE harmonic_part
#include <boost/test/unit_test.hpp>

#include <string>
#include <vector>

#include "core/symbols.hpp"
#include "emit/shared_pieces.hpp"
#include "engine/closed_forms.hpp"
#include "formulas/user_profile.hpp"
#include "profile/block_keer.hpp"
#include "profile/harmonic_part.hpp"

using namespace wavecontact::derive;
using GiNaC::ex;
using GiNaC::numeric;

namespace {

// T_0..T_K at a rational c, exactly.
std::vector<numeric> chebyshev_values(int K, const numeric& c) {
  std::vector<numeric> T{1, c};
  for (int k = 1; k < K; ++k) T.push_back(2 * c * T[k] - T[k - 1]);
  return T;
}

// y(x^) at cos x^ = c (0 < x^ < pi), at 50 digits, straight from the expression.
numeric profile_at(const ex& y, const numeric& c) {
  return GiNaC::ex_to<numeric>(y.subs(sym::x() == GiNaC::acos(c)).evalf());
}

struct Digits {
  explicit Digits(int digits) : saved(GiNaC::Digits) { GiNaC::Digits = digits; }
  ~Digits() { GiNaC::Digits = saved; }
  long saved;
};

}  // namespace

// Y(c) and sum_k A_k T_k(c) + R(c) against y itself at points of the period, and the sum
// against Y exactly at K + 2 rational points (two polynomials of degree K agreeing at K + 1
// points are equal).
BOOST_AUTO_TEST_CASE(cosine_coefficients_reproduce_the_profile) {
  const Digits digits(50);
  const std::vector<std::string> profiles{"cos(x)^256",
                                          "cos(x)+cos(256*x)/4",
                                          "(cos(x)+1/3)^100",
                                          "sin(x)^2*cos(7*x)^10",
                                          "sin(x)*sin(3*x)+cos(2*x)",
                                          "cos(x)^9+cos(x)/(2-cos(x))",
                                          "(cos(3*x)^5+1)/(3+cos(x))"};
  for (const std::string& text : profiles) {
    const ex y = GiNaC::parser(GiNaC::symtab{{"x", sym::x()}})(text);
    const ex Y = in_cosine(y);
    const HarmonicSplit split = split_harmonic_part(Y);
    BOOST_TEST_REQUIRE(!split.cosine.empty(), text);
    const int K = static_cast<int>(split.cosine.size()) - 1;
    for (const numeric& c : {numeric(-9, 10), numeric(1, 7), numeric(99, 100)}) {
      const numeric direct = profile_at(y, c);
      const numeric in_cos = GiNaC::ex_to<numeric>(Y.subs(sym::Cx() == c).evalf());
      const double deviation = GiNaC::abs(in_cos - direct).to_double();
      BOOST_TEST(deviation < 1e-40, text << ": Y(" << c << ") = " << in_cos << ", y = " << direct);
    }
    for (int i = 0; i <= K + 1; ++i) {
      const numeric c = numeric(2 * i - K - 1, K + 3);  // in (-1, 1)
      const std::vector<numeric> T = chebyshev_values(K, c);
      numeric sum = 0;
      for (int k = 0; k <= K; ++k) sum += GiNaC::ex_to<numeric>(split.cosine[k]) * T[k];
      const ex rest = split.rational.subs(sym::Cx() == c);
      BOOST_TEST((sum + rest - Y.subs(sym::Cx() == c)).is_zero(), text << " at c = " << c);
    }
  }
}

BOOST_AUTO_TEST_CASE(what_is_split_and_what_is_kept_whole) {
  const GiNaC::realsymbol m("m"), H("H");
  const ex c = sym::Cx();
  // A cosine sum over nothing, and over a number-led denominator: split.
  BOOST_TEST(split_harmonic_part(c * c * c).rational.is_zero());
  const HarmonicSplit bump = split_harmonic_part(c * c / (2 - c));
  BOOST_TEST(bump.cosine.size() == 2u);
  BOOST_TEST(
      (bump.cosine[0] + bump.cosine[1] * c + bump.rational - c * c / (2 - c)).normal().is_zero(),
      "T_0, T_1 and the rest of c^2/(2 - c): " << bump.cosine[0] << ", " << bump.cosine[1] << ", " << bump.rational);
  // The wave curve's denominator m c + 1: its polynomial part would carry 1/m.
  const ex wave = H * (m + 1) * c / (m * c + 1);
  BOOST_TEST(split_harmonic_part(wave).cosine.empty());
  BOOST_TEST((split_harmonic_part(wave).rational - wave).normal().is_zero());
  // A denominator free of c is the profile's own: c^2/H = (T_0 + T_2)/(2H) splits.
  const HarmonicSplit scaled = split_harmonic_part(c * c / H);
  BOOST_TEST_REQUIRE(scaled.cosine.size() == 3u);
  BOOST_TEST((scaled.cosine[2] - 1 / (2 * H)).normal().is_zero(), scaled.cosine[2]);
  // Only a constant beyond the proper part (cos x/(2 - cos x) = -1 + 2/(2 - cos x)): whole.
  BOOST_TEST(split_harmonic_part(c / (2 - c)).cosine.empty());
  // Odd profiles are not profiles.
  BOOST_CHECK_THROW(in_cosine(GiNaC::sin(sym::x())), std::invalid_argument);
  BOOST_CHECK_THROW(in_cosine(GiNaC::sin(3 * sym::x()) * GiNaC::cos(sym::x())), std::invalid_argument);
}

// The Legendre-Dirichlet form of the cosine sum plus the engine's closed form of R against
// the engine's partial fractions on the whole profile, at 40 digits, at zones on both sides
// of a = b1/2 (the cosine sums are analytic over the whole period).
BOOST_AUTO_TEST_CASE(split_equals_the_whole_profile_through_the_engine) {
  const Digits digits(40);
  struct Case {
    std::string expression;
    std::vector<ProfileParameter> parameters;
  };
  const std::vector<Case> cases{
      {"H1*cos(x)+H3*cos(3*x)", {{"H1", numeric(2, 3)}, {"H3", numeric(1, 7)}}},
      {"H*cos(x)^6", {{"H", numeric(3, 5)}}},
      {"H*cos(x)^3+c*cos(x)/(2-cos(x))", {{"H", numeric(3, 5)}, {"c", numeric(-1, 9)}}},
      {"sin(x)*sin(2*x)+H*cos(4*x)", {{"H", numeric(1, 3)}}},
      {"(cos(x)^4+c*cos(2*x))/(3+cos(x))", {{"c", numeric(2, 7)}}},
  };
  for (const Case& test : cases) {
    const ProfileDerivation d = derive_profile({"p", test.expression, test.parameters});
    BOOST_TEST_REQUIRE(!d.forms.cosine.empty(), test.expression);
    const ClosedForms whole = derive_closed_forms(d.forms.profile, {{}, d.forms.height}, d.sample);
    const ex scale = GiNaC::Pi / sym::b1();
    const std::pair<ex, ex> quantities[] = {
        {scale * harmonic_pressure(d.forms.cosine) + single_term(d.forms.pressure_angle),
         single_term(whole.pressure_angle)},
        {harmonic_load(d.forms.cosine) + single_term(d.forms.load_angle), single_term(whole.load_angle)},
        {harmonic_load_slope_factor(d.forms.cosine) + single_term(d.forms.load_slope_factor),
         single_term(whole.load_slope_factor)},
    };
    // (Ca, Cx) with Cx > Ca: a^ = 1.2 and 2.2 (beyond pi/2).
    for (const auto& [Ca, Cx] : {std::pair{numeric(1, 3), numeric(3, 4)}, std::pair{numeric(-3, 5), numeric(1, 5)},
                                 std::pair{numeric(-1, 2), numeric(-2, 5)}}) {
      GiNaC::exmap point = d.sample;
      point[sym::Ca()] = Ca;
      point[sym::Sa()] = 1 - Ca;
      point[sym::Cx()] = Cx;
      point[sym::Sx()] = 1 - Cx;
      point[sym::D()] = Cx - Ca;
      for (const auto& [split, expected] : quantities) {
        const numeric got = GiNaC::ex_to<numeric>(split.subs(point).evalf());
        const numeric want = GiNaC::ex_to<numeric>(expected.subs(point).evalf());
        const double relative = (GiNaC::abs(got - want) / GiNaC::abs(want)).to_double();
        BOOST_TEST(relative < 1e-35,
                   test.expression << " at Ca = " << Ca << ", Cx = " << Cx << ": split " << got << ", whole " << want);
      }
    }
    // The profile and its slope: the cosine sum plus R is Y.
    ex sum = d.forms.rational_height;
    for (std::size_t k = 0; k < d.forms.cosine.size(); ++k) {
      sum += d.forms.cosine[k] * GiNaC::cos(static_cast<long>(k) * sym::x());
    }
    BOOST_TEST((in_cosine(sum.subs(sym::Cx() == GiNaC::cos(sym::x()))) - d.forms.height).normal().is_zero(),
               test.expression);
  }
}
