#include "single_zone_commands.hpp"

#include <sstream>

#include "wavecontact/waviness.hpp"

namespace wavecontact::cli {

namespace {

// Every a carrying the load P, with its stability and admissibility.
std::vector<wavecontact::Equilibrium> equilibria(const ProfileOptions& profile, double P) {
  std::vector<wavecontact::Equilibrium> roots = profile.has_roughness()
                                                    ? wavecontact::two_scale_half_widths(profile.two_scale(), P)
                                                    : wavecontact::LoadCurve(profile.params()).equilibria(P);
  if (roots.empty()) {
    throw UsageError("no single contact zone 0 < a < b1 carries P = " + all_digits(P) +
                     " (solve without --single-zone gives the contact)");
  }
  return roots;
}

}  // namespace

TwoScaleContact admissible_contact(const TwoScaleParams& params, double a, Form form) {
  TwoScaleContact contact(params, a, form);
  if (!contact.admissible()) {
    const std::string why = contact.most_negative_pressure() < 0
                                ? "the total pressure is p = " + all_digits(contact.most_negative_pressure()) +
                                      " < 0 at x = " + all_digits(contact.most_negative_x()) +
                                      " (the contact would separate)"
                                : "the surface penetrates by " + all_digits(-contact.lowest_gap()) + " at x = +-" +
                                      all_digits(contact.x_of_lowest_gap()) + " (the gap would be negative)";
    throw InadmissibleError("no single-zone solution at a = " + all_digits(a) + ": " + why +
                            "; solve --P gives the contact at a load");
  }
  return contact;
}

std::string pressure_table(const TwoScaleParams& p, double a, const std::vector<double>& xs, Form form) {
  const TwoScaleContact contact = admissible_contact(p, a, form);
  std::ostringstream os;
  os << "x,p,p_waviness,p_roughness\n";
  for (double x : xs) {
    const double pw = contact.waviness_pressure(x), pr = contact.roughness_pressure(x);
    os << all_digits(x) << "," << all_digits(contact.pressure(x)) << "," << all_digits(pw) << "," << all_digits(pr)
       << "\n";
  }
  return os.str();
}

std::string load_row(const TwoScaleParams& p, double a, Form form) {
  const TwoScaleContact contact = admissible_contact(p, a, form);
  const WavinessParams& w = p.waviness;
  const double P = contact.load();
  return all_digits(a) + "," + all_digits(P) + "," + all_digits(contact.waviness_load()) + "," +
         all_digits(contact.roughness_load()) + "," + all_digits(P / (2 * w.b1)) + "," +
         all_digits(P / (M_PI * w.E * w.H1)) + "," + all_digits(wavecontact::contact_fraction(w, a)) + "\n";
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
       << all_digits(paper.waviness_pressure(0) + paper.roughness_pressure(0)) << "," << (exact.admissible() ? 1 : 0)
       << "\n";
  }
  return os.str();
}

std::string single_zone_rows(const ProfileOptions& profile, const ZoneOptions& zone) {
  const TwoScaleParams p = profile.two_scale();
  const std::vector<wavecontact::Equilibrium> found = equilibria(profile, zone.load(profile));
  std::string rows;
  bool any_admissible = false;
  for (const auto& e : found) {
    any_admissible = any_admissible || e.admissible;
    rows += all_digits(TwoScaleContact(p, e.a, Form::exact).load()) + "," + all_digits(e.a) + "," +
            all_digits(wavecontact::contact_fraction(p.waviness, e.a)) + "," + (e.stable ? "1" : "0") + "," +
            (e.admissible ? "1" : "0") + "\n";
  }
  if (!any_admissible) admissible_contact(p, found.front().a, Form::exact);  // throws
  return "P,a,contact_fraction,stable,admissible\n" + rows;
}

}  // namespace wavecontact::cli
