// Property tests over random valid inputs (fixed seeds): physical and algebraic properties
// that must hold everywhere in the domain, including its delicate corners.
#define BOOST_TEST_MODULE property
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <random>

#include "isa_under_test.hpp"
#include "wavecontact/two_scale.hpp"
#include "wavecontact/waviness.hpp"

namespace tt = boost::test_tools;
using namespace wavecontact;

namespace {

struct Sample {
  WavinessParams params;
  double a, x;
};

// m log-uniform in [1e-6, 1e6] (and exactly 0 now and then), a/b1 in (0, 1/2], x in [0, a).
std::vector<Sample> samples(std::uint64_t seed, int count) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto log_uniform = [&](double lo, double hi) { return lo * std::pow(hi / lo, unit(random)); };
  std::vector<Sample> result;
  for (int i = 0; i < count; ++i) {
    const double m = i % 10 == 0 ? 0.0 : log_uniform(1e-6, 1e6);
    const WavinessParams p{log_uniform(1e-3, 1e3), log_uniform(1e-3, 1e3), m, log_uniform(1e3, 1e12)};
    const double a = p.b1 / 2 * (1 - unit(random));  // (0, b1/2]
    result.push_back({p, a, a * unit(random)});
  }
  return result;
}

}  // namespace

BOOST_AUTO_TEST_CASE(pressure_is_nonnegative_and_vanishes_like_a_square_root_at_the_edge) {
  for (const auto& s : samples(1, 2000)) {
    for (Form form : {Form::exact, Form::paper}) {
      const double p = pressure(s.params, s.a, s.x, form);
      BOOST_TEST((std::isfinite(p) && p >= 0), "p = " << p << " at m = " << s.params.m);
      const double near = pressure(s.params, s.a, s.a * (1 - 1e-6), form);
      const double nearer = pressure(s.params, s.a, s.a * (1 - 1e-12), form);
      BOOST_TEST(nearer / near == 1e-3, tt::tolerance(1e-2));  // sqrt(1e-12/1e-6)
    }
  }
}

BOOST_AUTO_TEST_CASE(load_increases_with_the_zone) {
  for (const auto& s : samples(2, 500)) {
    const double a2 = std::min(s.params.b1 / 2, s.a * 1.01);
    if (a2 <= s.a) continue;
    BOOST_TEST(load(s.params, a2) > load(s.params, s.a), "m = " << s.params.m << ", a/b1 = " << s.a / s.params.b1);
  }
}

BOOST_AUTO_TEST_CASE(exact_and_printed_forms_coincide_at_m_zero) {
  for (auto s : samples(3, 500)) {
    s.params.m = 0;
    BOOST_TEST(pressure(s.params, s.a, s.x, Form::exact) == pressure(s.params, s.a, s.x, Form::paper),
               tt::tolerance(1e-13));
  }
}

BOOST_AUTO_TEST_CASE(pressure_scales_with_E_H1_and_inversely_with_b1) {
  for (const auto& s : samples(4, 500)) {
    const double p = pressure(s.params, s.a, s.x);
    WavinessParams stiffer = s.params, taller = s.params, wider = s.params;
    stiffer.E *= 3;
    taller.H1 *= 0.25;
    wider.b1 *= 8;  // exact power of two: a/b1 and x/b1 are unchanged
    BOOST_TEST(pressure(stiffer, s.a, s.x) == 3 * p, tt::tolerance(1e-14));
    BOOST_TEST(pressure(taller, s.a, s.x) == 0.25 * p, tt::tolerance(1e-14));
    BOOST_TEST(pressure(wider, 8 * s.a, 8 * s.x) == p / 8, tt::tolerance(1e-14));
    BOOST_TEST(load(wider, 8 * s.a) == load(s.params, s.a), tt::tolerance(1e-14));
  }
}

BOOST_AUTO_TEST_CASE(delicate_but_valid_inputs) {
  for (double m : {0.0, 1.0, 1e6}) {
    const WavinessParams p{1.0, 10.0, m, 1.0};
    for (double a : {1e-19, 1e-12, 5.0 * (1 - 1e-15), 5.0}) {
      const double P = load(p, a), p0 = pressure(p, a, 0.0), edge = pressure(p, a, a * (1 - 1e-15));
      BOOST_TEST((std::isfinite(P) && P >= 0 && std::isfinite(p0) && p0 >= 0 && edge >= 0),
                 "m = " << m << ", a = " << a);
      if (a >= 1e-12) BOOST_TEST(single_asperity_half_width(p, P) == a, tt::tolerance(1e-12));
    }
    // a -> b1/2 from below is continuous.
    BOOST_TEST(load(p, 5.0 * (1 - 1e-12)) == load(p, 5.0), tt::tolerance(1e-9 * (1 + m)));
  }
  // H2 -> 0: the two-scale solution tends to the waviness.
  const TwoScaleParams rough{{1.0, 10.0, 2.0, 1.0}, {1e-50, 16}};
  const TwoScaleContact contact(rough, 3.0);
  BOOST_TEST(contact.pressure(1.0) == pressure(rough.waviness, 3.0, 1.0), tt::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(admissible_two_scale_pressure_is_nonnegative) {
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int admissible = 0, refused = 0;
  for (int i = 0; i < 300; ++i) {
    const int n = 2 * (1 + static_cast<int>(unit(random) * 32));
    const TwoScaleParams params{{1.0, 10.0, 20 * unit(random), 1.0}, {0.2 * unit(random) / n, n}};
    const double a = 5.0 * (1 - unit(random));
    const TwoScaleContact contact(params, a);
    if (!contact.admissible()) {
      ++refused;
      BOOST_CHECK_THROW(contact.pressure(0.0), std::domain_error);
      continue;
    }
    ++admissible;
    for (int k = 0; k < 50; ++k) BOOST_TEST(contact.pressure(a * unit(random)) >= 0.0);
  }
  BOOST_TEST_MESSAGE(admissible << " admissible zones, " << refused << " refused");
  BOOST_TEST(admissible > 0);
}
