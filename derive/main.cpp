// wavecontact-derive: re-runs the derivations of the seed paper with GiNaC and writes
// the emitted evaluators and the manifest into generated/ (or --out DIR).
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "generate.hpp"
#include "output.hpp"

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
      "profile_<NAME>.hpp and profile_<NAME>_manifest.txt");
  auto* profile_name =
      app.add_option("--name", name, "the profile's name, a C++ identifier (with --profile)");
  auto* parameter = app.add_option(
      "--param", parameters,
      "a parameter of the profile, NAME or NAME=SAMPLE (repeatable): SAMPLE, a typical "
      "value (default 1/2), fixes the signs of square roots in the emitted form");
  profile->needs(profile_name);
  profile_name->needs(profile);
  parameter->needs(profile);
  profile->excludes(app.get_option("--n"));
  CLI11_PARSE(app, argc, argv);

  try {
    namespace derive = wavecontact::derive;
    std::vector<derive::GeneratedFile> files;
    if (!expression.empty()) {
      derive::ProfileSpec spec{name, expression, {}};
      std::string command = "wavecontact-derive --profile '" + expression + "'";
      for (const auto& p : parameters) {
        spec.parameters.push_back(derive::parse_parameter(p));
        command += " --param " + p;
      }
      files = derive::generate_profile(spec, command + " --name " + name + " --out DIR");
    } else {
      files = ns.empty() ? derive::generate_all() : derive::generate_roughness(ns);
    }
    derive::write_directory_atomically(out, files);
  } catch (const std::exception& e) {
    std::cerr << "wavecontact-derive: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
