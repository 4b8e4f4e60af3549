#include "user_profile_commands.hpp"

#include <cstdlib>
#include <sstream>

#include "refusals.hpp"
#include "wavecontact/stability.hpp"

namespace wavecontact::cli {

namespace {

// The zone of half-width a, refused if the pressure goes negative in it (naming x and p) or
// the surface penetrates off it (naming x and the penetration).
void require_admissible(const Profile& profile, double a) {
  const Admissibility check = admissibility(profile, a);
  if (!check.admissible) {
    const std::string why = check.most_negative_pressure < 0
                                ? "the pressure is p = " + all_digits(check.most_negative_pressure) +
                                      " < 0 at x = " + all_digits(check.most_negative_x) +
                                      " (the contact would separate)"
                                : "the surface penetrates by " + all_digits(-check.lowest_gap) + " at x = +-" +
                                      all_digits(check.x_of_lowest_gap) + " (the gap would be negative)";
    throw InadmissibleError("no single-zone solution at a = " + all_digits(a) + ": " + why +
                            "; solve --P gives the contact at a load");
  }
}

// Every half-width carrying P, with stability and admissibility (UsageError if none).
std::vector<Equilibrium> user_profile_equilibria(const Profile& profile, double P) {
  std::vector<Equilibrium> roots = LoadCurve(profile).equilibria(P);
  if (roots.empty()) {
    throw UsageError("no single contact zone 0 < a < " + all_digits(profile.reach()) + " carries P = " + all_digits(P) +
                     " (solve without --single-zone gives the contact)");
  }
  return roots;
}

}  // namespace

Profile user_profile(const std::string& name, const std::vector<std::string>& parameters, double b1, double E) {
  ProfileParams params{name, {}, b1, E};
  for (const auto& text : parameters) {
    const auto equals = text.find('=');
    char* end = nullptr;
    const std::string value = equals == std::string::npos ? "" : text.substr(equals + 1);
    const double number = std::strtod(value.c_str(), &end);
    if (equals == std::string::npos || equals == 0 || value.empty() || *end != '\0') {
      throw UsageError("--param " + text + ": expected NAME=VALUE, e.g. --param H3=0.1");
    }
    if (!params.parameters.emplace(text.substr(0, equals), number).second) {
      throw UsageError("--param " + text.substr(0, equals) + " is given twice");
    }
  }
  return Profile(params);
}

std::string user_profile_pressure(const Profile& profile, double a, const std::vector<double>& xs) {
  require_admissible(profile, a);
  std::ostringstream os;
  os << "x,p\n";
  for (double x : xs) os << all_digits(x) << "," << all_digits(profile.pressure(a, x)) << "\n";
  return os.str();
}

std::string user_profile_load(const Profile& profile, double a) {
  const double P = profile.load(a), b1 = profile.params().b1;
  return "a,P,pa,contact_fraction,load_slope\n" + all_digits(a) + "," + all_digits(P) + "," + all_digits(P / (2 * b1)) +
         "," + all_digits(a / b1) + "," + all_digits(profile.load_slope(a)) + "\n";
}

std::string user_profile_solve(const Profile& profile, double P) {
  const std::vector<Equilibrium> found = user_profile_equilibria(profile, P);
  std::string rows;
  bool any_admissible = false;
  for (const auto& e : found) {
    any_admissible = any_admissible || e.admissible;
    rows += all_digits(profile.load(e.a)) + "," + all_digits(e.a) + "," + all_digits(e.a / profile.params().b1) + "," +
            (e.stable ? "1" : "0") + "," + (e.admissible ? "1" : "0") + "\n";
  }
  if (!any_admissible) require_admissible(profile, found.front().a);  // throws
  return "P,a,contact_fraction,stable,admissible\n" + rows;
}

std::string user_profile_curve(const Profile& profile, int points) {
  if (points < 1 || points > 2000) throw UsageError("--points must be in [1, 2000]");
  std::ostringstream os;
  os << "a,contact_fraction,P,load_slope,p0,admissible\n";
  const double end = profile.reach() * (1 - 1e-9), b1 = profile.params().b1;
  for (int k = 1; k <= points; ++k) {
    const double a = end * k / points;
    os << all_digits(a) << "," << all_digits(a / b1) << "," << all_digits(profile.load(a)) << ","
       << all_digits(profile.load_slope(a)) << "," << all_digits(profile.pressure(a, 0)) << ","
       << (admissibility(profile, a).admissible ? 1 : 0) << "\n";
  }
  return os.str();
}

}  // namespace wavecontact::cli
