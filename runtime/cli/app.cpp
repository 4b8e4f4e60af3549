// The wavecontact command line: argument parsing and the subcommands, as a function that
// main() and the fuzz target share.
// Output is CSV on `out`; a failure prints one line on `err`, returns its exit status
// (common/exit_status.hpp) and writes nothing on `out` (output is assembled before it is
// printed).
#include "app.hpp"

#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "contact_commands.hpp"
#include "decimal_option.hpp"
#include "exit_status.hpp"
#include "map_command.hpp"
#include "options.hpp"
#include "refusals.hpp"
#include "reproduce.hpp"
#include "single_zone_commands.hpp"
#include "user_profile_commands.hpp"
#include "wavecontact/contact.hpp"
#include "wavecontact/errors.hpp"
#include "wavecontact/shape_design.hpp"
#include "wavecontact/two_scale.hpp"

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

// Every subcommand with its options; the option values live here, where CLI11 writes them.
struct Commands {
  CLI::App app{
      "wavecontact: elastic contact of the parametric wave curve (Tsukanov) with "
      "closed forms derived by wavecontact-derive"};
  ProfileOptions profile, load_profile, solve_profile, contact_profile, curve_profile;
  ZoneOptions zone, solve_zone, contact_zone;
  std::vector<double> xs;
  std::optional<double> load_a;
  bool single_zone = false;
  int points = 100;
  std::string out_dir;
  std::vector<std::string> only;
  double optimize_ratio = 0, optimize_m_max = 100;
  int kcoef_n = 0;
  MapArguments map_arguments;
  CLI::App *pressure, *load, *solve, *contact, *curve, *reproduce, *optimize, *kcoef, *map;

  Commands();
  Commands(const Commands&) = delete;
  Commands& operator=(const Commands&) = delete;
};

Commands::Commands() {
  app.require_subcommand(1);
  pressure = app.add_subcommand("pressure",
                                "contact pressure at the points --x: of the contact at a load (--P, --pa-over-pstar; "
                                "with the gap), or of one zone (--a, closed form)");
  profile.add_to(pressure, true);
  zone.add_to(pressure, true, false);
  pressure->add_option("--x", xs, "points x (comma-separated) [length]")->required()->delimiter(',');

  load = app.add_subcommand("load", "load, mean pressure and contact fraction of one zone --a");
  load_profile.add_to(load, true);
  load->add_option("--a", load_a, "contact half-width a, 0 < a < b1 [length]")->required();

  solve = app.add_subcommand("solve",
                             "the contact at each load (--P or --pa-over-pstar): zones per period, contact fraction, "
                             "pressures, error estimate; --single-zone: every half-width of one zone carrying it");
  solve_profile.add_to(solve, true);
  solve_zone.add_to(solve, false, true);
  solve->add_flag("--single-zone", single_zone,
                  "the single-zone family instead: every half-width a carrying the load, stable (dP/da > 0) "
                  "and admissible (p >= 0 on it, gap >= 0 off it)");

  contact = app.add_subcommand(
      "contact", "the zones of the contact at a load in the period [-b1, b1): ends, load, largest pressure");
  contact_profile.add_to(contact, false);
  contact_zone.add_to(contact, false, false);

  curve = app.add_subcommand("curve", "pa/p* against 2a/L1 and p(0) against a, single zones (Figs. 6, 7)");
  curve_profile.add_to(curve, false);
  curve->add_option("--points", points, "number of half-widths in (0, b1/2]")->capture_default_str();

  reproduce = app.add_subcommand("reproduce", "CSV and PNG of the seed paper's figures");
  reproduce->add_option("--out", out_dir, "output directory")->required();
  reproduce
      ->add_option("--figures", only,
                   "only these figures (comma list, e.g. fig1,fig10); without it, all of them and REPORT.md")
      ->delimiter(',');

  optimize = app.add_subcommand(
      "optimize-shape", "the shape m of the wave curve whose pressure is most uniform (min max p / mean p) at a load");
  optimize->add_option("--pa-over-pstar", optimize_ratio, "the load, as pa/p* > 0")->required();
  optimize->add_option("--m-max", optimize_m_max, "search 0 <= m <= m-max")->capture_default_str();

  map = app.add_subcommand("map",
                           "the contact over a grid of m, H2, n and the load, on all cores, into a CSV file that a "
                           "rerun completes: contact fraction, zones, p(0), max p, error estimate, status");
  map_arguments.add_to(map);

  kcoef = app.add_subcommand("kcoef", "the exact coefficients k_j of eq. 18");
  kcoef->add_option("--n", kcoef_n, "wavelength ratio n, even >= 2")->required();
  cli_common::require_decimal_numbers(app);
}

// Parses the arguments; CLI11 reads an unknown first word as a missing subcommand, which is
// reported as what it is.
void parse(Commands& c, int argc, const char* const* argv) {
  try {
    c.app.parse(argc, argv);
  } catch (const CLI::RequiredError&) {
    if (argc > 1 && argv[1][0] != '-') {
      std::string names;
      for (const CLI::App* sub : c.app.get_subcommands([](CLI::App*) { return true; })) {
        names += (names.empty() ? "" : ", ") + sub->get_name();
      }
      throw UsageError("unknown subcommand \"" + cli_common::shortened(argv[1]) + "\" (one of: " + names + ")");
    }
    throw;
  }
}

std::string shape_row(double ratio, double m_max) {
  const wavecontact::PressureUniformity best = wavecontact::most_uniform_shape(ratio, m_max);
  return "pa_over_pstar,m,contact_fraction,max_over_mean,x_of_max_over_a\n" + all_digits(ratio) + "," +
         all_digits(best.m) + "," + all_digits(best.a_over_b1) + "," + all_digits(best.max_over_mean) + "," +
         all_digits(best.x_of_max_over_a) + "\n";
}

std::string kcoef_rows(int n) {
  const auto k = wavecontact::expansion_coefficients(n);
  std::string rows = "j,k\n";
  for (std::size_t j = 0; j < k.size(); ++j) rows += std::to_string(j + 1) + "," + k[j] + "\n";
  return rows;
}

// The output of the parsed subcommand (reproduce writes its files and returns nothing).
std::string command_output(const Commands& c, std::ostream& err, bool allow_files) {
  namespace cli = wavecontact::cli;
  if (*c.pressure && !c.zone.a) {
    return cli::contact_pressure(c.profile.surface(), c.zone.load(c.profile), c.xs, c.zone.solver());
  }
  if (*c.contact) {
    return cli::contact_zones(c.contact_profile.surface(), c.contact_zone.load(c.contact_profile),
                              c.contact_zone.solver());
  }
  if (*c.solve && !c.single_zone) {
    if (c.solve_profile.form != "exact") throw UsageError("--form paper needs --single-zone");
    return cli::contact_rows(c.solve_profile.surface(), c.solve_zone.loads(c.solve_profile),
                             c.solve_profile.pstar_load(), c.solve_zone.solver());
  }
  if (*c.pressure && c.profile.is_user_profile()) {
    c.zone.loads(c.profile);  // --a alone
    return cli::user_profile_pressure(c.profile.user_profile(), *c.zone.a, c.xs);
  }
  if (*c.load && c.load_profile.is_user_profile())
    return cli::user_profile_load(c.load_profile.user_profile(), *c.load_a);
  if (*c.solve && c.solve_profile.is_user_profile()) {
    return cli::user_profile_solve(c.solve_profile.user_profile(), c.solve_zone.load(c.solve_profile));
  }
  if (*c.curve && c.curve_profile.is_user_profile())
    return cli::user_profile_curve(c.curve_profile.user_profile(), c.points);
  if (*c.pressure) {
    c.zone.loads(c.profile);  // --a alone
    return pressure_table(c.profile.two_scale(), *c.zone.a, c.xs, c.profile.selected_form());
  }
  if (*c.load) {
    return "a,P,P_waviness,P_roughness,pa,pa_over_pstar,contact_fraction\n" +
           load_row(c.load_profile.two_scale(), *c.load_a, c.load_profile.selected_form());
  }
  if (*c.solve) return single_zone_rows(c.solve_profile, c.solve_zone);
  if (*c.curve) return curve_table(c.curve_profile.two_scale(), c.points);
  if (*c.optimize) return shape_row(c.optimize_ratio, c.optimize_m_max);
  if (*c.kcoef) return kcoef_rows(c.kcoef_n);
  if (!allow_files) throw UsageError("reproduce and map are disabled here (they write files)");
  if (*c.map) return cli::run_map(c.map_arguments, err);
  cli::reproduce(c.out_dir, c.only, err);
  return "";
}

}  // namespace

int run(int argc, const char* const* argv, std::ostream& out, std::ostream& err, bool allow_files) {
  Commands c;
  try {
    parse(c, argc, argv);
    out << command_output(c, err, allow_files);
    out.flush();
    if (!out) throw OutputError("cannot write the output (standard output)");
    return exit_status::success;
  } catch (const CLI::CallForHelp& e) {
    return c.app.exit(e, out, err);
  } catch (const CLI::CallForAllHelp& e) {
    return c.app.exit(e, out, err);
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
