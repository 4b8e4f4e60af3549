// The engine over part of a zone (derive/engine/sub_interval.hpp), at 40 digits:
// - the moments over [0, beta] and [beta, alpha] add up to the engine's whole moment;
// - the load from g alone, 2 pi sqrt(1 + alpha^2) M[v g/(1 + v^2)] (docs/mathematics.md fact 7), is the
//   engine's load of the wave curve (eq. 6 applied to the inversion), a <= b1/2;
// - the load's slope from g alone, (pi/2) sqrt(1 + alpha^2) M[(1 + v^2) g' + v g] sin(a^), is
//   the derivative of the load, within the zone's top branch and beyond b1/2;
// - the large-argument form of a moment equals the moment;
// - beyond b1/2 the derived load in v-variables equals its angle form, and both forms of it;
// - beyond b1/2 the derived pressure, in each of its four assemblies (the other piece with its
//   Cauchy factor or with the jump apart, each piece in I_{j,l} or the edge basis), is eq. 12 by
//   an independent tanh-sinh quadrature at 50 digits, on both sides of the kink.
#define BOOST_TEST_MODULE sub_interval
#include <boost/test/unit_test.hpp>

#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "core/symbols.hpp"
#include "emit/shared_pieces.hpp"
#include "engine/hilbert.hpp"
#include "engine/radicals.hpp"
#include "engine/sub_interval.hpp"
#include "formulas/wave_curve.hpp"
#include "tanh_sinh_reference.hpp"

using namespace wavecontact::derive;
using GiNaC::ex;
using GiNaC::numeric;
using wavecontact::test::tanh_sinh;

namespace {

struct Digits {
  explicit Digits(int digits) : saved(GiNaC::Digits) { GiNaC::Digits = digits; }
  ~Digits() { GiNaC::Digits = saved; }
  long saved;
};

numeric value(const ex& e, const GiNaC::exmap& point) { return GiNaC::ex_to<numeric>(e.subs(point).evalf()); }

std::string text(const numeric& q) {
  std::ostringstream os;
  os << q;
  return os.str();
}

void check_close(const numeric& got, const numeric& expected, const std::string& what) {
  const double relative = (GiNaC::abs(got - expected) / GiNaC::abs(expected)).to_double();
  BOOST_TEST(relative < 1e-35, what << ": " << got << " vs " << expected);
}

const WavinessDerivation& waviness() {
  static const WavinessDerivation d = derive_waviness();
  return d;
}

// dP/da^ / sin(a^) from the load's derivative in alpha: da^/dalpha = 2/(1 + alpha^2),
// sin(a^) = 2 alpha/(1 + alpha^2).
ex slope_factor_of(const ex& load) {
  const GiNaC::symbol& alpha = sym::alpha();
  return load.diff(alpha) * GiNaC::pow(1 + alpha * alpha, 2) / (4 * alpha);
}

}  // namespace

BOOST_AUTO_TEST_CASE(pressure_beyond_half_is_eq12) {
  const Digits digits(50);
  const WavinessDerivation& d = waviness();
  const GiNaC::symbol &v = sym::v(), &t = sym::t();
  const ex s = sym::s();
  const ex f_top = even_in_square(v * d.beyond_half.top_g, v, t);
  const ex f_flank = even_in_square(v * d.beyond_half.flank_g, v, t);
  for (const numeric& m : {numeric(1, 2), numeric(2), numeric(35)}) {
    for (const numeric& alpha : {numeric(3, 2), numeric(3)}) {
      for (const numeric& u : {numeric(1, 2), numeric(99, 100), numeric(5, 4)}) {
        const bool on_top = u < 1;
        // (f(t) - f(s))/(t - s) with t - s divided out where t and s lie on one branch.
        const ex own = on_top ? f_top : f_flank;
        const ex same = ((own - own.subs(t == s)) / (t - s)).normal().subs(s == u * u).subs(sym::m() == m);
        const ex across = ((on_top ? f_flank : f_top) - own.subs(t == s)) / (t - s);
        const ex other = across.subs(s == u * u).subs(sym::m() == m);
        const GiNaC::exmap parameters{{sym::E(), numeric(3, 2)}, {sym::H1(), numeric(2, 3)}};
        const auto integrand = [&](const numeric& theta) {  // v = alpha sin(theta)
          const numeric sine = alpha * GiNaC::sin(theta), tt = sine * sine;
          return GiNaC::ex_to<numeric>(((tt < 1) == on_top ? same : other).subs(parameters).subs(t == tt).evalf());
        };
        const numeric kink = GiNaC::asin(numeric(1) / alpha);
        const numeric eq12 = GiNaC::sqrt(alpha * alpha - u * u) * 2 / GiNaC::ex_to<numeric>(GiNaC::Pi.evalf()) *
                             (tanh_sinh(integrand, 0, kink) +
                              tanh_sinh(integrand, kink, GiNaC::ex_to<numeric>((GiNaC::Pi / 2).evalf())));
        const auto& side = on_top ? d.beyond_half.pressure_top_v : d.beyond_half.pressure_flank_v;
        GiNaC::exmap point{{sym::alpha(), alpha}, {sym::s(), u * u}, {sym::m(), m}, {sym::b1(), GiNaC::Pi}};
        point.insert(parameters.begin(), parameters.end());
        const std::string where = "m = " + text(m) + ", alpha = " + text(alpha) + ", u = " + text(u);
        for (const bool edge : {false, true}) {
          const ex own_piece = as_ex(edge ? side.own_edge : side.own);
          const ex cauchy = own_piece + as_ex(edge ? side.other_cauchy_edge : side.other_cauchy);
          const ex jump = own_piece + as_ex(edge ? side.other_edge : side.other) + as_ex(side.jump);
          check_close(value(cauchy, point), eq12, "Cauchy factor kept, " + where);
          check_close(value(jump, point), eq12, "jump apart, " + where);
        }
      }
    }
  }
}

BOOST_AUTO_TEST_CASE(pieces_add_up_to_the_whole_moment) {
  const Digits digits(40);
  const ex t = sym::t();
  // Poles off [0, alpha^2] (a double pole at t = -3, a simple one at t = -2) and a polynomial:
  // one factor in tan^2(phi) on either piece, as the engine requires.
  for (const ex& Phi : {ex(t / GiNaC::pow(3 + t, 2)), ex(1 / (2 + t)), ex(t * t + 3)}) {
    Radicals radicals;
    const ex whole = weighted_moment(RadicalSum::rational(Phi), radicals).with_roots(radicals);
    for (const numeric& alpha : {numeric(7, 10), numeric(13, 10)}) {
      const numeric beta = alpha / 2;
      const GiNaC::exmap point{{sym::alpha(), alpha}};
      const ex pieces = as_ex(inner_moment(Phi, beta)) + as_ex(outer_moment(Phi, beta));
      std::ostringstream what;
      what << "M[" << Phi << "] at alpha = " << alpha;
      check_close(value(pieces, point), value(whole, point), what.str());
    }
  }
}

BOOST_AUTO_TEST_CASE(load_from_g_alone_is_the_engines_load) {
  const Digits digits(40);
  const WavinessDerivation& d = waviness();
  Radicals radicals = d.radicals;
  const ex from_g = 2 * GiNaC::Pi * GiNaC::sqrt(1 + GiNaC::pow(sym::alpha(), 2)) *
                    weighted_moment(RadicalSum::rational(load_integrand(d.g)), radicals).with_roots(radicals);
  const ex engine = d.load.with_roots(d.radicals);
  for (const numeric& m : {numeric(0), numeric(1, 2), numeric(3), numeric(40)}) {
    for (const numeric& alpha : {numeric(1, 10), numeric(3, 5), numeric(99, 100)}) {
      const GiNaC::exmap point{
          {sym::alpha(), alpha}, {sym::m(), m}, {sym::E(), numeric(3, 2)}, {sym::H1(), numeric(2, 3)}};
      check_close(value(from_g, point), value(engine, point), "load at m = " + text(m));
    }
  }
}

BOOST_AUTO_TEST_CASE(load_slope_from_g_alone_is_the_loads_derivative) {
  const Digits digits(40);
  const WavinessDerivation& d = waviness();
  Radicals radicals = d.radicals;
  const ex whole = GiNaC::Pi / 2 * GiNaC::sqrt(1 + GiNaC::pow(sym::alpha(), 2)) *
                   weighted_moment(RadicalSum::rational(load_slope_integrand(d.g)), radicals).with_roots(radicals);
  const ex whole_expected = slope_factor_of(d.load.with_roots(d.radicals));
  const ex pieces = as_ex(d.beyond_half.load_slope_factor_by_parts_v);
  const ex pieces_expected = slope_factor_of(as_ex(d.beyond_half.load_v));
  for (const numeric& m : {numeric(0), numeric(1, 2), numeric(3), numeric(40)}) {
    const auto at = [&m](const numeric& alpha) {
      return GiNaC::exmap{{sym::alpha(), alpha}, {sym::m(), m}, {sym::E(), numeric(3, 2)}, {sym::H1(), numeric(2, 3)}};
    };
    for (const numeric& alpha : {numeric(1, 10), numeric(3, 5), numeric(99, 100)}) {
      check_close(value(whole, at(alpha)), value(whole_expected, at(alpha)),
                  "dP/da^ at m = " + text(m) + ", alpha = " + text(alpha));
    }
    for (const numeric& alpha : {numeric(1000001, 1000000), numeric(3, 2), numeric(20)}) {
      check_close(value(pieces, at(alpha)), value(pieces_expected, at(alpha)),
                  "dP/da^ beyond b1/2 at m = " + text(m) + ", alpha = " + text(alpha));
    }
  }
}

BOOST_AUTO_TEST_CASE(large_argument_form_is_the_moment) {
  const Digits digits(40);
  const MomentTerm term = moment_term(numeric(3, 7), 1 + sym::alpha(), 1, 2, sym::alpha() * 5, 1 + sym::alpha() * 5);
  for (const numeric& alpha : {numeric(1, 3), numeric(2), numeric(50)}) {
    const GiNaC::exmap point{{sym::alpha(), alpha}};
    check_close(value(as_ex(large_argument_form(term)), point), value(as_ex(term), point),
                "I_{1,2} at z = " + text(5 * alpha));
  }
}

// The derived load beyond b1/2: v-form = angle form (a^ = 2 atan(alpha)), near-half form =
// direct form, and continuity with the closed form below b1/2 at a = b1/2.
BOOST_AUTO_TEST_CASE(beyond_half_forms_agree) {
  const Digits digits(40);
  const WavinessDerivation& d = waviness();
  for (const numeric& m : {numeric(0), numeric(1, 5), numeric(1), numeric(7), numeric(300)}) {
    for (const numeric& alpha : {numeric(1000001, 1000000), numeric(3, 2), numeric(20)}) {
      const numeric Ca = (1 - alpha * alpha) / (1 + alpha * alpha);
      const GiNaC::exmap v_point{{sym::alpha(), alpha}, {sym::m(), m}, {sym::E(), 1}, {sym::H1(), 1}};
      const GiNaC::exmap angle_point{
          {sym::Ca(), Ca}, {sym::Sa(), 1 - Ca}, {sym::m(), m}, {sym::E(), 1}, {sym::H1(), 1}};
      const numeric v_form = value(as_ex(d.beyond_half.load_v), v_point);
      const std::string where = "m = " + text(m) + ", alpha = " + text(alpha);
      check_close(value(as_ex(d.beyond_half.load_angle), angle_point), v_form, "angle form, " + where);
      if (value(d.beyond_half.top_piece_argument, angle_point) > 0) {  // where the near-half form holds
        check_close(value(as_ex(d.beyond_half.load_near_branch_angle), angle_point), v_form,
                    "near-half form, " + where);
      }
      check_close(value(as_ex(d.beyond_half.load_slope_factor_by_parts), angle_point),
                  value(as_ex(d.beyond_half.load_slope_factor), angle_point), "slope forms, " + where);
    }
  }
  // At a = b1/2 (Ca = 0-) the near-half form joins the closed form below b1/2: they differ by
  // the flank's part, of order (-Ca)^(3/2).
  const numeric Ca = GiNaC::ex_to<numeric>(GiNaC::pow(numeric(10), -20)) * -1, m = 3;
  const GiNaC::exmap point{{sym::Ca(), Ca}, {sym::Sa(), 1 - Ca}, {sym::m(), m}, {sym::E(), 1}, {sym::H1(), 1}};
  const ex below = single_term(d.load_angle);
  const double jump =
      (GiNaC::abs(value(as_ex(d.beyond_half.load_near_branch_angle), point) - value(below, point))).to_double();
  BOOST_TEST(jump < 1e-27, "load across b1/2: " << jump);
}
