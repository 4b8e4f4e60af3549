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
  CLI11_PARSE(app, argc, argv);

  try {
    const auto files =
        ns.empty() ? wavecontact::derive::generate_all() : wavecontact::derive::generate_roughness(ns);
    wavecontact::derive::write_directory_atomically(out, files);
  } catch (const std::exception& e) {
    std::cerr << "wavecontact-derive: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
