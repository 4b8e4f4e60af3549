#include "reproduce.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

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
#include "refusals.hpp"

extern char** environ;

namespace wavecontact::cli {

namespace fs = std::filesystem;

namespace {

void write(const fs::path& path, const std::string& contents) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << contents;
  out.close();
  if (!out) throw OutputError("cannot write " + path.string() + ": " + std::strerror(errno));
}

// Runs gnuplot on `script` (a file name in `dir`) with `dir` as its working directory: an
// argument vector, no shell, so any path works. Throws OutputError if it cannot run or fails.
void run_gnuplot(const fs::path& dir, const std::string& script) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, dir.c_str());
  std::string program = "gnuplot", argument = script;
  char* argv[] = {program.data(), argument.data(), nullptr};
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) {
    throw OutputError("cannot run gnuplot: " + std::string(std::strerror(spawned)) +
                      (spawned == ENOENT ? " (scripts/install-deps.sh installs it)" : ""));
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw OutputError("cannot wait for gnuplot: " + std::string(std::strerror(errno)));
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw OutputError("gnuplot failed on " + (dir / script).string() +
                      (WIFEXITED(status) ? " (exit status " + std::to_string(WEXITSTATUS(status)) + ")" : " (killed)"));
  }
}

// A whole PNG: its signature first and its IEND chunk last (a full disk truncates it).
void require_png(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string signature = "\x89PNG\r\n\x1a\n";
  const std::string end("\0\0\0\0IEND\xae\x42\x60\x82", 12);
  if (bytes.size() < signature.size() + end.size() || bytes.compare(0, signature.size(), signature) != 0 ||
      bytes.compare(bytes.size() - end.size(), end.size(), end) != 0) {
    throw OutputError(path.string() + " is not a whole PNG after gnuplot (a full disk?)");
  }
}

}  // namespace

void reproduce(const std::string& out_dir, const std::vector<std::string>& only, std::ostream& log) {
  const std::vector<std::string> names{"fig1", "fig2", "fig4", "fig5a", "fig5b", "fig6",
                                       "fig7", "fig8", "fig9", "fig10", "fig11", "fig12"};
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
  std::vector<Figure> figures;
  for (std::future<Figure>& f : pending) figures.push_back(f.get());
  for (const Figure& figure : figures) {
    write(dir / (figure.name + ".csv"), figure.csv);
    write(dir / (figure.name + ".gp"), "set terminal pngcairo size 1100,650 font 'DejaVu Sans,10'\nset output '" +
                                           figure.name +
                                           ".png'\nset datafile separator ','\n"
                                           "set grid\n" +
                                           figure.script);
    run_gnuplot(dir, figure.name + ".gp");
    require_png(dir / (figure.name + ".png"));
    log << "wrote " << (dir / (figure.name + ".png")).string() << "\n";
  }
  if (!only.empty()) return;  // the report reads every figure
  write(dir / "REPORT.md", discrepancy_report(figures, sweeps.get()));
  log << "wrote " << (dir / "REPORT.md").string() << "\n";
}

}  // namespace wavecontact::cli
