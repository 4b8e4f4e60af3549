// wavecontact: command-line front end of the runtime library.
// Output is CSV on stdout; a bad argument prints one line on stderr, exits 2 and
// writes nothing on stdout (output is assembled before it is printed).
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "reproduce.hpp"
#include "wavecontact/waviness.hpp"

namespace {

using wavecontact::Form;
using wavecontact::WavinessParams;

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string number(double value) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

// Options shared by the subcommands: the profile, the material, the form.
struct ProfileOptions {
  double H1 = 0, b1 = 0, m = 0;
  std::optional<double> E, E1, nu1, E2, nu2;
  std::string form = "exact";

  void add_to(CLI::App* app, bool with_form) {
    app->add_option("--H1", H1, "height of the waviness H1 [length]")->required();
    app->add_option("--b1", b1, "half-period b1 of the waviness [length]")->required();
    app->add_option("--m", m, "shape parameter m >= 0 of the parametric wave curve")->required();
    auto* e = app->add_option("--E", E, "reduced modulus E* [pressure]");
    auto* e1 = app->add_option("--E1", E1, "Young's modulus of body 1 (with --nu1 --E2 --nu2)");
    auto* n1 = app->add_option("--nu1", nu1, "Poisson ratio of body 1");
    auto* e2 = app->add_option("--E2", E2, "Young's modulus of body 2");
    auto* n2 = app->add_option("--nu2", nu2, "Poisson ratio of body 2");
    for (auto* o : {e1, n1, e2, n2}) e->excludes(o);
    if (with_form) {
      app->add_option("--form", form, "exact (derived) or paper (printed eq. 13/14)")
          ->check(CLI::IsMember({"exact", "paper"}));
    }
  }

  WavinessParams params() const {
    double modulus = 0;
    if (E) {
      modulus = *E;
    } else if (E1 && nu1 && E2 && nu2) {
      modulus = wavecontact::reduced_modulus(*E1, *nu1, *E2, *nu2);
    } else {
      throw UsageError("give --E, or all of --E1 --nu1 --E2 --nu2");
    }
    WavinessParams p{H1, b1, m, modulus};
    wavecontact::validate(p, "wavecontact");
    return p;
  }

  Form selected_form() const { return form == "paper" ? Form::paper : Form::exact; }
};

// Exactly one of --a, --P, --pa-over-pstar fixes the contact half-width.
struct ZoneOptions {
  std::optional<double> a, P, ratio;

  void add_to(CLI::App* app, bool with_a) {
    if (with_a) app->add_option("--a", a, "contact half-width a, 0 < a <= b1/2 [length]");
    app->add_option("--P", P, "load per unit length P [pressure x length]");
    app->add_option("--pa-over-pstar", ratio, "dimensionless mean pressure pa/p*");
  }

  double half_width(const WavinessParams& p) const {
    const int given = (a ? 1 : 0) + (P ? 1 : 0) + (ratio ? 1 : 0);
    if (given != 1) throw UsageError("give exactly one of --a, --P, --pa-over-pstar");
    if (a) return *a;
    if (P) return wavecontact::contact_half_width(p, *P);
    return wavecontact::contact_half_width_for_pa_over_pstar(p, *ratio);
  }
};

std::string pressure_table(const WavinessParams& p, double a, const std::vector<double>& xs,
                           Form form) {
  std::ostringstream os;
  os << "x,p,p_waviness,p_roughness\n";
  for (double x : xs) {
    const double pw = wavecontact::pressure(p, a, x, form);
    os << number(x) << "," << number(pw) << "," << number(pw) << "," << number(0.0) << "\n";
  }
  return os.str();
}

std::string load_table(const WavinessParams& p, double a) {
  const double P = wavecontact::load(p, a);
  std::ostringstream os;
  os << "a,P,P_waviness,P_roughness,pa,pa_over_pstar,contact_fraction\n"
     << number(a) << "," << number(P) << "," << number(P) << "," << number(0.0) << ","
     << number(wavecontact::mean_pressure(p, a)) << ","
     << number(wavecontact::pa_over_pstar(p, a)) << ","
     << number(wavecontact::contact_fraction(p, a)) << "\n";
  return os.str();
}

std::string curve_table(const WavinessParams& p, int points) {
  if (points < 1) throw UsageError("--points must be >= 1");
  std::ostringstream os;
  os << "a,contact_fraction,pa_over_pstar,p0,p0_paper\n";
  for (int k = 1; k <= points; ++k) {
    const double a = p.b1 / 2 * k / points;
    os << number(a) << "," << number(wavecontact::contact_fraction(p, a)) << ","
       << number(wavecontact::pa_over_pstar(p, a)) << ","
       << number(wavecontact::pressure(p, a, 0.0, Form::exact)) << ","
       << number(wavecontact::pressure(p, a, 0.0, Form::paper)) << "\n";
  }
  return os.str();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"wavecontact: elastic contact of the parametric wave curve (Tsukanov) with "
               "closed forms derived by wavecontact-derive"};
  app.require_subcommand(1);

  ProfileOptions profile;
  ZoneOptions zone;
  std::vector<double> xs;
  int points = 100;
  std::string out_dir;

  auto* pressure = app.add_subcommand("pressure", "contact pressure at the points --x");
  profile.add_to(pressure, true);
  zone.add_to(pressure, true);
  pressure->add_option("--x", xs, "points x (comma-separated) [length]")
      ->required()
      ->delimiter(',');

  auto* load = app.add_subcommand("load", "load, mean pressure and contact fraction for --a");
  ProfileOptions load_profile;
  std::optional<double> load_a;
  load_profile.add_to(load, true);
  load->add_option("--a", load_a, "contact half-width a, 0 < a <= b1/2 [length]")->required();

  auto* solve = app.add_subcommand("solve", "contact half-width for a load");
  ProfileOptions solve_profile;
  ZoneOptions solve_zone;
  solve_profile.add_to(solve, false);
  solve_zone.add_to(solve, false);

  auto* curve = app.add_subcommand("curve", "pa/p* against 2a/L1 and p(0) against a (Figs. 6, 7)");
  ProfileOptions curve_profile;
  curve_profile.add_to(curve, false);
  curve->add_option("--points", points, "number of half-widths in (0, b1/2]")->capture_default_str();

  auto* reproduce = app.add_subcommand("reproduce", "CSV and PNG of the seed paper's figures");
  reproduce->add_option("--out", out_dir, "output directory")->required();

  try {
    app.parse(argc, argv);
    std::string output;
    if (*pressure) {
      const WavinessParams p = profile.params();
      output = pressure_table(p, zone.half_width(p), xs, profile.selected_form());
    } else if (*load) {
      output = load_table(load_profile.params(), *load_a);
    } else if (*solve) {
      const WavinessParams p = solve_profile.params();
      const double a = solve_zone.half_width(p);
      output = "P,a,contact_fraction\n" + number(wavecontact::load(p, a)) + "," + number(a) +
               "," + number(wavecontact::contact_fraction(p, a)) + "\n";
    } else if (*curve) {
      output = curve_table(curve_profile.params(), points);
    } else if (*reproduce) {
      wavecontact::cli::reproduce(out_dir, std::cerr);
    }
    std::cout << output;
    return 0;
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "wavecontact: " << e.what() << "\n";
    return 2;
  } catch (const UsageError& e) {
    std::cerr << "wavecontact: " << e.what() << "\n";
    return 2;
  } catch (const std::domain_error& e) {
    std::cerr << "wavecontact: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "wavecontact: error: " << e.what() << "\n";
    return 1;
  }
}
