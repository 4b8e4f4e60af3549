// Symbolic regression tests of derive/: the derived formulas against independently
// written expectations (docs/mathematics.md, the seed's eq. 11, Westergaard, Hertz), in the manner
// of GiNaC's check/exam_*.cpp: (got - expected).normal() must be zero, and a failure
// prints the input, the result and the expectation.
#define BOOST_TEST_MODULE symbolic
#include <boost/test/unit_test.hpp>

#include <fstream>
#include <map>
#include <sstream>

#include "core/canonical.hpp"
#include "core/symbols.hpp"
#include "engine/hilbert.hpp"
#include "formulas/wave_curve.hpp"
#include "high_precision.hpp"
#include "profile/block_keer.hpp"

using namespace wavecontact::derive;
using GiNaC::ex;
using GiNaC::numeric;
using GiNaC::pow;
using GiNaC::sqrt;

namespace {

const WavinessDerivation& waviness() {
  static const WavinessDerivation d = derive_waviness();
  return d;
}

// GiNaC's exam style: zero after normal(), else print everything.
void check_equal(const ex& got, const ex& expected, const std::string& what) {
  const ex difference = (got - expected).normal();
  BOOST_TEST(difference.is_zero(),
             what << "\n  got:      " << got << "\n  expected: " << expected << "\n  difference: " << difference);
}

// p^(u)^2 from the engine's closed form: (alpha^2 - s) * inversion^2 with radicals squared.
ex pressure_squared(const RadicalSum& inversion, const Radicals& radicals) {
  const RadicalSum square = inversion.times(inversion, radicals);
  return (pow(sym::alpha(), 2) - sym::s()) * square.to_ex(radicals);
}

}  // namespace

BOOST_AUTO_TEST_CASE(kernel_identity_of_block_keer) {
  // cot((x - xi)/2) dxi = 2 [1/(v - u) + u/(1 + u^2)] du for v = tan(x/2), u = tan(xi/2):
  // cot(theta) = i (e^{2 i theta} + 1)/(e^{2 i theta} - 1), e^{i x} = (1 + i v)/(1 - i v).
  const ex u = sym::u(), v = sym::v();
  const ex z = exp_i(v) / exp_i(u);  // e^{i (x - xi)}
  const ex cot_half_difference = GiNaC::I * (z + 1) / (z - 1);
  const ex dxi_du = (2 * GiNaC::atan(u)).diff(sym::u());
  check_equal(cot_half_difference * dxi_du, 2 * (1 / (v - u) + u / (1 + pow(u, 2))), "kernel identity");
  // And e^{i x} = (1 + i v)/(1 - i v) really is v = tan(x/2): tan of its half angle.
  const ex half = (exp_i(v) - 1) / (GiNaC::I * (exp_i(v) + 1));  // tan(x/2) from e^{ix}
  check_equal(half, v, "tan(x/2) from e^{ix}");
}

BOOST_AUTO_TEST_CASE(half_angle_multiples_match_de_moivre_and_trig) {
  // cos(kx), sin(kx) against numerical evaluation at x = 0.7 for several k.
  const double x = 0.7;
  const ex v = std::tan(x / 2);
  for (long k : {1L, 2L, 3L, 7L, -2L}) {
    const double c = GiNaC::ex_to<numeric>(cos_multiple(k, v).evalf()).to_double();
    const double s = GiNaC::ex_to<numeric>(sin_multiple(k, v).evalf()).to_double();
    BOOST_TEST(c == std::cos(k * x), boost::test_tools::tolerance(1e-13));
    BOOST_TEST(s == std::sin(k * x), boost::test_tools::tolerance(1e-13));
  }
}

BOOST_AUTO_TEST_CASE(derived_g_is_eq_11) {
  // Eq. 11 as reconstructed in docs/mathematics.md.
  const ex v = sym::v(), m = sym::m();
  const ex eq11 = sym::E() * sym::H1() * (m + 1) * v * (1 + pow(v, 2)) / pow(m - m * pow(v, 2) + pow(v, 2) + 1, 2);
  check_equal(waviness().g, eq11, "g(v) of the parametric wave curve");
}

BOOST_AUTO_TEST_CASE(engine_rejects_even_and_non_rational_rhs) {
  Radicals radicals;
  BOOST_CHECK_THROW(bounded_inversion(pow(sym::v(), 2), radicals), std::invalid_argument);
  BOOST_CHECK_THROW(in_half_angle_tangent(sqrt(GiNaC::cos(sym::x()))), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(m_zero_is_westergaard) {
  // Westergaard (docs/mathematics.md fact 3), b1 = pi: p = E H1 cos(x/2) sqrt(sin^2(a/2) - sin^2(x/2)),
  // P = pi E H1 sin^2(a/2); in v-variables cos^2(x/2) = 1/(1+s), sin^2(a/2) = alpha^2/(1+alpha^2).
  const auto& d = waviness();
  const ex s = sym::s(), alpha2 = pow(sym::alpha(), 2), EH = sym::E() * sym::H1();
  const GiNaC::exmap m0{{sym::m(), 0}};
  const ex westergaard_squared = pow(EH, 2) / (1 + s) * (alpha2 / (1 + alpha2) - s / (1 + s));
  check_equal(pressure_squared(d.inversion, d.radicals).subs(m0), westergaard_squared, "exact p^2 at m = 0");
  check_equal(pressure_squared(d.paper_inversion, d.radicals).subs(m0), westergaard_squared, "printed p^2 at m = 0");
  check_equal(d.load.with_roots(d.radicals).subs(m0), GiNaC::Pi * EH * alpha2 / (1 + alpha2), "load at m = 0");
}

BOOST_AUTO_TEST_CASE(small_contact_is_hertz) {
  // Small a: p -> (E*/(2R)) sqrt(a^2 - x^2) with R = b1^2 (m+1)/(pi^2 H1) (= (m+1)/H1 at b1 = pi),
  // a = 2 alpha, x = 2u to leading order; P -> pi E* a^2/(4R).
  const auto& d = waviness();
  const GiNaC::symbol epsilon("epsilon"), A("A"), U("U");
  const GiNaC::exmap scaling{{sym::alpha(), epsilon * A}, {sym::s(), pow(epsilon * U, 2)}};
  const ex R = (sym::m() + 1) / sym::H1();
  const ex inversion = d.inversion.with_roots(d.radicals).subs(scaling);
  const ex leading = inversion.series(epsilon, 1).coeff(epsilon, 0);
  // sqrt(a^2 - x^2) = 2 sqrt(alpha^2 - u^2): p^ = (E/(2R)) 2 sqrt(...) = (E/R) sqrt(alpha^2 - u^2).
  check_equal(leading, sym::E() / R, "leading term of p^/sqrt(alpha^2 - u^2)");
  const ex load = d.load.with_roots(d.radicals).subs(scaling);
  const ex load_leading = load.series(epsilon, 3).coeff(epsilon, 2);
  check_equal(load_leading, GiNaC::Pi * sym::E() * pow(2 * A, 2) / (4 * R), "leading load");
}

BOOST_AUTO_TEST_CASE(printed_eq13_has_the_exact_load) {
  const auto& d = waviness();
  check_equal(d.paper_load.with_roots(d.radicals), d.load.with_roots(d.radicals),
              "load of the printed eq. 13 against the exact load");
  // ... while the pressures differ for m != 0.
  const ex difference =
      (pressure_squared(d.inversion, d.radicals) - pressure_squared(d.paper_inversion, d.radicals)).normal();
  BOOST_TEST(!difference.is_zero());
}

// The forward transform (1/pi) PV Int p(u)/(v - u) du at 40 digits by the midpoint rule
// in u = alpha cos(theta) (PV Int_0^pi dtheta/(v - alpha cos theta) = 0 for |v| < alpha):
// (1/pi) Int_0^pi (F(alpha cos theta) - F(v))/(v - alpha cos theta) dtheta, F = (alpha^2 - u^2) I(u^2).
numeric forward_transform(const ex& inversion, const GiNaC::exmap& parameters, const numeric& alpha, const numeric& v,
                          int nodes) {
  const GiNaC::symbol uu("uu");
  const ex F = ((pow(alpha, 2) - pow(uu, 2)) * inversion.subs(parameters).subs(sym::s() == pow(uu, 2)))
                   .subs(sym::alpha() == alpha);
  const numeric Fv = GiNaC::ex_to<numeric>(F.subs(uu == v).evalf());
  numeric sum = 0;
  for (int k = 0; k < nodes; ++k) {
    const numeric c = GiNaC::ex_to<numeric>(GiNaC::cos(GiNaC::Pi * (k + numeric(1, 2)) / nodes).evalf());
    const numeric u = alpha * c;
    sum += (GiNaC::ex_to<numeric>(F.subs(uu == u).evalf()) - Fv) / (v - u);
  }
  return sum / nodes;
}

BOOST_AUTO_TEST_CASE(exact_pressure_satisfies_eq5_and_printed_does_not) {
  const auto& d = waviness();
  wavecontact::test::Precision precision(wavecontact::test::reference_digits);
  const numeric alpha(7, 10);
  for (const numeric& m : {numeric(0), numeric(1, 2), numeric(2), numeric(10)}) {
    const GiNaC::exmap parameters{{sym::m(), m}, {sym::E(), 1}, {sym::H1(), 1}, {sym::alpha(), alpha}};
    const ex exact = d.inversion.with_roots(d.radicals);
    const ex printed = d.paper_inversion.with_roots(d.radicals);
    for (const numeric& v : {numeric(1, 10), numeric(4, 10), numeric(65, 100)}) {
      const numeric g = GiNaC::ex_to<numeric>(d.g.subs(parameters).subs(sym::v() == v).evalf());
      const numeric exact_residual = GiNaC::abs(forward_transform(exact, parameters, alpha, v, 96) - g) / g;
      const numeric printed_residual = GiNaC::abs(forward_transform(printed, parameters, alpha, v, 96) - g) / g;
      BOOST_TEST_MESSAGE("m = " << m << ", v = " << v << ": eq. 5 residual exact " << exact_residual.to_double()
                                << ", printed " << printed_residual.to_double());
      BOOST_TEST(exact_residual.to_double() < 1e-30);
      if (m.is_zero()) {
        BOOST_TEST(printed_residual.to_double() < 1e-30);
      } else {
        BOOST_TEST(printed_residual.to_double() > 1e-3);  // the printed eq. 13 fails eq. 5
      }
    }
  }
}

BOOST_AUTO_TEST_CASE(angle_forms_equal_v_forms) {
  const auto& d = waviness();
  const std::vector<std::pair<const std::vector<RootTerm>*, const std::vector<RootTerm>*>> pairs{
      {&d.pressure_v, &d.pressure_angle},
      {&d.paper_pressure_v, &d.paper_pressure_angle},
      {&d.load_v, &d.load_angle},
      {&d.pa_over_pstar_v, &d.pa_over_pstar_angle}};
  for (const auto& [v_form, angle_form] : pairs) {
    BOOST_TEST_REQUIRE(v_form->size() == angle_form->size());
    for (std::size_t i = 0; i < v_form->size(); ++i) {
      bool sign_agrees = false;
      const ex residual = angle_form_residual((*v_form)[i], (*angle_form)[i], sign_agrees);
      BOOST_TEST(residual.is_zero(),
                 "angle form " << as_ex((*angle_form)[i]) << " of " << as_ex((*v_form)[i]) << ": " << residual);
      BOOST_TEST(sign_agrees);
    }
  }
}

BOOST_AUTO_TEST_CASE(manifest_matches_the_engine) {
  const auto& d = waviness();
  GiNaC::symtab table;
  for (const auto& s : {sym::x(), sym::v(), sym::s(), sym::alpha(), sym::m(), sym::E(), sym::H1(), sym::b1(), sym::Ca(),
                        sym::Sa(), sym::Cx(), sym::Sx(), sym::D()}) {
    table[s.get_name()] = s;
  }
  table["Pi"] = GiNaC::Pi;
  for (unsigned i = 0; i < d.radicals.size(); ++i) table[d.radicals.symbol(i).get_name()] = d.radicals.symbol(i);
  GiNaC::parser reader(table, true);

  std::map<std::string, ex> derived;
  for (unsigned i = 0; i < d.radicals.size(); ++i) {
    derived[d.radicals.symbol(i).get_name() + ".pole"] = d.radicals.pole(i);
    derived[d.radicals.symbol(i).get_name() + ".square"] = d.radicals.square(i);
  }
  derived["waviness.profile"] = d.profile;
  derived["waviness.g"] = d.g;
  auto add_sum = [&](const std::string& name, const RadicalSum& sum) {
    for (const auto& [mask, c] : sum.terms()) {
      std::string monomial;
      for (unsigned i = 0; i < d.radicals.size(); ++i) {
        if (mask & (RadicalSum::Mask{1} << i)) {
          monomial += (monomial.empty() ? "" : "*") + d.radicals.symbol(i).get_name();
        }
      }
      derived[name + "[" + (monomial.empty() ? "1" : monomial) + "]"] = c;
    }
  };
  add_sum("waviness.inversion.exact", d.inversion);
  add_sum("waviness.inversion.paper", d.paper_inversion);
  add_sum("waviness.load.exact", d.load);
  add_sum("waviness.load.paper", d.paper_load);
  auto add_terms = [&](const std::string& name, const std::vector<RootTerm>& terms) {
    BOOST_TEST_REQUIRE(terms.size() == 1u);
    derived[name + ".rational"] = terms[0].rational;
    derived[name + ".radicand"] = terms[0].radicand;
  };
  add_terms("waviness.pressure.exact.angle", d.pressure_angle);
  add_terms("waviness.pressure.paper.angle", d.paper_pressure_angle);
  add_terms("waviness.load.angle", d.load_angle);
  add_terms("waviness.pa_over_pstar.angle", d.pa_over_pstar_angle);
  add_terms("waviness.load_slope_factor.angle", d.load_slope_factor);
  derived["waviness.height"] = d.height;
  derived["waviness.height_slope"] = d.height_slope;
  derived["waviness.flank.g"] = d.beyond_half.flank_g;
  derived["waviness.top_piece_argument"] = d.beyond_half.top_piece_argument;
  auto add_moments = [&](const std::string& name, const std::vector<MomentTerm>& terms) {
    for (std::size_t i = 0; i < terms.size(); ++i) {
      const std::string prefix = name + "[" + std::to_string(i) + "]";
      derived[prefix + ".rational"] = terms[i].rational;
      derived[prefix + ".radicand"] = terms[i].radicand;
      if (terms[i].l == 0) continue;
      derived[prefix + ".j"] = terms[i].j;
      derived[prefix + ".l"] = terms[i].l;
      derived[prefix + ".z"] = terms[i].z;
      derived[prefix + ".one_plus_z"] = terms[i].one_plus_z;
      if (!terms[i].cauchy) continue;
      derived[prefix + ".y"] = terms[i].y;
      derived[prefix + ".one_plus_y"] = terms[i].one_plus_y;
    }
  };
  add_moments("waviness.load.beyond_half", d.beyond_half.load_v);
  add_moments("waviness.load.beyond_half.angle", d.beyond_half.load_angle);
  add_moments("waviness.load_slope_factor.beyond_half.angle", d.beyond_half.load_slope_factor);
  add_moments("waviness.load.near_half.angle", d.beyond_half.load_near_branch_angle);
  add_moments("waviness.load_slope_factor.by_parts", d.beyond_half.load_slope_factor_by_parts_v);
  add_moments("waviness.load_slope_factor.by_parts.angle", d.beyond_half.load_slope_factor_by_parts);
  for (const bool top : {true, false}) {
    const auto& side = top ? d.beyond_half.pressure_top_v : d.beyond_half.pressure_flank_v;
    const std::string name = std::string("waviness.pressure.beyond_half.") + (top ? "top" : "flank");
    add_moments(name + ".own", side.own);
    add_moments(name + ".own_edge", side.own_edge);
    add_moments(name + ".other_cauchy", side.other_cauchy);
    add_moments(name + ".other_cauchy_edge", side.other_cauchy_edge);
    add_moments(name + ".other", side.other);
    add_moments(name + ".other_edge", side.other_edge);
    add_moments(name + ".jump", side.jump);
  }

  std::ifstream manifest(WAVECONTACT_SOURCE_DIR "/generated/manifest.txt");
  BOOST_TEST_REQUIRE(manifest.good());
  std::size_t entries = 0;
  for (std::string line; std::getline(manifest, line);) {
    if (line.empty() || line[0] == '#') continue;
    const auto eq = line.find(" = ");
    BOOST_TEST_REQUIRE(eq != std::string::npos, line);
    const std::string name = line.substr(0, eq);
    const auto it = derived.find(name);
    const bool known = it != derived.end();
    BOOST_TEST(known, "manifest entry " << name << " is not derived");
    if (it == derived.end()) continue;
    check_equal(reader(line.substr(eq + 3)), it->second, "manifest entry " + name);
    ++entries;
  }
  BOOST_TEST(entries == derived.size(), "every derived expression is in the manifest");
}

// The emitted dP/da: sin(a^) (dP/dSa - dP/dCa) of the angle form equals d/da^ of the v-form
// load, dP/dalpha * dalpha/da^ = dP/dalpha (1 + alpha^2)/2, at points of the domain (40 digits).
BOOST_AUTO_TEST_CASE(load_slope_factor_is_the_derivative) {
  const WavinessDerivation& d = waviness();
  const ex alpha = sym::alpha();
  ex load_v = 0, factor = 0;
  for (const auto& term : d.load_v) load_v += as_ex(term);
  for (const auto& term : d.load_slope_factor) factor += as_ex(term);
  const ex expected = load_v.diff(sym::alpha()) * (1 + pow(alpha, 2)) / 2;
  const ex got = 2 * alpha / (1 + pow(alpha, 2)) * atoms_in_v_variables(factor);  // sin a^
  const long digits = GiNaC::Digits;
  GiNaC::Digits = 40;
  const numeric tolerance = GiNaC::ex_to<numeric>(pow(numeric(10), -30));
  for (const numeric& m : {numeric(0), numeric(1, 5), numeric(3), numeric(35)}) {
    for (const numeric& a : {numeric(1, 10), numeric(1, 2), numeric(9, 10)}) {
      const GiNaC::lst point{alpha == a, sym::m() == m, sym::E() == numeric(3, 2), sym::H1() == numeric(2, 3)};
      const ex difference = (got.subs(point) - expected.subs(point)).evalf();
      const ex scale = expected.subs(point).evalf();
      BOOST_TEST(GiNaC::ex_to<numeric>(GiNaC::abs(difference / scale).evalf()) < tolerance,
                 "m = " << m << ", alpha = " << a << ": got " << got.subs(point).evalf() << ", expected " << scale);
    }
  }
  GiNaC::Digits = digits;
}

// The surface as the multi-zone solver sees it: Y(cos x^) is the profile of eq. 2 (its
// analytic branch) and height_slope is dY/ds, checked against the profile itself.
BOOST_AUTO_TEST_CASE(height_in_cos_is_the_profile) {
  const WavinessDerivation& d = waviness();
  const ex c = GiNaC::cos(sym::x());
  check_equal(d.height.subs(sym::Cx() == c), parametric_wave_curve(), "Y(cos x^)");
  // dy/dx^ = Y'(cos x^) (-sin x^).
  check_equal(-d.height_slope.subs(sym::Cx() == c) * GiNaC::sin(sym::x()), parametric_wave_curve().diff(sym::x()),
              "Y'(cos x^) d(cos x^)/dx^");
  BOOST_TEST(d.harmonic == 1);
}
