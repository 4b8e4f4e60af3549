// The options the subcommands share: the profile (the wave curve with its roughness, or a
// generated user profile), the material, the form; and the zone or the loads.
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "refusals.hpp"
#include "user_profile_commands.hpp"
#include "wavecontact/contact.hpp"
#include "wavecontact/profile.hpp"
#include "wavecontact/two_scale.hpp"
#include "wavecontact/waviness.hpp"

namespace wavecontact::cli {

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
    auto* name = app->add_option("--profile-name", profile_name,
                                 "a generated user profile instead of the wave curve (built in: " +
                                     list(wavecontact::available_profiles()) + "), with --param NAME=VALUE");
    app->add_option("--param", profile_parameters, "a parameter of the --profile-name profile, NAME=VALUE (repeatable)")
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
    auto* ratio = app->add_option("--n", n,
                                  "wavelength ratio n = b1/b2, even (with --H2; a comma list "
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
      throw UsageError("give as many --H2 as --n (" + std::to_string(H2.size()) + " and " + std::to_string(n.size()) +
                       ")");
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
      throw UsageError(
          "one zone (--a, --single-zone, load, curve) takes one roughness harmonic; "
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
    app->add_option("--tolerance", tolerance, "relative error the contact must meet, 1e-14 to 1e-2 (missed: exit 4)")
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

}  // namespace wavecontact::cli
