// The command-line contract of `wavecontact` (issue: core pipeline, section 4).
#define BOOST_TEST_MODULE cli
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "run_command.hpp"

namespace fs = std::filesystem;
namespace tt = boost::test_tools;

namespace {

using Result = wavecontact::test::CommandResult;
using wavecontact::test::fields;
using wavecontact::test::lines;

Result run(const std::string& arguments) {
  return wavecontact::test::run_command(wavecontact::test::command_line(WAVECONTACT_CLI, arguments));
}

std::string number(double value) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

const std::string b1 = number(M_PI);
const std::string profile = "--H1 1 --b1 " + b1 + " --E 1";

}  // namespace

BOOST_AUTO_TEST_CASE(pressure_prints_check_values) {
  const Result r = run("pressure " + profile + " --m 2 --a " + number(0.45 * M_PI) + " --x 0," + number(0.1));
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  const auto rows = lines(r.out);
  BOOST_TEST_REQUIRE(rows.size() == 3u);
  BOOST_TEST(rows[0] == "x,p,p_waviness,p_roughness");
  const auto first = fields(rows[1]);
  BOOST_TEST(first.at(1) == 0.5375117929804417, tt::tolerance(1e-13));
  BOOST_TEST(first.at(2) == first.at(1));
  BOOST_TEST(first.at(3) == 0.0);
  // 17 significant digits.
  BOOST_TEST(rows[1].substr(rows[1].find(',') + 1, 19) == "0.53751179298044172");

  const Result paper = run("pressure " + profile + " --m 10 --a " + number(0.45 * M_PI) + " --x 0 --form paper");
  BOOST_TEST_REQUIRE(paper.status == 0, paper.err);
  BOOST_TEST(fields(lines(paper.out).at(1)).at(1) == 0.2532608275678914, tt::tolerance(1e-13));

  // By load: the contact (one zone here, a = 0.4 b1), with the gap.
  const Result by_load =
      run("pressure " + profile + " --m 5 --P 0.6548011577944177 --x " + number(0.1 * M_PI) + "," + number(0.6 * M_PI));
  BOOST_TEST_REQUIRE(by_load.status == 0, by_load.err);
  BOOST_TEST(lines(by_load.out).at(0) == "x,p,gap");
  BOOST_TEST(fields(lines(by_load.out).at(1)).at(1) == 0.2569750078646253, tt::tolerance(1e-11));
  BOOST_TEST(fields(lines(by_load.out).at(1)).at(2) == 0.0);
  BOOST_TEST(fields(lines(by_load.out).at(2)).at(1) == 0.0);  // off the zone
  BOOST_TEST(fields(lines(by_load.out).at(2)).at(2) > 0.0);
}

BOOST_AUTO_TEST_CASE(load_and_solve_print_one_row) {
  const Result r = run("load " + profile + " --m 0.2 --a " + number(0.3 * M_PI));
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  const auto rows = lines(r.out);
  BOOST_TEST_REQUIRE(rows.size() == 2u);
  BOOST_TEST(rows[0] == "a,P,P_waviness,P_roughness,pa,pa_over_pstar,contact_fraction");
  const auto v = fields(rows[1]);
  BOOST_TEST(v.at(1) == 0.6003844994822082, tt::tolerance(1e-13));
  BOOST_TEST(v.at(4) == v.at(1) / (2 * M_PI), tt::tolerance(1e-15));
  BOOST_TEST(v.at(5) == v.at(1) / M_PI, tt::tolerance(1e-15));
  BOOST_TEST(v.at(6) == 0.3, tt::tolerance(1e-15));

  // The contact at the load of a = 0.45 b1 (m = 10): one zone, 2a/L1 = 0.45.
  const Result s = run("solve " + profile + " --m 10 --P 1.070213575867781");
  BOOST_TEST_REQUIRE(s.status == 0, s.err);
  BOOST_TEST(lines(s.out).at(0) ==
             "P,pa,pa_over_pstar,zones,contact_fraction,full_contact,p0,max_p,x_of_max_p,error_estimate");
  BOOST_TEST_REQUIRE(lines(s.out).size() == 2u);
  const auto row = fields(lines(s.out).at(1));
  BOOST_TEST(row.at(3) == 1.0);
  BOOST_TEST(row.at(4) == 0.45, tt::tolerance(1e-12));
  BOOST_TEST(row.at(6) == 0.3234091494997856, tt::tolerance(1e-11));  // docs/mathematics.md fact 2, p(0)
  BOOST_TEST(row.at(9) < 1e-10);

  // The single-zone family: one row per half-width.
  const Result family = run("solve --single-zone " + profile + " --m 10 --P 1.070213575867781");
  BOOST_TEST_REQUIRE(family.status == 0, family.err);
  BOOST_TEST(lines(family.out).at(0) == "P,a,contact_fraction,stable,admissible");
  BOOST_TEST(lines(family.out).size() == 2u);
  BOOST_TEST(lines(family.out).at(1).substr(lines(family.out).at(1).size() - 4) == ",1,1");
  BOOST_TEST(fields(lines(family.out).at(1)).at(1) == 0.45 * M_PI, tt::tolerance(1e-13));

  // Several loads, by pa/p*: Westergaard's sin^2(pi a/(2 b1)) = pa/p*.
  const Result ratio = run("solve " + profile + " --m 0 --pa-over-pstar 0.25,0.5");
  BOOST_TEST_REQUIRE(ratio.status == 0, ratio.err);
  BOOST_TEST_REQUIRE(lines(ratio.out).size() == 3u);
  BOOST_TEST(fields(lines(ratio.out).at(1)).at(4) == 1.0 / 3.0, tt::tolerance(1e-12));  // sin^2(pi/6)
  BOOST_TEST(fields(lines(ratio.out).at(2)).at(4) == 0.5, tt::tolerance(1e-12));
}

// The commands: beyond the single zone's peak load (pa/p* = 1.80) the contact of
// m = 10 is the top and the valley; beyond 3.975 it is full.
BOOST_AUTO_TEST_CASE(solve_answers_every_load) {
  const std::string m10 = "--H1 1 --b1 10 --m 10 --E 1";
  const Result two = run("solve " + m10 + " --pa-over-pstar 1.9");
  BOOST_TEST_REQUIRE(two.status == 0, two.err);
  const auto row = fields(lines(two.out).at(1));
  BOOST_TEST(row.at(3) == 2.0);  // zones per period
  BOOST_TEST(row.at(5) == 0.0);  // not full
  BOOST_TEST(row.at(9) < 1e-10);
  const Result full = run("solve " + m10 + " --pa-over-pstar 4.5");
  BOOST_TEST_REQUIRE(full.status == 0, full.err);
  BOOST_TEST(fields(lines(full.out).at(1)).at(3) == 1.0);
  BOOST_TEST(fields(lines(full.out).at(1)).at(4) == 1.0);
  BOOST_TEST(fields(lines(full.out).at(1)).at(5) == 1.0);

  // The zones of the period: the top and the valley, their loads adding up to P.
  const Result zones = run("contact " + m10 + " --pa-over-pstar 1.9");
  BOOST_TEST_REQUIRE(zones.status == 0, zones.err);
  BOOST_TEST(lines(zones.out).at(0) == "zone,x_start,x_end,load,max_p,x_of_max_p");
  BOOST_TEST_REQUIRE(lines(zones.out).size() == 3u);
  const auto top = fields(lines(zones.out).at(1)), valley = fields(lines(zones.out).at(2));
  BOOST_TEST(top.at(1) == -top.at(2));
  BOOST_TEST(valley.at(2) == 20 - valley.at(1), tt::tolerance(1e-14));  // around x = b1
  BOOST_TEST(top.at(3) + valley.at(3) == 1.9 * M_PI, tt::tolerance(1e-10));

  // The seed's two-scale profile: a single zone that the next asperity penetrates is
  // refused (docs/mathematics.md fact 10), the contact at its load answered.
  const std::string fig7 = "--H1 1 --b1 10 --m 0 --E 1 --H2 0.15 --n 8";
  const Result penetrating = run("pressure " + fig7 + " --a 0.5 --x 0");
  BOOST_TEST(penetrating.status == 3);
  BOOST_TEST(penetrating.out.empty());
  BOOST_TEST(lines(penetrating.err).size() == 1u);
  BOOST_TEST(penetrating.err.find("penetrates by 0.0304") != std::string::npos, penetrating.err);
  BOOST_TEST(penetrating.err.find("at x = +-2.32") != std::string::npos, penetrating.err);
  const Result rough = run("contact " + fig7 + " --pa-over-pstar 0.1");
  BOOST_TEST_REQUIRE(rough.status == 0, rough.err);
  BOOST_TEST(lines(rough.out).size() == 4u);  // the top and the next asperities either side
}

BOOST_AUTO_TEST_CASE(single_zone_family_in_the_snap_through_range) {
  // m = 10: P(a) peaks at 1.80 pi E* H1 beyond b1/2 and falls to 0.686 pi at full contact;
  // at P = 4 (pa/p* = 1.27) both half-widths interpenetrate at the valley (which closes at
  // pa/p* = 0.974), so --single-zone is refused, naming it; the contact is two zones.
  const Result s = run("solve --single-zone " + profile + " --m 10 --P 4");
  BOOST_TEST(s.status == 3, s.err);
  BOOST_TEST(s.out.empty());
  BOOST_TEST(s.err.find("penetrates") != std::string::npos, s.err);
  const Result contact = run("solve " + profile + " --m 10 --P 4");
  BOOST_TEST_REQUIRE(contact.status == 0, contact.err);
  BOOST_TEST(fields(lines(contact.out).at(1)).at(3) == 2.0);
  // At P = 2.9 (pa/p* = 0.92) the family has one root, and it is the contact.
  const Result one = run("solve --single-zone " + profile + " --m 10 --P 2.9");
  BOOST_TEST_REQUIRE(one.status == 0, one.err);
  BOOST_TEST(lines(one.out).at(1).substr(lines(one.out).at(1).size() - 4) == ",1,1");  // the smallest a
  BOOST_TEST(fields(lines(one.out).at(1)).at(1) < M_PI / 2);
}

BOOST_AUTO_TEST_CASE(material_constants_replace_E) {
  const double E = 1 / ((1 - 0.09) / 2.0 + (1 - 0.16) / 3.0);
  const Result a = run("load --H1 1 --b1 2 --m 1 --a 0.5 --E " + number(E));
  const Result b = run("load --H1 1 --b1 2 --m 1 --a 0.5 --E1 2 --nu1 0.3 --E2 3 --nu2 0.4");
  BOOST_TEST_REQUIRE(a.status == 0);
  BOOST_TEST_REQUIRE(b.status == 0, b.err);
  BOOST_TEST(fields(lines(a.out).at(1)).at(1) == fields(lines(b.out).at(1)).at(1), tt::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(curve_has_a_row_per_point) {
  const Result r = run("curve --H1 1 --b1 10 --m 2 --E 1 --points 7");
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  const auto rows = lines(r.out);
  BOOST_TEST(rows.size() == 8u);
  BOOST_TEST(rows[0] == "a,contact_fraction,pa_over_pstar,p0,p0_paper,admissible");
  BOOST_TEST(fields(rows.back()).at(1) == 0.5);
}

BOOST_AUTO_TEST_CASE(bad_arguments_exit_2_with_one_line_and_no_output) {
  const std::vector<std::string> bad{
      "pressure " + profile + " --m 2 --a 4 --x 0",                        // a >= b1
      "pressure " + profile + " --m -1 --a 1 --x 0",                       // m < 0
      "pressure " + profile + " --m 2 --x 0",                              // no zone
      "pressure " + profile + " --m 2 --a 1 --P 1 --x 0",                  // two zones
      "pressure --H1 1 --b1 3 --m 2 --a 1 --x 0",                          // no modulus
      "pressure " + profile + " --m 2 --a 1 --x zero",                     // not a number
      "pressure " + profile + " --m 2 --a 1 --x 0 --form fancy",           // bad form
      "load " + profile + " --m 2 --a 1 --a 1.2",                          // repeated option
      "load " + profile + " --m 2 --a 1 --colour red",                     // unknown option
      "load --H1 0 --b1 3 --E 1 --m 2 --a 1",                              // H1 = 0
      "load --H1 1 --b1 3 --E 1 --m 2 --a nan",                            // not finite
      "solve " + profile + " --m 2 --P 0",                                 // P = 0
      "solve " + profile + " --m 2 --P 1,-1",                              // a negative load
      "solve " + profile + " --m 2 --P 1 --pa-over-pstar 1",               // two kinds of load
      "solve " + profile + " --m 2 --P 1 --tolerance 0",                   // tolerance out of range
      "solve " + profile + " --m 2 --P 1 --form paper",                    // paper without --single-zone
      "contact " + profile + " --m 2 --P 1,2",                             // contact takes one load
      "contact " + profile + " --m 2 --P 1 --H2 0.1,0.2 --n 8",            // as many --H2 as --n
      "pressure " + profile + " --m 2 --a 1 --H2 0.1,0.1 --n 8,16 --x 0",  // --a: one harmonic
      "solve --single-zone " + profile + " --m 2 --P 1e9",                 // no single zone carries it
      "load --H1 1 --b1 3 --m 1 --a 1 --E1 2 --nu1 0.7 --E2 3 --nu2 0.3",  // nu1 > 0.5
      "load " + profile + " --m 2 --a 1 --H2 0.1",                         // --H2 without --n
      "load " + profile + " --m 2 --a 1 --H2 0.1 --n 7",                   // odd n
      "load " + profile + " --m 2 --a 1 --H2 -0.1 --n 8",                  // negative H2
      "frobnicate",                                                        // unknown subcommand
  };
  for (const auto& arguments : bad) {
    const Result r = run(arguments);
    BOOST_TEST(r.status == 2, arguments << " -> " << r.status << ": " << r.err);
    BOOST_TEST(r.out.empty(), arguments << " printed " << r.out);
    BOOST_TEST(lines(r.err).size() == 1u, arguments << " -> " << r.err);
  }
}

// Every figure, into a path a shell would misread (issue 28: the path was pasted into a shell
// command): quotes, a semicolon, spaces; gnuplot runs with an argument vector.
BOOST_AUTO_TEST_CASE(reproduce_writes_csv_and_png_into_any_path) {
  const fs::path base = fs::temp_directory_path() / ("wavecontact_reproduce_" + std::to_string(::getpid()));
  const fs::path out = base / "Tsukanov's figs x';touch PWNED;'";
  fs::remove_all(base);
  fs::create_directories(base);
  const Result r = wavecontact::test::run_command({WAVECONTACT_CLI, "reproduce", "--out", out.string()});
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  BOOST_TEST(!fs::exists("PWNED"));
  BOOST_TEST(!fs::exists(base / "PWNED"));
  for (const char* figure :
       {"fig1", "fig2", "fig4", "fig5a", "fig5b", "fig6", "fig7", "fig8", "fig9", "fig10", "fig11", "fig12", "fig13"}) {
    for (const char* extension : {".csv", ".png"}) {
      const fs::path file = out / (std::string(figure) + extension);
      BOOST_TEST(fs::exists(file), file);
      BOOST_TEST((fs::exists(file) && fs::file_size(file) > 100), file);
    }
  }
  const fs::path report = out / "REPORT.md";
  BOOST_TEST((fs::exists(report) && fs::file_size(report) > 1000), report);
  fs::remove_all(base);
}

BOOST_AUTO_TEST_CASE(roughness_columns_are_filled) {
  // n = 16, a = 0.5 b2 (docs/mathematics.md fact 4): p_roughness(0) = 10.21387598287078 H2 E*; with
  // H2 = 1e-3 the neighbouring asperities stay clear of the flat, so the zone is the contact.
  const std::string rough = profile + " --m 0 --H2 0.001 --n 16 --a " + number(0.5 * M_PI / 16);
  const Result r = run("pressure " + rough + " --x 0");
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  const auto v = fields(lines(r.out).at(1));
  BOOST_TEST(v.at(3) == 10.21387598287078e-3, tt::tolerance(1e-13));
  BOOST_TEST(v.at(1) == v.at(2) + v.at(3), tt::tolerance(1e-15));

  const Result paper = run("pressure " + rough + " --x 0 --form paper");
  BOOST_TEST_REQUIRE(paper.status == 0, paper.err);
  BOOST_TEST(fields(lines(paper.out).at(1)).at(3) == 10.14091356098158e-3, tt::tolerance(1e-13));

  const Result load = run("load " + rough);
  BOOST_TEST_REQUIRE(load.status == 0, load.err);
  const auto l = fields(lines(load.out).at(1));
  BOOST_TEST(l.at(3) == 1.399144397552393e-3, tt::tolerance(1e-13));
  BOOST_TEST(l.at(1) == l.at(2) + l.at(3), tt::tolerance(1e-15));
}

BOOST_AUTO_TEST_CASE(kcoef_prints_exact_coefficients) {
  const Result r = run("kcoef --n 8");
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  BOOST_TEST(r.out == "j,k\n1,-2\n2,84\n3,-1008\n4,5280\n5,-14080\n6,19968\n7,-14336\n8,4096\n");
  const Result six = run("kcoef --n 6");
  BOOST_TEST(lines(six.out).at(2) == "2,140/3");
  const Result odd = run("kcoef --n 7");
  BOOST_TEST(odd.status == 2);
  BOOST_TEST(odd.out.empty());
}

BOOST_AUTO_TEST_CASE(negative_total_pressure_is_refused) {
  const Result r = run("pressure --H1 1 --b1 10 --E 1 --m 10 --H2 0.5 --n 8 --a 4 --x 0");
  BOOST_TEST(r.status == 3, r.err);
  BOOST_TEST(r.out.empty(), r.out);
  BOOST_TEST(r.err.find("at x = ") != std::string::npos, r.err);
  BOOST_TEST(r.err.find("p = -") != std::string::npos, r.err);
  BOOST_TEST(lines(r.err).size() == 1u);
}

// --profile-name: the generated example profiles through the command line. The two-harmonic
// profile at H3 = 0 is Westergaard's sine, P = pi E* H1 sin^2(pi a/(2 b1)).
BOOST_AUTO_TEST_CASE(user_profile_commands) {
  const std::string sine = "--profile-name two_harmonic --param H1=0.5 --param H3=0 --b1 10 --E 2";
  const Result load = run("load " + sine + " --a 3");
  BOOST_TEST_REQUIRE(load.status == 0, load.err);
  BOOST_TEST(lines(load.out)[0] == "a,P,pa,contact_fraction,load_slope");
  const double expected = M_PI * 2 * 0.5 * std::pow(std::sin(M_PI * 3 / 20), 2);
  BOOST_TEST(fields(lines(load.out)[1])[1] == expected, tt::tolerance(1e-14));

  const Result solve = run("solve --single-zone " + sine + " --P " + number(expected));
  BOOST_TEST_REQUIRE(solve.status == 0, solve.err);
  BOOST_TEST_REQUIRE(lines(solve.out).size() == 2u, solve.out);
  BOOST_TEST(fields(lines(solve.out)[1])[1] == 3.0, tt::tolerance(1e-13));

  // The contact: one zone, 2a/L1 = 0.3 (no pa/p* column for a user profile).
  const Result contact = run("solve " + sine + " --P " + number(expected));
  BOOST_TEST_REQUIRE(contact.status == 0, contact.err);
  BOOST_TEST(lines(contact.out).at(0) == "P,pa,zones,contact_fraction,full_contact,p0,max_p,x_of_max_p,error_estimate");
  BOOST_TEST(fields(lines(contact.out)[1])[3] == 0.3, tt::tolerance(1e-12));

  const Result pressure = run("pressure " + sine + " --P " + number(expected) + " --x 0,1,5");
  BOOST_TEST_REQUIRE(pressure.status == 0, pressure.err);
  BOOST_TEST(lines(pressure.out).size() == 4u);
  BOOST_TEST(fields(lines(pressure.out)[3])[1] == 0.0);  // outside the zone
  BOOST_TEST(fields(lines(pressure.out)[3])[2] > 0.0);

  // The dimpled top: two zones either side of x = 0 at a small load.
  const Result dimpled = run("solve --profile-name two_harmonic --param H1=1 --param H3=-0.2 --b1 10 --E 1 --P 0.05");
  BOOST_TEST_REQUIRE(dimpled.status == 0, dimpled.err);
  BOOST_TEST(fields(lines(dimpled.out)[1])[2] == 2.0);
  BOOST_TEST(fields(lines(dimpled.out)[1])[5] == 0.0);  // p(0)

  // A dimpled top (H3 < -H1/9): a small zone would need p < 0 at x = 0.
  const Result dimple =
      run("pressure --profile-name two_harmonic --param H1=1 --param H3=-0.2 --b1 10 --E 1 --a 1 --x 0");
  BOOST_TEST(dimple.status == 3);
  BOOST_TEST(dimple.err.find("< 0 at x = 0") != std::string::npos, dimple.err);

  // Refusals: exit 2, one line naming the problem.
  const Result missing = run("load --profile-name two_harmonic --param H1=1 --b1 10 --E 1 --a 3");
  BOOST_TEST(missing.status == 2);
  BOOST_TEST(missing.err.find("needs the parameter \"H3\"") != std::string::npos, missing.err);
  const Result unknown = run("load --profile-name circle --b1 10 --E 1 --a 3");
  BOOST_TEST(unknown.status == 2);
  BOOST_TEST(unknown.err.find("available: parametric_wave_curve, two_harmonic") != std::string::npos, unknown.err);
  const Result malformed = run("load " + sine + " --param H5 --a 3");
  BOOST_TEST(malformed.status == 2);
  BOOST_TEST(malformed.err.find("expected NAME=VALUE") != std::string::npos, malformed.err);
  const Result mixed = run("load " + sine + " --H1 1 --a 3");
  BOOST_TEST(mixed.status == 2);
  // Eq. 2 as an expression beyond b1/2: docs/mathematics.md fact 8, m = 2, a = 0.6 b1, P = 3.0393833648235.
  const Result beyond =
      run("load --profile-name parametric_wave_curve --param H1=1 --param m=2 "
          "--b1 10 --E 1 --a 6");
  BOOST_TEST(beyond.status == 0, beyond.err);
  BOOST_TEST(beyond.out.find("3.03938336482") != std::string::npos, beyond.out);
}

// optimize-shape: one row with the optimum (checked against a brute-force scan in
// shape_design_test), and a clear refusal of a load no shape carries.
BOOST_AUTO_TEST_CASE(optimize_shape_prints_the_optimum) {
  const Result r = run("optimize-shape --pa-over-pstar 0.2");
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  BOOST_TEST(lines(r.out).at(0) == "pa_over_pstar,m,contact_fraction,max_over_mean,x_of_max_over_a");
  BOOST_TEST_REQUIRE(lines(r.out).size() == 2u);
  const auto row = fields(lines(r.out)[1]);
  BOOST_TEST(row.at(1) > 2.5);  // the brute-force check lives in shape_design_test
  BOOST_TEST(row.at(1) < 3.5);
  BOOST_TEST(row.at(3) < 1.08);
  const Result refused = run("optimize-shape --pa-over-pstar 50 --m-max 10");
  BOOST_TEST(refused.status == 2);
  BOOST_TEST(refused.err.find("pa/p* = 50") != std::string::npos, refused.err);
}
