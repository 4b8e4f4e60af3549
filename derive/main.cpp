// wavecontact-derive: re-runs the derivations of the seed paper with GiNaC and writes
// the emitted evaluators and the manifest into generated/ (or --out DIR).
// Exit statuses: common/exit_status.hpp (docs/cli.md).
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/resource_budget.hpp"
#include "decimal_option.hpp"
#include "emit/file_contents.hpp"
#include "emit/owned_output.hpp"
#include "exit_status.hpp"

namespace {

namespace status = wavecontact::exit_status;

int fail(int code, const std::string& message) {
  std::cerr << "wavecontact-derive: " << message << "\n";
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "wavecontact-derive: derives the closed forms of the seed paper (Block-Keer change of "
      "variables, bounded finite Hilbert inversion, loads) with GiNaC and emits C++ "
      "evaluators and a manifest of every derived expression."};
  std::string out = "generated";
  std::vector<int> ns;
  bool force = false;
  app.add_option("--out", out,
                 "output directory (created if missing); only the files written are replaced, each in one "
                 "rename")
      ->capture_default_str();
  app.add_flag("--force", force,
               "write into --out even if it is the root, current or home directory, or a non-empty "
               "directory without a manifest of wavecontact-derive");
  app.add_option("--n", ns,
                 "write only the roughness evaluators roughness_n<N>.hpp for these even n "
                 "(2 <= n <= 4096, repeatable); without it, everything in generated/");
  std::string expression, name;
  std::vector<std::string> parameters;
  auto* profile = app.add_option("--profile", expression,
                                 "a user profile y(x) over the period 2 pi of x = pi x/b1, even in x, rational in "
                                 "cos(k x) and sin(k x) (GiNaC syntax, e.g. \"H1*cos(x)+H3*cos(3*x)\"): writes "
                                 "profile_<NAME>.hpp and profile_<NAME>_manifest.txt. Bounded: at most 2000 "
                                 "characters, parentheses 16 deep, numbers of 20 digits, exponents integer literals "
                                 "|n| <= 256, order (cos(k x) counts k) <= 256 in the numerator and <= 32 in the "
                                 "denominator, 8 parameters; beyond, refused (exit 2)");
  auto* profile_name = app.add_option("--name", name, "the profile's name, a C++ identifier (with --profile)");
  auto* parameter = app.add_option("--param", parameters,
                                   "a parameter of the profile, NAME or NAME=SAMPLE (repeatable): SAMPLE, a typical "
                                   "value (default 1/2), fixes the signs of square roots in the emitted form");
  double max_seconds = 60;
  long max_memory_mb = 4096;
  app.add_option("--max-seconds", max_seconds,
                 "time budget of the derivation, 0 < s <= 86400: beyond it, exit 4 and nothing written")
      ->capture_default_str()
      ->check(CLI::Range(1e-3, 86400.0));
  app.add_option("--max-memory-mb", max_memory_mb, "memory budget (address space) of the derivation: beyond it, exit 4")
      ->capture_default_str()
      ->check(CLI::Range(64L, 1L << 20));
  profile->needs(profile_name);
  profile_name->needs(profile);
  parameter->needs(profile);
  profile->excludes(app.get_option("--n"));
  wavecontact::cli_common::require_decimal_numbers(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    return fail(status::bad_argument, wavecontact::cli_common::shortened(e.what()));
  }

  namespace derive = wavecontact::derive;
  try {
    std::vector<derive::GeneratedFile> files;
    if (profile->count() > 0) {
      derive::ProfileSpec spec{name, expression, {}};
      std::string command = "wavecontact-derive --profile '" + expression + "'";
      for (const auto& p : parameters) {
        spec.parameters.push_back(derive::parse_parameter(p));
        command += " --param " + p;
      }
      const derive::ResourceBudget budget(
          max_seconds, max_memory_mb,
          "profile " + name + " = \"" + wavecontact::cli_common::shortened(expression) + "\"");
      files = derive::generate_profile(spec, command + " --name " + name + " --out DIR");
    } else {
      const derive::ResourceBudget budget(max_seconds, max_memory_mb, "the generated set");
      files = ns.empty() ? derive::generate_all() : derive::generate_roughness(ns);
    }
    derive::write_generated_files(out, files, force);
  } catch (const std::bad_alloc&) {
    return fail(status::beyond_reach, "the derivation exceeds its memory budget of " + std::to_string(max_memory_mb) +
                                          " MB (--max-memory-mb); nothing is written");
  } catch (const derive::OutputError& e) {
    return fail(status::io_error, e.what());
  } catch (const std::invalid_argument& e) {  // the input or --out is refused; nothing is written
    return fail(status::bad_argument, e.what());
  } catch (const std::exception& e) {
    return fail(status::internal_error, std::string("internal error: ") + e.what());
  }
  return status::success;
}
