// The wavecontact command line: argument parsing and the subcommands, as a function that
// main() and the fuzz target share.
// Output is CSV on `out`; a failure prints one line on `err`, returns its exit status
// (common/exit_status.hpp) and writes nothing on `out` (output is assembled before it is
// printed).
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include <cmath>

#include "app.hpp"
#include "contact_commands.hpp"
#include "decimal_option.hpp"
#include "exit_status.hpp"
#include "errors.hpp"
#include "reproduce.hpp"
#include "user_profile_commands.hpp"
#include "wavecontact/contact.hpp"
#include "wavecontact/shape_design.hpp"
#include "wavecontact/two_scale.hpp"
#include "wavecontact/stability.hpp"
#include "wavecontact/waviness.hpp"

namespace {

using wavecontact::Form;
using wavecontact::TwoScaleContact;
using wavecontact::TwoScaleParams;
using wavecontact::WavinessParams;
using wavecontact::cli::InadmissibleError;
using wavecontact::cli::all_digits;
using wavecontact::cli::UsageError;

// Options shared by the subcommands: the profile, the material, the form.
struct ProfileOptions {
  std::optional<double> H1, m;
  double b1 = 0;
  std::optional<double> E, E1, nu1, E2, nu2;
  std::vector<double> H2;
  std::vector<int> n;
  std::string form = "exact";
  std::optional<std::string> profile_name;
  std::vector<std::string> profile_parameters;

  void add_to(CLI::App* app, bool with_form) {
    auto* h1 = app->add_option("--H1", H1, "height of the waviness H1 [length]");
    app->add_option("--b1", b1, "half-period b1 of the waviness [length]")->required();
    auto* shape = app->add_option("--m", m, "shape parameter m >= 0 of the parametric wave curve");
    auto* name = app->add_option(
        "--profile-name", profile_name,
        "a generated user profile instead of the wave curve (built in: " +
            list(wavecontact::available_profiles()) + "), with --param NAME=VALUE");
    app->add_option("--param", profile_parameters,
                    "a parameter of the --profile-name profile, NAME=VALUE (repeatable)")
        ->needs(name);
    name->excludes(h1)->excludes(shape);
    auto* e = app->add_option("--E", E, "reduced modulus E* [pressure]");
    auto* e1 = app->add_option("--E1", E1, "Young's modulus of body 1 (with --nu1 --E2 --nu2)");
    auto* n1 = app->add_option("--nu1", nu1, "Poisson ratio of body 1");
    auto* e2 = app->add_option("--E2", E2, "Young's modulus of body 2");
    auto* n2 = app->add_option("--nu2", nu2, "Poisson ratio of body 2");
    for (auto* o : {e1, n1, e2, n2}) e->excludes(o);
    auto* h2 = app->add_option("--H2", H2,
                               "height of the roughness harmonic H2 [length] (with --n); a comma list "
                               "adds several harmonics (--P and --pa-over-pstar only)")
                   ->delimiter(',');
    auto* ratio = app->add_option("--n", n, "wavelength ratio n = b1/b2, even (with --H2; a comma list "
                                            "for several)")
                      ->delimiter(',');
    h2->needs(ratio);
    ratio->needs(h2);
    name->excludes(h2)->excludes(ratio);
    if (with_form) {
      app->add_option("--form", form, "exact (derived) or paper (printed eq. 13/14)")
          ->check(CLI::IsMember({"exact", "paper"}));
    }
  }

  static std::string list(const std::vector<std::string>& names) {
    std::string joined;
    for (const auto& n : names) joined += (joined.empty() ? "" : ", ") + n;
    return joined;
  }

  double modulus() const {
    if (E) return *E;
    if (E1 && nu1 && E2 && nu2) return wavecontact::reduced_modulus(*E1, *nu1, *E2, *nu2);
    throw UsageError("give --E, or all of --E1 --nu1 --E2 --nu2");
  }

  bool is_user_profile() const { return profile_name.has_value(); }

  wavecontact::Profile user_profile() const {
    if (form != "exact") throw UsageError("--form paper applies to the wave curve only");
    return wavecontact::cli::user_profile(*profile_name, profile_parameters, b1, modulus());
  }

  WavinessParams params() const {
    if (!H1 || !m) throw UsageError("give --H1 and --m (the wave curve) or --profile-name");
    WavinessParams p{*H1, b1, *m, modulus()};
    wavecontact::validate(p, "wavecontact");
    return p;
  }

  Form selected_form() const { return form == "paper" ? Form::paper : Form::exact; }

  // The roughness harmonics (eq. 3): as many --H2 as --n, each H2 >= 0 and n even.
  std::vector<wavecontact::Harmonic> harmonics() const {
    if (H2.size() != n.size()) {
      throw UsageError("give as many --H2 as --n (" + std::to_string(H2.size()) + " and " +
                       std::to_string(n.size()) + ")");
    }
    std::vector<wavecontact::Harmonic> result;
    for (std::size_t i = 0; i < H2.size(); ++i) {
      wavecontact::validate(wavecontact::RoughnessParams{H2[i], n[i]}, "wavecontact");
      result.push_back({H2[i], n[i]});
    }
    return result;
  }

  // The two-scale profile (eq. 1), H2 = 0 when no roughness is given: one harmonic at most.
  TwoScaleParams two_scale() const {
    const std::vector<wavecontact::Harmonic> h = harmonics();
    if (h.size() > 1) {
      throw UsageError("one zone (--a, --single-zone, load, curve) takes one roughness harmonic; "
                       "several are for the contact at a load (--P, --pa-over-pstar)");
    }
    return {params(), h.empty() ? wavecontact::RoughnessParams{0.0, 2} : wavecontact::RoughnessParams{h[0].H, h[0].n}};
  }
  bool has_roughness() const { return !H2.empty(); }

  // The surface of the real contact: the wave curve with every harmonic, or the user profile.
  // The library checks the harmonics (at most max_harmonics, even n <= max_roughness_n).
  wavecontact::Surface surface() const {
    if (is_user_profile()) return wavecontact::Surface(user_profile());
    if (form != "exact") throw UsageError("--form paper applies to one zone (--a, --single-zone)");
    return wavecontact::Surface(params(), harmonics());
  }

  // P at pa/p* = 1 (pi E* H1), for the wave curve.
  std::optional<double> pstar_load() const {
    if (is_user_profile()) return std::nullopt;
    const WavinessParams p = params();
    return M_PI * p.E * p.H1;
  }
};

// The zone for a: refuses it if the total pressure goes negative in it (naming x and p) or
// the surface penetrates off it (naming x and the penetration).
TwoScaleContact admissible_contact(const TwoScaleParams& params, double a, Form form) {
  TwoScaleContact contact(params, a, form);
  if (!contact.admissible()) {
    const std::string why =
        contact.most_negative_pressure() < 0
            ? "the total pressure is p = " + all_digits(contact.most_negative_pressure()) + " < 0 at x = " +
                  all_digits(contact.most_negative_x()) + " (the contact would separate)"
            : "the surface penetrates by " + all_digits(-contact.lowest_gap()) + " at x = +-" +
                  all_digits(contact.x_of_lowest_gap()) + " (the gap would be negative)";
    throw InadmissibleError("no single-zone solution at a = " + all_digits(a) + ": " + why +
                            "; solve --P gives the contact at a load");
  }
  return contact;
}

// Every a carrying the load P, with its stability and admissibility.
std::vector<wavecontact::Equilibrium> equilibria(const ProfileOptions& profile, double P) {
  const std::vector<wavecontact::Equilibrium> roots =
      profile.has_roughness() ? wavecontact::two_scale_half_widths(profile.two_scale(), P)
                              : wavecontact::LoadCurve(profile.params()).equilibria(P);
  if (roots.empty()) {
    throw UsageError("no single contact zone 0 < a < b1 carries P = " + all_digits(P) +
                     " (solve without --single-zone gives the contact)");
  }
  return roots;
}

// Exactly one of --a (one zone, closed form), --P or --pa-over-pstar (the contact at loads).
struct ZoneOptions {
  std::optional<double> a;
  std::vector<double> P, ratio;
  double tolerance = 1e-10;
  double max_seconds = 60;

  void add_to(CLI::App* app, bool with_a, bool several_loads) {
    if (with_a) app->add_option("--a", a, "contact half-width a of one zone, 0 < a < b1 [length]");
    const std::string list = several_loads ? " (a comma list for several)" : "";
    app->add_option("--P", P, "load per unit length P [pressure x length]" + list)->delimiter(',');
    app->add_option("--pa-over-pstar", ratio, "dimensionless mean pressure pa/p*" + list)->delimiter(',');
    app->add_option("--tolerance", tolerance,
                    "relative error the contact must meet, 1e-14 to 1e-2 (missed: exit 4)")
        ->capture_default_str();
    app->add_option("--max-seconds", max_seconds,
                    "work budget of each load, 0 < s <= 1e6: beyond it, exit 4 saying how far it got")
        ->capture_default_str();
  }

  // The loads the options fix (none with --a).
  std::vector<double> loads(const ProfileOptions& profile) const {
    const int given = (a ? 1 : 0) + (P.empty() ? 0 : 1) + (ratio.empty() ? 0 : 1);
    if (given != 1) throw UsageError("give exactly one of --a, --P, --pa-over-pstar");
    if (P.size() + ratio.size() > 1000) throw UsageError("at most 1000 loads");
    if (a) return {};
    if (!ratio.empty() && profile.is_user_profile()) {
      throw UsageError("--pa-over-pstar (p* = pi E* H1/(2 b1)) needs H1: give --P for a user profile");
    }
    if (!P.empty()) return P;
    std::vector<double> loads;
    for (double r : ratio) loads.push_back(r * *profile.pstar_load());  // pa/p* = P/(pi E* H1)
    return loads;
  }

  // The one load, for pressure and contact.
  double load(const ProfileOptions& profile) const {
    const std::vector<double> l = loads(profile);
    if (l.size() != 1) throw UsageError("give one load");
    return l.front();
  }

  wavecontact::SolverOptions solver() const { return {tolerance, 0, max_seconds}; }
};

std::string pressure_table(const TwoScaleParams& p, double a, const std::vector<double>& xs,
                           Form form) {
  const TwoScaleContact contact = admissible_contact(p, a, form);
  std::ostringstream os;
  os << "x,p,p_waviness,p_roughness\n";
  for (double x : xs) {
    const double pw = contact.waviness_pressure(x), pr = contact.roughness_pressure(x);
    os << all_digits(x) << "," << all_digits(contact.pressure(x)) << "," << all_digits(pw) << ","
       << all_digits(pr) << "\n";
  }
  return os.str();
}

std::string load_row(const TwoScaleParams& p, double a, Form form) {
  const TwoScaleContact contact = admissible_contact(p, a, form);
  const WavinessParams& w = p.waviness;
  const double P = contact.load();
  return all_digits(a) + "," + all_digits(P) + "," + all_digits(contact.waviness_load()) + "," +
         all_digits(contact.roughness_load()) + "," + all_digits(P / (2 * w.b1)) + "," +
         all_digits(P / (M_PI * w.E * w.H1)) + "," + all_digits(wavecontact::contact_fraction(w, a)) +
         "\n";
}

std::string curve_table(const TwoScaleParams& p, int points) {
  if (points < 1 || points > 2000) throw UsageError("--points must be in [1, 2000]");
  std::ostringstream os;
  // Zones whose total pressure would be negative are listed with admissible = 0.
  os << "a,contact_fraction,pa_over_pstar,p0,p0_paper,admissible\n";
  const WavinessParams& w = p.waviness;
  for (int k = 1; k <= points; ++k) {
    const double a = w.b1 / 2 * k / points;
    const TwoScaleContact exact(p, a, Form::exact), paper(p, a, Form::paper);
    os << all_digits(a) << "," << all_digits(wavecontact::contact_fraction(w, a)) << ","
       << all_digits(exact.load() / (M_PI * w.E * w.H1)) << ","
       << all_digits(exact.waviness_pressure(0) + exact.roughness_pressure(0)) << ","
       << all_digits(paper.waviness_pressure(0) + paper.roughness_pressure(0)) << ","
       << (exact.admissible() ? 1 : 0) << "\n";
  }
  return os.str();
}

}  // namespace

namespace wavecontact::cli {

namespace {

// A library message without its "wavecontact::function: " prefix (the command line names
// itself), shortened to about 200 characters of any echoed input.
std::string without_prefix(const std::string& message) {
  std::string text = message;
  if (text.rfind("wavecontact::", 0) == 0 || text.rfind("wavecontact: ", 0) == 0) {
    const std::size_t colon = text.find(": ");
    if (colon != std::string::npos) text = text.substr(colon + 2);
  }
  return text;
}

int fail(std::ostream& err, int status, const std::string& message) {
  err << "wavecontact: " << cli_common::shortened(without_prefix(message), 600) << "\n";
  return status;
}

}  // namespace

int run(int argc, const char* const* argv, std::ostream& out, std::ostream& err,
        bool allow_files) {
  CLI::App app{"wavecontact: elastic contact of the parametric wave curve (Tsukanov) with "
               "closed forms derived by wavecontact-derive"};
  app.require_subcommand(1);

  ProfileOptions profile;
  ZoneOptions zone;
  std::vector<double> xs;
  int points = 100;
  std::string out_dir;

  auto* pressure = app.add_subcommand(
      "pressure", "contact pressure at the points --x: of the contact at a load (--P, --pa-over-pstar; "
                  "with the gap), or of one zone (--a, closed form)");
  profile.add_to(pressure, true);
  zone.add_to(pressure, true, false);
  pressure->add_option("--x", xs, "points x (comma-separated) [length]")
      ->required()
      ->delimiter(',');

  auto* load = app.add_subcommand("load", "load, mean pressure and contact fraction of one zone --a");
  ProfileOptions load_profile;
  std::optional<double> load_a;
  load_profile.add_to(load, true);
  load->add_option("--a", load_a, "contact half-width a, 0 < a < b1 [length]")->required();

  auto* solve = app.add_subcommand(
      "solve", "the contact at each load (--P or --pa-over-pstar): zones per period, contact fraction, "
               "pressures, error estimate; --single-zone: every half-width of one zone carrying it");
  ProfileOptions solve_profile;
  ZoneOptions solve_zone;
  bool single_zone = false;
  solve_profile.add_to(solve, true);
  solve_zone.add_to(solve, false, true);
  solve->add_flag("--single-zone", single_zone,
                  "the single-zone family instead: every half-width a carrying the load, stable (dP/da > 0) "
                  "and admissible (p >= 0 on it, gap >= 0 off it)");

  auto* contact = app.add_subcommand(
      "contact", "the zones of the contact at a load in the period [-b1, b1): ends, load, largest pressure");
  ProfileOptions contact_profile;
  ZoneOptions contact_zone;
  contact_profile.add_to(contact, false);
  contact_zone.add_to(contact, false, false);

  auto* curve = app.add_subcommand("curve", "pa/p* against 2a/L1 and p(0) against a, single zones (Figs. 6, 7)");
  ProfileOptions curve_profile;
  curve_profile.add_to(curve, false);
  curve->add_option("--points", points, "number of half-widths in (0, b1/2]")->capture_default_str();

  auto* reproduce = app.add_subcommand("reproduce", "CSV and PNG of the seed paper's figures");
  reproduce->add_option("--out", out_dir, "output directory")->required();
  std::vector<std::string> only;
  reproduce->add_option("--figures", only,
                        "only these figures (comma list, e.g. fig1,fig10); without it, all of them and REPORT.md")
      ->delimiter(',');

  auto* optimize = app.add_subcommand(
      "optimize-shape",
      "the shape m of the wave curve whose pressure is most uniform (min max p / mean p) at a load");
  double optimize_ratio = 0, optimize_m_max = 100;
  optimize->add_option("--pa-over-pstar", optimize_ratio, "the load, as pa/p* > 0")->required();
  optimize->add_option("--m-max", optimize_m_max, "search 0 <= m <= m-max")->capture_default_str();

  auto* kcoef = app.add_subcommand("kcoef", "the exact coefficients k_j of eq. 18");
  int kcoef_n = 0;
  kcoef->add_option("--n", kcoef_n, "wavelength ratio n, even >= 2")->required();

  cli_common::require_decimal_numbers(app);
  try {
    try {
      app.parse(argc, argv);
    } catch (const CLI::RequiredError&) {
      // CLI11 reads an unknown first word as a missing subcommand.
      if (argc > 1 && argv[1][0] != '-') {
        std::string names;
        for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
          names += (names.empty() ? "" : ", ") + sub->get_name();
        }
        throw UsageError("unknown subcommand \"" + cli_common::shortened(argv[1]) + "\" (one of: " + names + ")");
      }
      throw;
    }
    std::string output;
    namespace cli = wavecontact::cli;
    if (*pressure && !zone.a) {
      output = cli::contact_pressure(profile.surface(), zone.load(profile), xs, zone.solver());
    } else if (*contact) {
      output = cli::contact_zones(contact_profile.surface(), contact_zone.load(contact_profile),
                                  contact_zone.solver());
    } else if (*solve && !single_zone) {
      if (solve_profile.form != "exact") throw UsageError("--form paper needs --single-zone");
      output = cli::contact_rows(solve_profile.surface(), solve_zone.loads(solve_profile),
                                 solve_profile.pstar_load(), solve_zone.solver());
    } else if (*pressure && profile.is_user_profile()) {
      zone.loads(profile);  // --a alone
      output = cli::user_profile_pressure(profile.user_profile(), *zone.a, xs);
    } else if (*load && load_profile.is_user_profile()) {
      output = cli::user_profile_load(load_profile.user_profile(), *load_a);
    } else if (*solve && solve_profile.is_user_profile()) {
      output = cli::user_profile_solve(solve_profile.user_profile(), solve_zone.load(solve_profile));
    } else if (*curve && curve_profile.is_user_profile()) {
      output = cli::user_profile_curve(curve_profile.user_profile(), points);
    } else if (*pressure) {
      zone.loads(profile);  // --a alone
      output = pressure_table(profile.two_scale(), *zone.a, xs, profile.selected_form());
    } else if (*load) {
      output = "a,P,P_waviness,P_roughness,pa,pa_over_pstar,contact_fraction\n" +
               load_row(load_profile.two_scale(), *load_a, load_profile.selected_form());
    } else if (*solve) {
      // --single-zone: one row per half-width carrying the load (several in a snap-through
      // range or with roughness), flagged stable (dP/da > 0) and admissible (p >= 0 on it,
      // gap >= 0 off it); an error naming the refusal if none is admissible.
      const TwoScaleParams p = solve_profile.two_scale();
      const double P = solve_zone.load(solve_profile);
      const std::vector<wavecontact::Equilibrium> found = equilibria(solve_profile, P);
      std::string rows;
      bool any_admissible = false;
      for (const auto& e : found) {
        any_admissible = any_admissible || e.admissible;
        rows += all_digits(TwoScaleContact(p, e.a, Form::exact).load()) + "," + all_digits(e.a) + "," +
                all_digits(wavecontact::contact_fraction(p.waviness, e.a)) + "," +
                (e.stable ? "1" : "0") + "," + (e.admissible ? "1" : "0") + "\n";
      }
      if (!any_admissible) admissible_contact(p, found.front().a, Form::exact);  // throws
      output = "P,a,contact_fraction,stable,admissible\n" + rows;
    } else if (*curve) {
      output = curve_table(curve_profile.two_scale(), points);
    } else if (*optimize) {
      const wavecontact::PressureUniformity best =
          wavecontact::most_uniform_shape(optimize_ratio, optimize_m_max);
      output = "pa_over_pstar,m,contact_fraction,max_over_mean,x_of_max_over_a\n" +
               all_digits(optimize_ratio) + "," + all_digits(best.m) + "," +
               all_digits(best.a_over_b1) + "," + all_digits(best.max_over_mean) + "," +
               all_digits(best.x_of_max_over_a) + "\n";
    } else if (*kcoef) {
      const auto k = wavecontact::expansion_coefficients(kcoef_n);
      output = "j,k\n";
      for (std::size_t j = 0; j < k.size(); ++j) output += std::to_string(j + 1) + "," + k[j] + "\n";
    } else if (*reproduce) {
      if (!allow_files) throw UsageError("reproduce is disabled here (it writes files)");
      cli::reproduce(out_dir, only, err);
    }
    out << output;
    out.flush();
    if (!out) throw OutputError("cannot write the output (standard output)");
    return exit_status::success;
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e, out, err);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e, out, err);
  } catch (const CLI::ParseError& e) {
    return fail(err, exit_status::bad_argument, e.what());
  } catch (const UsageError& e) {
    return fail(err, exit_status::bad_argument, e.what());
  } catch (const std::domain_error& e) {
    return fail(err, exit_status::bad_argument, e.what());
  } catch (const InadmissibleError& e) {
    return fail(err, exit_status::not_the_contact, e.what());
  } catch (const wavecontact::BeyondReach& e) {
    return fail(err, exit_status::beyond_reach, e.what());
  } catch (const NotWithinTolerance& e) {
    return fail(err, exit_status::beyond_reach, e.what());
  } catch (const OutputError& e) {
    return fail(err, exit_status::io_error, e.what());
  } catch (const std::exception& e) {
    return fail(err, exit_status::internal_error, std::string("internal error (please report it): ") + e.what());
  }
}

}  // namespace wavecontact::cli
