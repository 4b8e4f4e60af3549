// Full contact in closed form for profiles built with abs() (derive/formulas/full_contact.hpp), at 50
// digits, against an independent quadrature of the derivative of the conjugate function:
//   p_fc(x^) = (E*/2)(pi/b1) (1/(2 pi)) Int_{-pi}^{pi} (y'(xi) - y'(x^)) cot((x^ - xi)/2) dxi,
// with y' written here by hand and the integral split at the branch points and at x^ (its
// integrand is bounded, with kinks there): the whole form everywhere, the form of the point's
// side (the other piece's Cauchy factor kept) off the branch point, including next to the poles
// of the other branch's formula. The same reference checks the rational profile's residue form
// first, which tests/branch_profile_test.cpp checks against cosine coefficients.
#define BOOST_TEST_MODULE full_contact
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <functional>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "core/symbols.hpp"
#include "formulas/user_profile.hpp"
#include "tanh_sinh_reference.hpp"

using namespace wavecontact::derive;
using GiNaC::ex;
using GiNaC::numeric;

namespace {

struct Digits {
  explicit Digits(int digits) : saved(GiNaC::Digits) { GiNaC::Digits = digits; }
  ~Digits() { GiNaC::Digits = saved; }
  long saved;
};

numeric square(const numeric& q) { return q * q; }

numeric pi() { return GiNaC::ex_to<numeric>(GiNaC::Pi.evalf()); }

// (E*/2)(pi/b1) times the conjugate function's derivative, at b1 = pi.
numeric conjugate_slope(const std::function<numeric(const numeric&)>& slope, const numeric& x, const numeric& branch,
                        const numeric& E) {
  std::vector<numeric> ends{-pi(), pi(), x};
  if (branch > 0) ends.insert(ends.end(), {-branch, branch});
  std::sort(ends.begin(), ends.end(), [](const numeric& a, const numeric& b) { return a < b; });
  const numeric at_x = slope(x);
  // Bounded: a node that rounds onto x^ itself (weight below 10^-Digits) adds nothing.
  const auto integrand = [&](const numeric& xi) {
    const numeric tangent = GiNaC::tan((x - xi) / 2);
    return tangent.is_zero() ? numeric(0) : (slope(xi) - at_x) / tangent;
  };
  numeric sum = 0;
  for (std::size_t i = 0; i + 1 < ends.size(); ++i) {
    if (ends[i] < ends[i + 1]) sum += wavecontact::test::tanh_sinh(integrand, ends[i], ends[i + 1]);
  }
  return E / 2 * sum / (2 * pi());
}

struct Case {
  std::string expression;
  std::vector<ProfileParameter> parameters;      // the derivation's sample values (angle forms' signs)
  std::vector<numeric> values;                   // where the closed form is checked
  std::function<numeric(const numeric&)> slope;  // dy/dx^ at the parameters' values
  numeric branch;                                // x^ of the branch point, 0 if none
};

void check_case(const Case& c, const std::vector<numeric>& xs) {
  const ProfileDerivation d = derive_profile({"profile", c.expression, c.parameters});

  const numeric E(3, 2);
  GiNaC::exmap point{{sym::E(), E}, {sym::b1(), GiNaC::Pi}};
  for (std::size_t i = 0; i < d.parameters.size(); ++i) point[d.parameters[i]] = c.values[i];
  // The whole form everywhere; for a profile built with abs(), the form of the point's side off
  // the branch point too.
  std::vector<std::tuple<std::string, numeric, numeric>> values;  // form, derived, reference
  numeric scale = 0;
  for (const numeric& x : xs) {
    point[sym::Cx()] = GiNaC::cos(x);
    const numeric reference = conjugate_slope(c.slope, x, c.branch, E);
    scale = std::max(scale, GiNaC::abs(reference));
    const std::string at = ", x^ = " + std::to_string(x.to_double());
    values.emplace_back("whole" + at, GiNaC::ex_to<numeric>(d.full_contact_pressure.subs(point).evalf()), reference);
    if (d.branches.branched && x != c.branch) {
      const bool on_top = x < c.branch;
      const ex& side = on_top ? d.full_contact_pressure_top : d.full_contact_pressure_flank;
      values.emplace_back((on_top ? "top" : "flank") + at, GiNaC::ex_to<numeric>(side.subs(point).evalf()), reference);
    }
  }
  for (const auto& [form, derived, reference] : values) {
    const numeric error = GiNaC::abs(derived - reference) / scale;
    std::ostringstream where;
    where << c.expression << " at";
    for (std::size_t k = 0; k < c.values.size(); ++k) where << " " << c.parameters[k].name << " = " << c.values[k];
    where << ", form " << form << ": derived " << derived << ", quadrature " << reference << ", error "
          << error.to_double() << " of max |p_fc|";
    BOOST_TEST(error < numeric(1, 10).power(35), where.str());
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(rational_profile_is_the_quadrature) {
  const Digits digits(50);
  const numeric H(2, 3), m(1, 2);
  check_case(Case{"H1*(m+1)*cos(x)/(m*cos(x)+1)",
                  {{"H1", H}, {"m", m}},
                  {H, m},
                  [&](const numeric& xi) { return -H * (m + 1) * GiNaC::sin(xi) / square(m * GiNaC::cos(xi) + 1); },
                  numeric(0)},
             {numeric(0), numeric(2, 5), numeric(2), numeric(3)});
}

BOOST_AUTO_TEST_CASE(eq2_is_the_quadrature) {
  const Digits digits(50);
  const numeric H(2, 3), half_pi = pi() / 2;
  for (const numeric& m : {numeric(1, 2), numeric(2), numeric(35)}) {
    std::vector<numeric> xs{
        numeric(0), numeric(2, 5), half_pi - numeric(1, 1000), half_pi, half_pi + numeric(1, 1000000),
        numeric(2), pi()};
    if (m > 1) {  // near the poles of the other branch's formula, cos x^ = 1/m (top) and -1/m (flank)
      for (const numeric& cosine : {1 / m, -1 / m}) xs.push_back(GiNaC::acos(cosine) + numeric(1, 10000));
    }
    check_case(Case{"H1*(m+1)*cos(x)/(m*abs(cos(x))+1)",
                    {{"H1", H}, {"m", numeric(1, 2)}},
                    {H, m},
                    [&](const numeric& xi) {
                      return -H * (m + 1) * GiNaC::sin(xi) / square(m * GiNaC::abs(GiNaC::cos(xi)) + 1);
                    },
                    half_pi},
               xs);
  }
}

BOOST_AUTO_TEST_CASE(kinked_profile_is_the_quadrature) {
  const Digits digits(50);
  const numeric H(1), c(1, 5), branch = GiNaC::acos(numeric(3, 5));
  check_case(Case{"H*cos(x)+c*(5*cos(x)-3)*abs(5*cos(x)-3)",
                  {{"H", H}, {"c", c}},
                  {H, c},
                  [&](const numeric& xi) {
                    return -H * GiNaC::sin(xi) - 10 * c * GiNaC::abs(5 * GiNaC::cos(xi) - 3) * GiNaC::sin(xi);
                  },
                  branch},
             {numeric(1, 10), branch - numeric(1, 100000), branch + numeric(1, 100), numeric(2), numeric(31, 10)});
}
