#include "reproduce.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <future>
#include <string>
#include <vector>

#include "figure.hpp"
#include "gnuplot.hpp"
#include "refusals.hpp"

namespace wavecontact::cli {

namespace fs = std::filesystem;

void reproduce(const std::string& out_dir, const std::vector<std::string>& only, std::ostream& log) {
  const std::vector<std::string> names{"fig1", "fig2", "fig4",  "fig5a", "fig5b", "fig6", "fig7",
                                       "fig8", "fig9", "fig10", "fig11", "fig12", "fig13"};
  for (const std::string& name : only) {
    if (std::find(names.begin(), names.end(), name) == names.end()) {
      std::string list;
      for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
      throw UsageError("--figures: no figure \"" + name + "\" (one of: " + list + ")");
    }
  }
  const auto wanted = [&](const char* name) {
    return only.empty() || std::find(only.begin(), only.end(), name) != only.end();
  };
  const fs::path dir(out_dir);
  std::error_code error;
  fs::create_directories(dir, error);
  if (error || !fs::is_directory(dir)) {
    throw OutputError("cannot create --out " + out_dir + (error ? ": " + error.message() : ": not a directory"));
  }
  // The figures are independent: each is computed on its own thread (the two-scale sweeps,
  // which fig7, fig10 and the report share, on one more), then written in order.
  const bool need_sweeps = wanted("fig7") || wanted("fig10");
  const std::shared_future<TwoScaleSweeps> sweeps = std::async(std::launch::async, [need_sweeps] {
    return need_sweeps ? two_scale_sweeps({8, 16}, 1.2, 60) : TwoScaleSweeps{};
  });
  std::vector<std::future<Figure>> pending;
  const auto compute = [&](const char* name, std::function<Figure()> build) {
    if (wanted(name)) pending.push_back(std::async(std::launch::async, std::move(build)));
  };
  compute("fig1", wave_curves);
  compute("fig2", two_scale_profiles);
  compute("fig4", roughness_integrand);
  compute("fig5a", single_asperity_pressure);
  compute("fig5b", periodic_pressure);
  compute("fig6", contact_length);
  compute("fig7", [sweeps] { return centre_pressure(sweeps.get()); });
  compute("fig8", two_scale_contact_area);
  compute("fig9", shape_design);
  compute("fig10", [sweeps] { return contact_fraction_and_zones(sweeps.get()); });
  compute("fig11", multi_zone_pressure);
  compute("fig12", four_scale_contact);
  compute("fig13", scale_map);
  std::vector<Figure> figures;
  for (std::future<Figure>& f : pending) figures.push_back(f.get());
  for (const Figure& figure : figures) {
    write_file(dir / (figure.name + ".csv"), figure.csv);
    write_file(dir / (figure.name + ".gp"), gnuplot_preamble(figure.name + ".png") + figure.script);
    run_gnuplot(dir, figure.name + ".gp", figure.name + ".png");
    log << "wrote " << (dir / (figure.name + ".png")).string() << "\n";
  }
  if (!only.empty()) return;  // the report reads every figure
  write_file(dir / "REPORT.md", discrepancy_report(figures, sweeps.get()));
  log << "wrote " << (dir / "REPORT.md").string() << "\n";
}

}  // namespace wavecontact::cli
