// wavecontact-derive: re-runs the derivations of the seed paper with GiNaC and writes
// the emitted evaluators and the manifest into generated/ (or --out DIR).
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "generate.hpp"
#include "output.hpp"
#include "resource_budget.hpp"

int main(int argc, char** argv) {
  CLI::App app{
      "wavecontact-derive: derives the closed forms of the seed paper (Block-Keer change of "
      "variables, bounded finite Hilbert inversion, loads) with GiNaC and emits C++ "
      "evaluators and a manifest of every derived expression."};
  std::string out = "generated";
  std::vector<int> ns;
  app.add_option("--out", out, "output directory (created if missing; updated atomically)")
      ->capture_default_str();
  app.add_option("--n", ns,
                 "write only the roughness evaluators roughness_n<N>.hpp for these even n "
                 "(2 <= n <= 4096, repeatable); without it, everything in generated/");
  std::string expression, name;
  std::vector<std::string> parameters;
  auto* profile = app.add_option(
      "--profile", expression,
      "a user profile y(x) over the period 2 pi of x = pi x/b1, even in x, rational in "
      "cos(k x) and sin(k x) (GiNaC syntax, e.g. \"H1*cos(x)+H3*cos(3*x)\"): writes "
      "profile_<NAME>.hpp and profile_<NAME>_manifest.txt. Bounded: at most 2000 "
      "characters, parentheses 16 deep, numbers of 20 digits, exponents integer literals "
      "|n| <= 256, order (cos(k x) counts k) <= 256 in the numerator and <= 32 in the "
      "denominator, 8 parameters; beyond, refused (exit 2)");
  auto* profile_name =
      app.add_option("--name", name, "the profile's name, a C++ identifier (with --profile)");
  auto* parameter = app.add_option(
      "--param", parameters,
      "a parameter of the profile, NAME or NAME=SAMPLE (repeatable): SAMPLE, a typical "
      "value (default 1/2), fixes the signs of square roots in the emitted form");
  double max_seconds = 60;
  long max_memory_mb = 4096;
  app.add_option("--max-seconds", max_seconds,
                 "time budget of the derivation: beyond it, exit 2 and nothing written")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--max-memory-mb", max_memory_mb,
                 "memory budget (address space) of the derivation: beyond it, exit 2")
      ->capture_default_str()
      ->check(CLI::Range(64L, 1L << 20));
  profile->needs(profile_name);
  profile_name->needs(profile);
  parameter->needs(profile);
  profile->excludes(app.get_option("--n"));
  CLI11_PARSE(app, argc, argv);

  try {
    namespace derive = wavecontact::derive;
    std::vector<derive::GeneratedFile> files;
    if (profile->count() > 0) {
      derive::ProfileSpec spec{name, expression, {}};
      std::string command = "wavecontact-derive --profile '" + expression + "'";
      for (const auto& p : parameters) {
        spec.parameters.push_back(derive::parse_parameter(p));
        command += " --param " + p;
      }
      const derive::ResourceBudget budget(max_seconds, max_memory_mb,
                                          "profile " + name + " = \"" + expression + "\"");
      files = derive::generate_profile(spec, command + " --name " + name + " --out DIR");
    } else {
      const derive::ResourceBudget budget(max_seconds, max_memory_mb, "the generated set");
      files = ns.empty() ? derive::generate_all() : derive::generate_roughness(ns);
    }
    derive::write_directory_atomically(out, files);
  } catch (const std::bad_alloc&) {
    std::cerr << "wavecontact-derive: the derivation exceeds its memory budget of "
              << max_memory_mb << " MB (--max-memory-mb); nothing is written\n";
    return 2;
  } catch (const std::invalid_argument& e) {  // the input is refused; nothing is written
    std::cerr << "wavecontact-derive: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "wavecontact-derive: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
