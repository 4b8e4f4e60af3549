#include "map_command.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <optional>
#include <set>
#include <sstream>

#include "decimal_option.hpp"
#include "refusals.hpp"

namespace wavecontact::cli {

namespace {

double number(const std::string& name, const std::string& text) {
  const std::string wrong = cli_common::decimal_real_error(text);
  if (!wrong.empty()) throw UsageError("--" + name + ": \"" + cli_common::shortened(text) + "\" is not " + wrong);
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(begin, &end);
  if (text.empty() || end != begin + text.size() || errno == ERANGE || !std::isfinite(value)) {
    throw UsageError("--" + name + ": \"" + text + "\" is not a finite number");
  }
  return value;
}

std::string digits(double value) {
  if (std::isnan(value)) return "nan";
  return all_digits(value);
}

// A CSV field, quoted when it holds a comma or a quote.
std::string field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
  return quoted + "\"";
}

// The roughness as "H:n+H:n..." (empty: none).
std::string harmonics_text(const std::vector<Harmonic>& roughness) {
  std::string text;
  for (const Harmonic& h : roughness) text += (text.empty() ? "" : "+") + digits(h.H) + ":" + std::to_string(h.n);
  return text;
}

// A whole number from the command line ("--n", "--harmonics").
int whole(const std::string& name, double v) {
  if (v != std::floor(v) || !(std::fabs(v) <= 1e6))
    throw UsageError("--" + name + ": " + digits(v) + " is not a whole number");
  return static_cast<int>(v);
}

std::string row(const MapPoint& p) {
  std::ostringstream os;
  os << p.index << "," << digits(p.m) << "," << digits(p.H2) << "," << p.n << "," << harmonics_text(p.harmonics) << ","
     << digits(p.P) << "," << digits(p.pa_over_pstar) << "," << to_string(p.status) << "," << p.zones << ","
     << digits(p.contact_fraction) << "," << digits(p.p0) << "," << digits(p.max_p) << "," << digits(p.error_estimate)
     << "," << field(p.message) << "\n";
  return os.str();
}

// The map file: its rows so far (by index) and a descriptor to append to, opened before any
// work. A header of other parameters is refused; a last line without its newline (the row a
// killed run was writing) is cut off.
class MapFile {
 public:
  MapFile(const std::string& path, const std::vector<std::string>& header, std::size_t points) : path_(path) {
    std::ifstream in(path, std::ios::binary);
    std::string text;
    if (in) text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    const std::size_t complete = text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1;
    if (complete < text.size() && truncate(path.c_str(), static_cast<off_t>(complete)) != 0) fail("cannot truncate");
    text.resize(complete);
    descriptor_ = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CREAT, 0644);
    if (descriptor_ < 0) fail("cannot write");
    if (text.empty()) {
      std::string head;
      for (const std::string& line : header) head += line + "\n";
      append(head);
      return;
    }
    const std::vector<std::string> lines = split(text.substr(0, text.size() - 1), '\n');
    for (std::size_t i = 0; i < header.size(); ++i) {
      if (i >= lines.size() || lines[i] != header[i]) {
        ::close(descriptor_);
        throw UsageError("--out " + path + " holds a map of other parameters (line " + std::to_string(i + 1) + ": \"" +
                         (i < lines.size() ? lines[i] : "") + "\", this run's: \"" + header[i] +
                         "\"); give another --out");
      }
    }
    for (std::size_t i = header.size(); i < lines.size(); ++i) {
      char* end = nullptr;
      const unsigned long long index = std::strtoull(lines[i].c_str(), &end, 10);
      if (end == lines[i].c_str() || *end != ',' || index >= points) {
        ::close(descriptor_);
        throw UsageError("--out " + path + ": line " + std::to_string(i + 1) + " is not a row of this map");
      }
      done_.insert(static_cast<std::size_t>(index));
      if (lines[i].find(",solved,") == std::string::npos) ++unsolved_;
    }
  }
  ~MapFile() {
    if (descriptor_ >= 0) ::close(descriptor_);
  }
  MapFile(const MapFile&) = delete;
  MapFile& operator=(const MapFile&) = delete;

  bool done(std::size_t index) const { return done_.count(index) > 0; }
  std::size_t done_count() const { return done_.size(); }
  std::size_t unsolved_count() const { return unsolved_; }  // rows there not "solved"
  // Appends the rows in one write where the system allows (a kill leaves whole rows, or the
  // last one cut, which the next run removes).
  void append(const std::string& text) {
    std::size_t written = 0;
    while (written < text.size()) {
      const ssize_t n = ::write(descriptor_, text.data() + written, text.size() - written);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) fail("cannot write");
      written += static_cast<std::size_t>(n);
    }
  }

 private:
  [[noreturn]] void fail(const char* what) const {
    throw OutputError(std::string(what) + " --out " + path_ + ": " + std::strerror(errno));
  }
  std::string path_;
  int descriptor_ = -1;
  std::set<std::size_t> done_;
  std::size_t unsolved_ = 0;
};

// Points done, their rate and the time left, on one line of a terminal rewritten in place.
class Progress {
 public:
  Progress(std::ostream& err, std::size_t total, std::size_t already)
      : err_(err), shown_(&err == &std::cerr && ::isatty(STDERR_FILENO)), total_(total), done_(already) {}
  void advance(std::size_t points) {
    done_ += points, solved_ += points;
    if (!shown_) return;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double rate = seconds > 0 ? static_cast<double>(solved_) / seconds : 0;
    char text[160];
    std::snprintf(text, sizeof text, "\rmap: %zu/%zu points (%.0f %%), %.3g points/s, about %.0f s left   ", done_,
                  total_, 100.0 * static_cast<double>(done_) / static_cast<double>(total_), rate,
                  rate > 0 ? static_cast<double>(total_ - done_) / rate : 0.0);
    err_ << text << std::flush;
  }
  ~Progress() {
    if (shown_) err_ << "\n";
  }

 private:
  std::ostream& err_;
  bool shown_;
  std::size_t total_, done_, solved_ = 0;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, separator)) parts.push_back(part);
  if (!text.empty() && text.back() == separator) parts.emplace_back();
  return parts;
}

std::vector<double> axis_values(const std::string& name, const std::string& text) {
  if (text.find(':') == std::string::npos) {
    std::vector<double> values;
    for (const std::string& part : split(text, ',')) values.push_back(number(name, part));
    if (values.empty()) throw UsageError("--" + name + ": no values");
    return values;
  }
  const std::vector<std::string> parts = split(text, ':');
  if (parts.size() != 3 && !(parts.size() == 4 && parts[3] == "log")) {
    throw UsageError("--" + name + ": \"" + text +
                     "\" is neither start:stop:count, start:stop:count:log nor a comma list");
  }
  const double start = number(name, parts[0]), stop = number(name, parts[1]), count = number(name, parts[2]);
  const bool log = parts.size() == 4;
  if (!(count >= 1 && count == std::floor(count) && count <= 1e7)) {
    throw UsageError("--" + name + ": the count " + parts[2] + " is not a whole number from 1 on");
  }
  if (stop < start) throw UsageError("--" + name + ": the range " + text + " is reversed (stop below start)");
  if (count > 1 && stop == start) throw UsageError("--" + name + ": the range " + text + " is empty (start = stop)");
  if (log && !(start > 0)) throw UsageError("--" + name + ": a log range needs start > 0 (" + text + ")");
  const auto n = static_cast<std::size_t>(count);
  std::vector<double> values;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = n == 1 ? 0.0 : static_cast<double>(i) / static_cast<double>(n - 1);
    values.push_back(i + 1 == n ? stop : log ? start * std::pow(stop / start, t) : start + (stop - start) * t);
  }
  return values;
}

void MapArguments::add_to(CLI::App* app) {
  app->add_option("--H1", H1, "height of the waviness H1 [length]")->required();
  app->add_option("--b1", b1, "half-period b1 of the waviness [length]")->required();
  app->add_option("--E", E, "reduced modulus E* [pressure]")->required();
  app->add_option("--m", m, "shapes: start:stop:count, start:stop:count:log or a comma list")->capture_default_str();
  app->add_option("--H2", H2, "roughness heights [length], as --m (with --n; none: the wave curve alone)");
  app->add_option("--n", n, "wavelength ratios n = b1/b2, even whole numbers, as --m (with --H2)");
  app->add_option("--harmonics", harmonics,
                  "or whole roughnesses, a comma list of H:n+H:n... (e.g. 0.15:6+0.01:64,0.0375:32)");
  auto* ratio = app->add_option("--pa-over-pstar", pa_over_pstar, "loads as pa/p*, ascending, as --m");
  auto* load = app->add_option("--P", P, "loads per unit length P [pressure x length], ascending, as --m");
  ratio->excludes(load);
  app->add_option("--out", out, "the CSV file: created, or completed where a run with these arguments left it")
      ->required();
  app->add_option("--tolerance", tolerance, "relative error each contact must meet")->capture_default_str();
  app->add_option("--max-seconds", max_seconds, "work budget of each load [s]")->capture_default_str();
  app->add_option("--threads", threads, "load lines solved at once (0: one a core)")->capture_default_str();
  app->add_flag("--force", force, "allow more than " + std::to_string(most_map_points) + " points");
  plot.add_to(app);
}

MapGrid MapArguments::grid() const {
  if (H2.empty() != n.empty()) throw UsageError("--H2 and --n go together (neither: the wave curve alone)");
  if (!harmonics.empty() && !H2.empty()) throw UsageError("give either --H2 and --n or --harmonics");
  if (pa_over_pstar.empty() == P.empty()) throw UsageError("give exactly one of --pa-over-pstar, --P");
  MapGrid g;
  g.waviness = {H1, b1, 0.0, E};
  g.m = axis_values("m", m);
  if (!H2.empty()) {
    g.H2 = axis_values("H2", H2);
    for (double v : axis_values("n", n)) g.n.push_back(whole("n", v));
  }
  for (const std::string& roughness : split(harmonics, ',')) {
    std::vector<Harmonic> set;
    for (const std::string& harmonic : split(roughness, '+')) {
      const std::vector<std::string> parts = split(harmonic, ':');
      if (parts.size() != 2) {
        throw UsageError("--harmonics: \"" + cli_common::shortened(harmonic) + "\" is not H:n");
      }
      set.push_back({number("harmonics", parts[0]), whole("harmonics", number("harmonics", parts[1]))});
    }
    g.harmonics.push_back(std::move(set));
  }
  g.loads_are_ratios = !pa_over_pstar.empty();
  g.loads = axis_values(g.loads_are_ratios ? "pa-over-pstar" : "P", g.loads_are_ratios ? pa_over_pstar : P);
  validate(g, "wavecontact map");
  return g;
}

std::vector<MapAxis> MapArguments::axes(const MapGrid& g) const {
  const auto logarithmic = [](const std::string& text) {
    return text.size() > 4 && text.substr(text.size() - 4) == ":log";
  };
  std::vector<MapAxis> list{{"m", g.m, logarithmic(m)}};
  if (!g.H2.empty()) {
    list.push_back({"H2", g.H2, logarithmic(H2)});
    list.push_back({"n", std::vector<double>(g.n.begin(), g.n.end()), logarithmic(n)});
  }
  if (!g.harmonics.empty()) {
    std::vector<double> places;
    for (std::size_t k = 0; k < g.harmonics.size(); ++k) places.push_back(static_cast<double>(k));
    list.push_back({"harmonics", places, false});
  }
  const std::string& loads = g.loads_are_ratios ? pa_over_pstar : P;
  list.push_back({g.loads_are_ratios ? "pa-over-pstar" : "P", g.loads, logarithmic(loads)});
  return list;
}

std::vector<std::string> MapArguments::header() const {
  return {"# wavecontact map: one row a point, in any order; a rerun with these arguments completes it",
          "# H1=" + all_digits(H1) + " b1=" + all_digits(b1) + " E=" + all_digits(E) +
              " tolerance=" + all_digits(tolerance) + " max_seconds=" + all_digits(max_seconds),
          "# m=" + m + " H2=" + H2 + " n=" + n + " harmonics=" + harmonics +
              (pa_over_pstar.empty() ? " P=" + P : " pa_over_pstar=" + pa_over_pstar),
          map_columns};
}

std::string run_map(const MapArguments& options, std::ostream& err) {
  const MapGrid grid = options.grid();
  const std::size_t points = grid.point_count(), per_line = grid.loads.size();
  if (points > most_map_points && !options.force) {
    throw UsageError("the grid has " + std::to_string(points) + " points, more than " +
                     std::to_string(most_map_points) + ": give --force to solve them all");
  }
  if (!(options.tolerance >= 1e-14 && options.tolerance <= 1e-2)) {
    throw UsageError("--tolerance " + digits(options.tolerance) + " is outside 1e-14 to 1e-2");
  }
  if (!(options.max_seconds > 0 && options.max_seconds <= 1e6)) {
    throw UsageError("--max-seconds " + digits(options.max_seconds) + " is outside (0, 1e6]");
  }
  const std::vector<MapAxis> axes = options.axes(grid);
  if (options.plot.wanted()) options.plot.check(axes);
  std::optional<MapFile> file(std::in_place, options.out, options.header(), points);
  const std::size_t already = file->done_count();
  Progress progress(err, points, already);
  std::size_t beyond = 0, above = 0, unsolved_before = file->unsolved_count();
  MapOptions run;
  run.solver = SolverOptions(options.tolerance, 0, options.max_seconds);
  run.threads = options.threads;
  map_contacts(
      grid, run,
      [&](std::size_t line) {
        for (std::size_t k = 0; k < per_line; ++k) {
          if (!file->done(line * per_line + k)) return false;
        }
        return true;
      },
      [&](const std::vector<MapPoint>& line) {
        std::string rows;
        std::size_t added = 0;
        for (const MapPoint& p : line) {
          if (file->done(p.index)) continue;
          rows += row(p), ++added;
          beyond += p.status == MapStatus::beyond_reach, above += p.status == MapStatus::above_tolerance;
        }
        file->append(rows);
        progress.advance(added);
      });
  file.reset();  // closed before the plot reads it
  std::string summary = "map: " + std::to_string(points) + " points in " + options.out + ": " +
                        std::to_string(points - already) + " solved now, " + std::to_string(already) + " there before";
  if (options.plot.wanted()) summary += "; drew " + draw_map_plot(options.plot, grid, axes, options.out);
  if (beyond + above + unsolved_before > 0) {
    throw NotWithinTolerance(summary + "; " + std::to_string(beyond) + " beyond reach and " + std::to_string(above) +
                             " above the tolerance now, " + std::to_string(unsolved_before) +
                             " of either there before (the status column says which)");
  }
  return summary + "\n";
}

}  // namespace wavecontact::cli
