// WavinessZone (wavecontact/waviness_zone.hpp) against the free functions of waviness.hpp:
// the same values, bit for bit up to b1/2, and beyond it bit for bit with the atoms per call
// and within their rounding with the tables kept, on every array-kernel path; the same
// refusals; and one zone shared by threads.
#define BOOST_TEST_MODULE waviness_zone
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstring>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>

#include "isa_under_test.hpp"
#include "wavecontact/waviness.hpp"
#include "wavecontact/waviness_zone.hpp"

using namespace wavecontact;

namespace {

bool same_bits(double u, double v) { return std::memcmp(&u, &v, sizeof u) == 0; }

// Points over three periods: inside the zone, at its edge, outside it, negative.
Eigen::ArrayXd points_around(const WavinessParams& p, double a, std::mt19937_64& random) {
  std::uniform_real_distribution<double> unit(-3.0, 3.0);
  Eigen::ArrayXd x(203);
  for (Eigen::Index i = 0; i < 200; ++i) x[i] = p.b1 * unit(random);
  x[200] = a, x[201] = -a * (1 - 1e-12), x[202] = 2 * p.b1 + a / 2;
  return x;
}

}  // namespace

BOOST_AUTO_TEST_CASE(zone_gives_the_free_functions_values_bit_for_bit_up_to_half_the_period) {
  std::mt19937_64 random(7);
  int compared = 0;
  for (double m : {0.0, 0.2, 1.0, 10.0, 1e4}) {
    const WavinessParams p{0.7, 3.0, m, 2e5};
    for (double ratio : {1e-6, 0.1, 0.37, 0.5}) {
      const double a = ratio * p.b1;
      for (Form form : {Form::exact, Form::paper}) {
        const WavinessZone zone(p, a, form);
        const Eigen::ArrayXd x = points_around(p, a, random);
        const Eigen::ArrayXd free_array = pressure(p, a, x, form), zone_array = zone.pressure(x);
        Eigen::ArrayXd into(x.size());
        zone.pressure(x, into);
        for (Eigen::Index i = 0; i < x.size(); ++i) {
          const double free_scalar = pressure(p, a, x[i], form), zone_scalar = zone.pressure(x[i]);
          BOOST_TEST(same_bits(zone_scalar, free_scalar), "m = " << m << ", a/b1 = " << ratio << ", x = " << x[i]
                                                                 << ": zone " << zone_scalar << ", free "
                                                                 << free_scalar);
          BOOST_TEST(same_bits(zone_array[i], free_array[i]),
                     "array, m = " << m << ", a/b1 = " << ratio << ", x = " << x[i] << ": zone " << zone_array[i]
                                   << ", free " << free_array[i]);
          BOOST_TEST(same_bits(into[i], zone_array[i]));
          BOOST_TEST(same_bits(zone_scalar, zone_array[i]),
                     "point and array, m = " << m << ", a/b1 = " << ratio << ", x = " << x[i] << ": point "
                                             << zone_scalar << ", array " << zone_array[i]);
          ++compared;
        }
      }
    }
  }
  BOOST_TEST(compared == 5 * 4 * 2 * 203);
}

// The printed eq. 13/14 continued beyond b1/2 (where 1 + m cos(pi a/b1) > 0) lies outside the
// array kernels' bounded arguments: an array takes each point as one point does.
BOOST_AUTO_TEST_CASE(printed_form_beyond_half_arrays_give_the_points_values) {
  std::mt19937_64 random(5);
  for (double m : {0.0, 0.2, 1.0}) {
    const WavinessParams p{0.7, 3.0, m, 2e5};
    const double a = 0.71 * p.b1;
    const Eigen::ArrayXd x = points_around(p, a, random);
    const Eigen::ArrayXd array = pressure(p, a, x, Form::paper),
                         zone_array = WavinessZone(p, a, Form::paper).pressure(x);
    for (Eigen::Index i = 0; i < x.size(); ++i) {
      const double point = pressure(p, a, x[i], Form::paper);
      BOOST_TEST(same_bits(array[i], point),
                 "m = " << m << ", x = " << x[i] << ": array " << array[i] << ", point " << point);
      BOOST_TEST(same_bits(zone_array[i], point));
    }
  }
}

// Beyond b1/2, a zone that takes the atoms per call (AtomTables::per_call) gives the free
// functions' values bit for bit, from a point and from an array.
BOOST_AUTO_TEST_CASE(zone_with_atoms_per_call_gives_the_free_functions_values_bit_for_bit) {
  std::mt19937_64 random(13);
  int compared = 0;
  for (double m : {0.0, 0.2, 1.0, 10.0, 1e4}) {
    const WavinessParams p{0.7, 3.0, m, 2e5};
    for (double ratio : {0.5 + 1e-9, 0.71, 0.98}) {
      const double a = ratio * p.b1;
      const WavinessZone zone(p, a, Form::exact, AtomTables::per_call);
      BOOST_TEST((zone.atom_tables() == AtomTables::per_call));
      const Eigen::ArrayXd x = points_around(p, a, random);
      // Twice: an array call must not leave tables that a later call reads.
      const Eigen::ArrayXd free_array = pressure(p, a, x), zone_array = zone.pressure(x), again = zone.pressure(x);
      for (Eigen::Index i = 0; i < x.size(); ++i) {
        const double free_scalar = pressure(p, a, x[i]), zone_scalar = zone.pressure(x[i]);
        BOOST_TEST(same_bits(zone_scalar, free_scalar), "m = " << m << ", a/b1 = " << ratio << ", x = " << x[i]
                                                               << ": zone " << zone_scalar << ", free " << free_scalar);
        BOOST_TEST(same_bits(zone_array[i], free_array[i]),
                   "array, m = " << m << ", a/b1 = " << ratio << ", x = " << x[i] << ": zone " << zone_array[i]
                                 << ", free " << free_array[i]);
        BOOST_TEST(same_bits(again[i], free_array[i]));
        ++compared;
      }
    }
  }
  BOOST_TEST(compared == 5 * 3 * 203);
}

// Beyond b1/2 a zone that keeps its tables (AtomTables::kept, the default) reads the Cauchy
// part's atoms from panels it builds on first use: its values are the same from a point or an
// array, whichever came first, and within the atoms' rounding of the free functions' (which
// tabulate per array call, or not at all for a point).
BOOST_AUTO_TEST_CASE(zone_beyond_half_is_a_function_of_x_near_the_free_functions) {
  std::mt19937_64 random(11);
  double largest_difference = 0;  // in eps of the zone's largest |p|
  int compared = 0, differing = 0;
  for (double m : {0.0, 0.2, 1.0, 10.0, 1e4}) {
    const WavinessParams p{0.7, 3.0, m, 2e5};
    for (double ratio : {0.5 + 1e-9, 0.71, 0.98}) {
      const double a = ratio * p.b1;
      const WavinessZone points_first(p, a), array_first(p, a);
      const Eigen::ArrayXd x = points_around(p, a, random);
      Eigen::ArrayXd zone_scalar(x.size());
      for (Eigen::Index i = 0; i < x.size(); ++i) zone_scalar[i] = points_first.pressure(x[i]);
      const Eigen::ArrayXd zone_array = array_first.pressure(x), again = points_first.pressure(x);
      const Eigen::ArrayXd free_array = pressure(p, a, x);
      const double scale = zone_array.abs().maxCoeff();
      for (Eigen::Index i = 0; i < x.size(); ++i) {
        const double free_scalar = pressure(p, a, x[i]);
        BOOST_TEST(same_bits(zone_scalar[i], zone_array[i]), "m = " << m << ", a/b1 = " << ratio << ", x = " << x[i]
                                                                    << ": point " << zone_scalar[i] << ", array "
                                                                    << zone_array[i]);
        BOOST_TEST(same_bits(again[i], zone_array[i]));
        for (double free : {free_scalar, free_array[i]}) {
          const double difference = std::fabs(zone_array[i] - free) / scale / 2.220446049250313e-16;
          largest_difference = std::max(largest_difference, difference);
          BOOST_TEST(difference <= 16, "m = " << m << ", a/b1 = " << ratio << ", x = " << x[i] << ": zone "
                                              << zone_array[i] << ", free " << free << ", " << difference << " eps of "
                                              << scale);
        }
        differing += !same_bits(zone_array[i], free_scalar);
        ++compared;
      }
    }
  }
  BOOST_TEST(compared == 5 * 3 * 203);
  BOOST_TEST_MESSAGE("zone against the free functions beyond b1/2: at most "
                     << largest_difference << " eps, " << differing << " of " << compared << " points not bit for bit");
}

BOOST_AUTO_TEST_CASE(zone_refuses_what_the_free_functions_refuse) {
  const WavinessParams p{1, 10, 0.2, 1};
  const auto refuses = [](const auto& call, const std::string& expected) {
    try {
      call();
    } catch (const std::domain_error& e) {
      BOOST_TEST(std::string(e.what()).find(expected) != std::string::npos,
                 "message: " << e.what() << "; expected to contain: " << expected);
      return;
    }
    BOOST_ERROR("no std::domain_error; expected one containing: " << expected);
  };
  refuses([&] { WavinessZone(p, 10, Form::exact); }, "wavecontact::WavinessZone: a = 10 is invalid");
  refuses([&] { WavinessZone(p, std::nan(""), Form::exact); }, "wavecontact::WavinessZone: a = nan is invalid");
  refuses([&] { WavinessZone(WavinessParams{1, 10, -1, 1}, 4, Form::exact); }, "m = -1 is invalid");
  refuses([&] { WavinessZone(WavinessParams{1, 10, 10, 1}, 9.5, Form::paper); }, "for the printed eq. 13/14");
  const WavinessZone zone(p, 4);
  refuses([&] { zone.pressure(INFINITY); }, "wavecontact::WavinessZone::pressure: x = inf is invalid");
  Eigen::ArrayXd x = Eigen::ArrayXd::LinSpaced(9, -4, 4);
  x[5] = std::nan("");
  refuses([&] { zone.pressure(x); }, "wavecontact::WavinessZone::pressure: x = nan is invalid");
  Eigen::ArrayXd short_p(3);
  refuses([&] { zone.pressure(Eigen::ArrayXd::LinSpaced(9, -4, 4), short_p); }, "p.size() = 3 is invalid");
  // The free function keeps its own name in its refusals.
  refuses([&] { pressure(p, 4, x); }, "wavecontact::pressure: x = nan is invalid");
}

BOOST_AUTO_TEST_CASE(one_zone_serves_threads_at_once) {
  // Beyond b1/2 the zone builds its atoms' panels as points ask for them: two threads on a new
  // zone, building them at once, must get what one thread gets.
  const WavinessParams p{1, 10, 10, 1};
  const Eigen::ArrayXd x = Eigen::ArrayXd::LinSpaced(4001, -10, 10);
  const Eigen::ArrayXd alone = WavinessZone(p, 8.3).pressure(x);
  const WavinessZone zone(p, 8.3);
  Eigen::ArrayXd first, second(x.size());
  std::thread one([&] { first = zone.pressure(x); }), two([&] {
    for (Eigen::Index i = x.size() - 1; i >= 0; --i) second[i] = zone.pressure(x[i]);
  });
  one.join(), two.join();
  BOOST_TEST((first == alone).all());
  BOOST_TEST((second == alone).all());
  BOOST_TEST((alone != 0).count() > 3000);  // the zone covers 83 % of the period
}
