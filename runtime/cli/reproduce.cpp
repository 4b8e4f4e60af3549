#include "reproduce.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "figure.hpp"

namespace wavecontact::cli {

namespace fs = std::filesystem;

namespace {

void write(const fs::path& path, const std::string& contents) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << contents;
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace

void reproduce(const std::string& out_dir, std::ostream& log) {
  const fs::path dir(out_dir);
  fs::create_directories(dir);
  const TwoScaleSweeps sweeps = two_scale_sweeps();
  const std::vector<Figure> figures{wave_curves(),      two_scale_profiles(),    roughness_integrand(),
                                    single_asperity_pressure(), periodic_pressure(), contact_length(),
                                    centre_pressure(sweeps),    two_scale_contact_area(), shape_design(),
                                    contact_fraction_and_zones(sweeps), multi_zone_pressure()};
  for (const Figure& figure : figures) {
    write(dir / (figure.name + ".csv"), figure.csv);
    write(dir / (figure.name + ".gp"),
          "set terminal pngcairo size 1100,650 font 'DejaVu Sans,10'\nset output '" +
              figure.name + ".png'\nset datafile separator ','\n"
              "set grid\n" + figure.script);
    const std::string command = "cd '" + dir.string() + "' && gnuplot '" + figure.name + ".gp'";
    if (std::system(command.c_str()) != 0) {
      throw std::runtime_error("gnuplot failed on " + (dir / (figure.name + ".gp")).string() +
                               " (is gnuplot installed? scripts/install-deps.sh installs it)");
    }
    log << "wrote " << (dir / (figure.name + ".png")).string() << "\n";
  }
  write(dir / "REPORT.md", discrepancy_report(figures, sweeps));
  log << "wrote " << (dir / "REPORT.md").string() << "\n";
}

}  // namespace wavecontact::cli
