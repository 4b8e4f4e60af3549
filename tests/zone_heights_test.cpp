// The heights at a zone's Chebyshev nodes as the zone's equations take them
// (runtime/src/contact/zone_system.cpp: node_offsets, node_heights, SurfaceModel::height_offsets),
// white-box, against 50-digit references. The nodes are placed in s, where the equations are
// posed; their angles are rounded by a few ulps, and the nodes themselves by half an ulp, and
// the heights' slope times either rounding is noise at every node, which a zone's
// coefficients d_j = j G_j / h multiply by j / h. What matters is the noise, not a smooth
// error: the tests measure the largest Chebyshev coefficient of the error beyond the first
// eighth, G_j (j >= M/8), against the heights at the doubles' nodes for the offsets (and, for
// comparison, the angles), and at the exact nodes for node_heights (and, for comparison, the
// offsets).
#define BOOST_TEST_MODULE zone_heights
#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "contact/chebyshev.hpp"
#include "contact/zone.hpp"
#include "contact/zone_system.hpp"
#include "wavecontact/contact.hpp"

using namespace wavecontact;
using boost::math::double_constants::pi;
using Real = boost::multiprecision::cpp_bin_float_50;
namespace chebyshev = wavecontact::detail::chebyshev;

namespace {

struct Case {
  const char* what;
  WavinessParams waviness;
  std::vector<Harmonic> roughness;
  double a, b;  // the zone, in x^
  int nodes;
};

// y(s) on eq. 2's branches in s = cos x^ plus the harmonics, at 50 digits.
Real height(const Case& c, const Real& s) {
  using boost::multiprecision::acos;
  using boost::multiprecision::cos;
  const Real m = c.waviness.m, H1 = c.waviness.H1;
  Real y = H1 * (m + 1) * s / (1 + m * abs(s));
  const Real x = acos(s);
  for (const Harmonic& h : c.roughness) y += Real(h.H) * cos(h.n * x);
  return y;
}

// The largest Chebyshev coefficient of `error` from j = M/8 on.
double tail(std::vector<double> error) {
  std::vector<double> coefficients(error.size());
  chebyshev::coefficients(error.data(), static_cast<int>(error.size()), coefficients.data());
  double largest = 0;
  for (std::size_t j = error.size() / 8; j < error.size(); ++j) largest = std::max(largest, std::fabs(coefficients[j]));
  return largest;
}

struct Expectation {
  Case c;
  double bound;
};

// Heights as the solver forms them at a zone's nodes x (angles), from the reference x_ref and
// the nodes' offsets in s.
using Heights =
    std::function<std::vector<double>(const detail::SurfaceModel&, const detail::ZoneGeometry&,
                                      const std::vector<double>& x, double x_ref, const std::vector<double>& offsets)>;

const Heights by_offsets = [](const detail::SurfaceModel& model, const detail::ZoneGeometry&,
                              const std::vector<double>& x, double x_ref, const std::vector<double>& offsets) {
  std::vector<double> out(x.size());
  model.height_offsets(x.data(), offsets.data(), x.size(), x_ref, out.data());
  return out;
};
const Heights by_angles = [](const detail::SurfaceModel& model, const detail::ZoneGeometry&,
                             const std::vector<double>& x, double x_ref, const std::vector<double>&) {
  std::vector<double> out(x.size());
  model.height_differences(x.data(), x.size(), x_ref, out.data());
  return out;
};
const Heights by_node_heights = [](const detail::SurfaceModel& model, const detail::ZoneGeometry& g,
                                   const std::vector<double>& x, double,
                                   const std::vector<double>&) { return detail::node_heights(model, g, x); };

// The noise of each way of forming the heights against 50-digit heights at the nodes as the
// zone's equations place them, 1 - s_i = 2 sin^2(a/2) + h (1 - tau_i) from the doubles sin(a/2)
// and h, the reference at the double x_ref; tau_i the doubles chebyshev::nodes or, with
// `exact_nodes`, cos(pi (i + 1/2) / M) itself.
std::vector<double> noise(const Case& c, const std::vector<Heights>& ways, bool exact_nodes) {
  using boost::multiprecision::cos;
  const Surface surface(c.waviness, c.roughness);
  const detail::ZoneGeometry g(c.a, c.b);
  const std::vector<double> x = detail::node_angles(g, c.nodes);
  const double x_ref = x[x.size() / 2];
  const std::vector<double> offsets = detail::node_offsets(g, c.nodes, x_ref);
  const std::vector<double>& tau = chebyshev::nodes(c.nodes);
  const Real sa = std::sin(c.a / 2), h = g.h, y_ref = height(c, cos(Real(x_ref)));
  std::vector<Real> exact(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Real t = exact_nodes ? cos(boost::math::constants::pi<Real>() * (Real(i) + 0.5) / c.nodes) : Real(tau[i]);
    exact[i] = height(c, 1 - (2 * sa * sa + h * (1 - t))) - y_ref;
  }
  std::vector<double> noises;
  for (const Heights& way : ways) {
    const std::vector<double> formed = way(*surface.model(), g, x, x_ref, offsets);
    std::vector<double> error(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) error[i] = static_cast<double>(Real(formed[i]) - exact[i]);
    noises.push_back(tail(error));
  }
  return noises;
}

}  // namespace

BOOST_AUTO_TEST_CASE(heights_at_the_nodes_carry_no_noise_of_the_angles) {
  // Each zone from a contact reported above its tolerance for that noise (docs/campaigns.md).
  // The bounds: a fifteenth of the angles' noise beside the kink (1.5e-16 there; the
  // offsets give 3.2e-18), well below it at the tip (3.5e-18; the offsets 2e-23), and 1e-18
  // on a top zone, where the angles are exact to 3e-19 already and offsets taken from m and
  // cos x_ref themselves gave 1e-15.
  const std::vector<Expectation> cases = {
      // Campaign seed 31, sweep 70 at P = 12.49: a zone ending 3.8e-4 short of the kink.
      {{"a zone beside the kink, n = 60, H2 = 0.2",
        {1, 10, 26.644485770378292, 1},
        {{0.2, 60}},
        1.53055463983,
        1.57041692117,
        2048},
       1e-17},
      // Campaign seed 99, sweep 117 at P = 0.1318: an asperity's tip just touching.
      {{"a tip 4.2e-6 wide, n = 396",
        {1, 10, 2.0974198729848226, 1},
        {{0.00065730587796289993, 396}},
        0.665909107306,
        0.665913305683,
        192},
       1e-20},
      // Campaign seed 31, sweep 393 at P = 0.0314: the top zone, three harmonics on the sine.
      {{"a top zone 0.0018 wide, m = 0",
        {1, 10, 0, 1},
        {{0.057838865380655302, 236}, {0.018448743977910891, 120}, {0.2, 4}},
        0,
        0.00182336358176,
        48},
       1e-18},
  };
  for (const Expectation& e : cases) {
    const std::vector<double> n = noise(e.c, {by_offsets, by_angles}, false);
    BOOST_TEST_MESSAGE(e.c.what << ": noise " << n[0] << " by the offsets, " << n[1] << " by the angles");
    BOOST_TEST(n[0] <= e.bound, e.c.what << ": noise " << n[0] << " by the offsets (bound " << e.bound
                                         << "; by the angles " << n[1] << ")");
  }
}

BOOST_AUTO_TEST_CASE(heights_at_the_exact_nodes_carry_no_noise_of_their_rounding) {
  // The transform takes the doubles tau_i for the exact nodes cos(pi (i + 1/2) / M); the
  // heights' slope times that rounding is noise too (node_heights). Each zone is a top zone
  // of a contact that was reported above the default tolerance 1e-10 for it (campaign seed 45,
  // docs/campaigns.md): the noise against 50-digit heights at the exact nodes, by node_heights
  // and by the heights at the doubles alone.
  const std::vector<Expectation> cases = {
      // Sweep 262 at P = 7.51395: three harmonics on the sine, 52 zones a period.
      {{"a top zone of 5346 nodes, m = 0, n = 8, 838 and 302",
        {1, 10, 0, 1},
        {{0.013420202888427383, 8}, {0.0012590618089401303, 838}, {0.0020363844247388756, 302}},
        0,
        2.4854516504414237,
        5346},
       1.5e-17},
      // Sweep 241 at P = 9.65428: the wave curve's top zone ending past the kink, 498 zones.
      {{"a top zone of 8192 nodes past the kink, m = 7.59, n = 996",
        {1, 10, 7.5931568019005065, 1},
        {{0.0037560694304024991, 996}},
        0,
        1.572607852519798,
        8192},
       1.5e-17},
  };
  for (const Expectation& e : cases) {
    const std::vector<double> n = noise(e.c, {by_node_heights, by_offsets}, true);
    BOOST_TEST_MESSAGE(e.c.what << ": noise " << n[0] << " by node_heights, " << n[1] << " at the doubles");
    BOOST_TEST(n[0] <= e.bound, e.c.what << ": noise " << n[0] << " by node_heights (bound " << e.bound
                                         << "; at the doubles " << n[1] << ")");
  }
}
