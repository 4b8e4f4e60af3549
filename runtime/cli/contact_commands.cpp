#include "contact_commands.hpp"

#include <cstdio>
#include <sstream>

#include "refusals.hpp"

namespace wavecontact::cli {

namespace {

// The contacts at the loads, each within the tolerance (else NotWithinTolerance, by how much).
std::vector<Contact> solve_within_tolerance(const Surface& surface, const std::vector<double>& loads,
                                            const SolverOptions& options) {
  std::vector<Contact> contacts = solve_contact(surface, loads, options);
  for (const Contact& c : contacts) {
    if (!(c.error_estimate() <= options.tolerance)) {
      char text[160];
      std::snprintf(text, sizeof text,
                    "the contact at P = %.17g has an error estimate of %.2g, %.3g times the tolerance %.2g "
                    "(--tolerance)",
                    c.load(), c.error_estimate(), c.error_estimate() / options.tolerance, options.tolerance);
      throw NotWithinTolerance(text);
    }
  }
  return contacts;
}

}  // namespace

std::string contact_rows(const Surface& surface, const std::vector<double>& loads, std::optional<double> pstar_load,
                         const SolverOptions& options) {
  const std::vector<Contact> contacts = solve_within_tolerance(surface, loads, options);
  std::ostringstream os;
  os << "P,pa," << (pstar_load ? "pa_over_pstar," : "")
     << "zones,contact_fraction,full_contact,p0,max_p,x_of_max_p,error_estimate\n";
  for (const Contact& c : contacts) {
    os << all_digits(c.load()) << "," << all_digits(c.load() / (2 * surface.b1())) << ",";
    if (pstar_load) os << all_digits(c.load() / *pstar_load) << ",";
    os << c.zones_per_period() << "," << all_digits(c.contact_fraction()) << "," << (c.full_contact() ? 1 : 0) << ","
       << all_digits(c.pressure(0)) << "," << all_digits(c.max_pressure()) << "," << all_digits(c.x_of_max_pressure())
       << "," << all_digits(c.error_estimate()) << "\n";
  }
  return os.str();
}

std::string contact_zones(const Surface& surface, double P, const SolverOptions& options) {
  const Contact c = solve_within_tolerance(surface, {P}, options).front();
  std::ostringstream os;
  os << "zone,x_start,x_end,load,max_p,x_of_max_p\n";
  int k = 0;
  for (const ContactZone& z : c.zones()) {
    os << ++k << "," << all_digits(z.x_start) << "," << all_digits(z.x_end) << "," << all_digits(z.load) << ","
       << all_digits(z.max_pressure) << "," << all_digits(z.x_of_max_pressure) << "\n";
  }
  return os.str();
}

std::string contact_pressure(const Surface& surface, double P, const std::vector<double>& xs,
                             const SolverOptions& options) {
  const Contact c = solve_within_tolerance(surface, {P}, options).front();
  std::ostringstream os;
  os << "x,p,gap\n";
  for (double x : xs) os << all_digits(x) << "," << all_digits(c.pressure(x)) << "," << all_digits(c.gap(x)) << "\n";
  return os.str();
}

}  // namespace wavecontact::cli
