// The active-set loop of the contact solver (runtime/src/contact/active_set.*), white-box:
// settled from a given guess, where the public API always starts from its own seed.
//
// A crowded contact (two zones nearer than the most working nodes resolve) is verified before
// its nodes grow. Campaign sweep 1677 of seed 1 (m = 15.5, four harmonics up to n = 662) at
// its seventh load has a gap of 5.8e-4 between its last two zones near x^ = 1.618. From a
// guess with that gap at 2.6e-4 (a grid seed whose rounding differed), Newton's method
// converged on 24 nodes with the gap at 1e-5, a root of the coarse equations alone; the zones
// beside it then grew to 4096 nodes as Newton's method crept, 29 s, before the tension that
// cuts them showed. Verified at once, the tension shows on the coarse nodes.
//
// And Newton's method on a zone alone (zone_system.*), whose steps need no product of GMRES.
#define BOOST_TEST_MODULE settle
#include <boost/math/constants/constants.hpp>
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <utility>
#include <vector>

#include "contact/active_set.hpp"
#include "contact/zone_system.hpp"
#include "wavecontact/contact.hpp"

using namespace wavecontact;
using boost::math::double_constants::pi;

BOOST_AUTO_TEST_CASE(crowded_contact_verified_before_its_nodes_grow) {
  const double m = 15.461108770636478;
  const std::vector<Harmonic> roughness{{0.019801441168662622, 662}, {0.2, 2}, {0.2, 4}, {0.037702671756412461, 12}};
  double slopes = 0;
  for (const Harmonic& h : roughness) slopes += h.H * h.n;
  const double bottom = 0.01 * pi, top = 2 * pi * (1 + m + slopes);
  const double P = bottom * std::pow(top / bottom, 6.0 / 7);  // the campaign's seventh load
  const Surface surface(WavinessParams{1, 10, m, 1}, roughness);

  detail::Configuration guess;
  for (const auto& [a, b] : std::vector<std::pair<double, double>>{
           {0, 1.58959}, {1.58997, 1.59882}, {1.59972, 1.60838}, {1.60915, 1.61799}, {1.61825, pi}}) {
    guess.zones.push_back({detail::ZoneGeometry(a, b), std::vector<double>(detail::working_nodes, 0.0)});
  }
  const detail::SettleOutcome s = detail::settle(surface.model(), P, guess, {400}, {});
  BOOST_TEST_REQUIRE(s.contact.has_value(), "no contact: " << s.failure);
  const std::vector<detail::ZoneUnknowns>& zones = s.contact->zones;
  BOOST_TEST_REQUIRE(zones.size() == 5u);
  // The gap between the last two zones, as the contact has it (solve_contact's 1.61796 to 1.61854).
  BOOST_TEST(std::fabs(zones[3].geometry.b - 1.61796) < 1e-5, "the gap opens at " << zones[3].geometry.b);
  BOOST_TEST(std::fabs(zones[4].geometry.a - 1.61854) < 1e-5, "the gap closes at " << zones[4].geometry.a);
  // The zone beside the gap keeps about the nodes its width and its neighbour's distance ask
  // for (12 sqrt(0.0088 / 5.8e-4) = 47): 48. Grown on the crowded root first, 192 (4096 in
  // the campaign's run).
  BOOST_TEST(zones[3].d.size() <= 96u, "zone 3 settled on " << zones[3].d.size() << " nodes");
}

// Campaign seed 5, sweep 127 with 64 loads and --max-n 32 (the wave curve m = 17.6 with
// harmonics at n = 10 and 6), at P = 26.132335, just below full contact: the whole half
// period's zone has a tension of 5e-5 of the largest pressure next to the kink at b1/2, a dip
// whose parabola is below 0 over 2.2e-4 on either side, and the contact a gap of 6.3e-4
// there. Cut a tenth of the resolution (0.031) on either side, Newton's method crept towards
// two zones 2e-4 short of the contact's and stalled at a scaled residual of 6e-8: no contact
// was found at that load. Cut by the dip's own width, the gap settles where the dip is.
BOOST_AUTO_TEST_CASE(a_narrow_dip_of_the_pressure_is_cut_narrowly) {
  const Surface surface(WavinessParams{1, 10, 17.587974087258871, 1}, {{0.044519177370679883, 10}, {0.2, 6}});
  detail::Configuration guess;
  guess.zones.push_back({detail::ZoneGeometry(0, pi), std::vector<double>(detail::working_nodes, 0.0)});
  const detail::SettleOutcome s = detail::settle(surface.model(), 26.132335, guess, {400}, {});
  BOOST_TEST_REQUIRE(s.contact.has_value(), "no contact: " << s.failure);
  const std::vector<detail::ZoneUnknowns>& zones = s.contact->zones;
  BOOST_TEST_REQUIRE(zones.size() == 2u);
  // Where the whole zone's pressure dips below 0 (the tension settle cut at).
  const double dip = 1.5971445;
  BOOST_TEST(zones[0].geometry.b < dip);
  BOOST_TEST(zones[1].geometry.a > dip);
  BOOST_TEST(zones[1].geometry.a - zones[0].geometry.b < 2e-3,
             "the gap [" << zones[0].geometry.b << ", " << zones[1].geometry.a << "]");
}

// Newton's method on a zone alone (m = 0, H2 = 0.002, n = 8, pa/p* = 0.5), from the guess the
// solver starts such a contact from (Westergaard's width of the top's curvature, relaxed):
// its steps are the preconditioner's solve (ZoneSystem::linear_solve), which is the Jacobian
// itself only with its end columns taken where the ends are now. Taken where the ends were at
// the start, the same steps converged linearly, about 150 times an iteration (4.5e-3, 9.1e-6,
// 6.1e-8, 4.0e-10, ...: six iterations to 1e-12); quadratically, three (4.5e-3, 1.9e-6,
// 1.7e-13).
BOOST_AUTO_TEST_CASE(a_zone_alone_converges_quadratically) {
  const Surface surface(WavinessParams{1, 10, 0, 1}, {{0.002, 8}});
  const detail::SurfaceModel& model = *surface.model();
  const double P = pi / 2;  // pa/p* = 0.5 (wavecontact solve --pa-over-pstar 0.5)
  const double w = 2 * std::asin(std::sqrt(P / (pi * model.E * model.top_curvature)));
  detail::Configuration c;
  c.zones.push_back({detail::ZoneGeometry(0, w), std::vector<double>(detail::working_nodes, 0.0)});
  const detail::ZoneSystem system(model, P);
  for (int i = 0; i < 3; ++i) system.relax(c);
  const detail::ZoneSystem::Result r = system.newton(c, 1e-12, {});
  BOOST_TEST_REQUIRE((r.outcome == detail::ZoneSystem::Outcome::converged));
  BOOST_TEST(r.iterations <= 3, "Newton's method took " << r.iterations << " iterations to " << r.residual);
  BOOST_TEST(std::fabs(r.configuration.zones[0].geometry.b - 1.57502) < 1e-5);  // solve's zone end
}
