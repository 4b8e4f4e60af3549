// wavecontact-derive: re-runs the derivations of the seed paper with GiNaC and writes
// the emitted evaluators and the manifest into generated/ (or --out DIR).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "generate.hpp"

namespace fs = std::filesystem;

namespace {

// Writes to a temporary name in the same directory, then renames it into place.
void write_atomically(const fs::path& path, const std::string& contents) {
  const fs::path temporary = path.string() + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write " + temporary.string());
    out << contents;
    out.flush();
    if (!out) throw std::runtime_error("error writing " + temporary.string());
  }
  fs::rename(temporary, path);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "wavecontact-derive: derives the closed forms of the seed paper (Block-Keer change of "
      "variables, bounded finite Hilbert inversion, loads) with GiNaC and emits C++ "
      "evaluators and a manifest of every derived expression."};
  std::string out = "generated";
  std::vector<int> ns;
  app.add_option("--out", out, "output directory (created if missing)")->capture_default_str();
  app.add_option("--n", ns,
                 "write only the roughness evaluators roughness_n<N>.hpp for these even n "
                 "(repeatable); without it, everything in generated/");
  CLI11_PARSE(app, argc, argv);

  try {
    const auto files =
        ns.empty() ? wavecontact::derive::generate_all() : wavecontact::derive::generate_roughness(ns);
    fs::create_directories(out);
    for (const auto& file : files) {
      write_atomically(fs::path(out) / file.name, file.contents);
    }
  } catch (const std::exception& e) {
    std::cerr << "wavecontact-derive: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
