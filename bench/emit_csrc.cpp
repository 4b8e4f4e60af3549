// Writes the benchmark baseline "no CSE": the exact waviness pressure as GiNaC's own
// print_csrc prints it (a straight transcription of the derived expression). Build-tree
// only: GiNaC's term order changes from run to run, so this is not committed.
#include <fstream>
#include <iostream>

#include "core/symbols.hpp"
#include "engine/angle_form.hpp"
#include "formulas/wave_curve.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: emit_csrc OUTPUT.hpp\n";
    return 2;
  }
  using namespace wavecontact::derive;
  const WavinessDerivation d = derive_waviness();
  GiNaC::ex p = 0;
  for (const auto& term : d.pressure_angle) p += as_ex(term);
  std::ofstream out(argv[1]);
  out << "// GiNaC print_csrc of the exact waviness pressure (benchmark baseline, no CSE).\n"
         "#pragma once\n#include <cmath>\nnamespace wavecontact::bench {\n"
         "inline double waviness_pressure_csrc(double E, double H1, double b1, double m, double Ca,\n"
         "                                     double Sa, double Cx, double Sx, double D) {\n"
         "  (void)Sa; (void)Sx;\n  const double Pi = 3.141592653589793;\n  return ";
  p.print(GiNaC::print_csrc_double(out));
  out << ";\n}\n}  // namespace wavecontact::bench\n";
  return out ? 0 : 1;
}
