// `wavecontact map` and wavecontact::map_contacts (issue: maps of shape and scale): every row
// the contact solve_contact gives for its load line, bit for bit, whatever the threads, over
// H2 and n or a list of roughnesses; a file cut short or killed mid-run completed by a rerun,
// with no row lost or written twice; the heat map's table; the refusals.
#define BOOST_TEST_MODULE map
#include <boost/test/unit_test.hpp>

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "run_command.hpp"
#include "wavecontact/map.hpp"

namespace fs = std::filesystem;

namespace {

using wavecontact::test::CommandResult;

CommandResult run(const std::vector<std::string>& arguments) {
  std::vector<std::string> argv{WAVECONTACT_CLI, "map"};
  argv.insert(argv.end(), arguments.begin(), arguments.end());
  return wavecontact::test::run_command(argv);
}

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("wavecontact_map_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  fs::remove(dir / name);
  return dir / name;
}

std::vector<std::string> lines_of(const fs::path& path) {
  std::vector<std::string> lines;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// The rows (no header) by index; a duplicate index fails the test.
std::map<std::size_t, std::string> rows_of(const fs::path& path) {
  std::map<std::size_t, std::string> rows;
  for (const std::string& line : lines_of(path)) {
    if (line.empty() || line[0] == '#' || line.rfind("index,", 0) == 0) continue;
    const std::size_t index = std::stoul(line.substr(0, line.find(',')));
    BOOST_TEST(rows.count(index) == 0u, "row " << index << " written twice");
    rows[index] = line;
  }
  return rows;
}

std::vector<std::string> fields(const std::string& row) {
  std::vector<std::string> out;
  std::istringstream in(row);
  for (std::string f; std::getline(in, f, ',');) out.push_back(f);
  return out;
}

std::string digits(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

const std::vector<std::string> profile{"--H1", "1", "--b1", "10", "--E", "1"};

std::vector<std::string> with_profile(std::vector<std::string> arguments) {
  arguments.insert(arguments.begin(), profile.begin(), profile.end());
  return arguments;
}

}  // namespace

// Each row holds what solve_contact gives for the row's load line, to the last bit: the
// roughness at m = 0 and m = 10 (its valley touching at pa/p* = 1.2), and the wave curve alone.
BOOST_AUTO_TEST_CASE(rows_are_the_solved_contacts) {
  struct Case {
    std::vector<std::string> grid;
    std::vector<double> m, loads;
    double H2;
    int n;
  };
  const std::vector<Case> cases{{{"--m", "0,10", "--H2", "0.03", "--n", "16", "--pa-over-pstar", "0.2:1.2:3"},
                                 {0, 10},
                                 {0.2, 0.7, 1.2},
                                 0.03,
                                 16},
                                {{"--m", "0.5:2:2", "--pa-over-pstar", "0.1,0.4"}, {0.5, 2}, {0.1, 0.4}, 0, 0}};
  for (const Case& k : cases) {
    const fs::path out = scratch("rows.csv");
    std::vector<std::string> arguments = with_profile(k.grid);
    arguments.insert(arguments.end(), {"--out", out.string()});
    const CommandResult r = run(arguments);
    BOOST_TEST_REQUIRE(r.status == 0, r.err);
    const auto rows = rows_of(out);
    BOOST_TEST_REQUIRE(rows.size() == k.m.size() * k.loads.size());
    for (std::size_t line = 0; line < k.m.size(); ++line) {
      const wavecontact::WavinessParams w{1.0, 10.0, k.m[line], 1.0};
      const wavecontact::Surface surface = k.n > 0 ? wavecontact::Surface(w, {{k.H2, k.n}}) : wavecontact::Surface(w);
      std::vector<double> P;
      for (double ratio : k.loads) P.push_back(ratio * M_PI);
      const std::vector<wavecontact::Contact> contacts = wavecontact::solve_contact(surface, P);
      for (std::size_t j = 0; j < P.size(); ++j) {
        const std::vector<std::string> f = fields(rows.at(line * P.size() + j));
        const wavecontact::Contact& c = contacts[j];
        const std::string where = "m = " + digits(k.m[line]) + ", pa/p* = " + digits(k.loads[j]);
        BOOST_TEST(f.at(4) == (k.n > 0 ? digits(k.H2) + ":" + std::to_string(k.n) : ""), where);
        BOOST_TEST(f.at(5) == digits(P[j]), where);
        BOOST_TEST(f.at(7) == "solved", where);
        BOOST_TEST(f.at(8) == std::to_string(c.zones_per_period()), where);
        BOOST_TEST(f.at(9) == digits(c.contact_fraction()), where);
        BOOST_TEST(f.at(10) == digits(c.pressure(0)), where);
        BOOST_TEST(f.at(11) == digits(c.max_pressure()), where);
        BOOST_TEST(f.at(12) == digits(c.error_estimate()), where);
      }
    }
  }
}

// A list of whole roughnesses as an axis: each row is solve_contact's for that roughness,
// which the row names.
BOOST_AUTO_TEST_CASE(a_list_of_roughnesses_is_an_axis) {
  const fs::path out = scratch("harmonics.csv");
  const CommandResult r = run(with_profile(
      {"--m", "0,10", "--harmonics", "0.15:6+0.01:64,0.0375:32", "--pa-over-pstar", "0.3,1", "--out", out.string()}));
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  const auto rows = rows_of(out);
  BOOST_TEST_REQUIRE(rows.size() == 8u);
  const std::vector<std::vector<wavecontact::Harmonic>> roughnesses{{{0.15, 6}, {0.01, 64}}, {{0.0375, 32}}};
  const std::vector<std::string> names{digits(0.15) + ":6+" + digits(0.01) + ":64", digits(0.0375) + ":32"};
  for (std::size_t i = 0; i < 2; ++i) {
    for (std::size_t k = 0; k < roughnesses.size(); ++k) {
      const wavecontact::Surface surface({1.0, 10.0, i == 0 ? 0.0 : 10.0, 1.0}, roughnesses[k]);
      const std::vector<wavecontact::Contact> contacts = wavecontact::solve_contact(surface, {0.3 * M_PI, M_PI});
      for (std::size_t j = 0; j < 2; ++j) {
        const std::vector<std::string> f = fields(rows.at((i * 2 + k) * 2 + j));
        BOOST_TEST(f.at(4) == names[k]);
        BOOST_TEST(f.at(2) == (k == 0 ? std::string("nan") : digits(0.0375)));
        BOOST_TEST(f.at(3) == (k == 0 ? "0" : "32"));
        BOOST_TEST(f.at(8) == std::to_string(contacts[j].zones_per_period()), names[k]);
        BOOST_TEST(f.at(9) == digits(contacts[j].contact_fraction()), names[k]);
      }
    }
  }
}

// --plot: the table gnuplot draws holds each solved row's value at its place on the two axes,
// and the PNG is whole.
BOOST_AUTO_TEST_CASE(plot_draws_a_column_over_two_axes) {
  const fs::path out = scratch("plotted.csv");
  const CommandResult r =
      run(with_profile({"--m", "0:4:3", "--H2", "0.02", "--n", "8", "--pa-over-pstar", "0.1:0.5:4:log", "--out",
                        out.string(), "--plot", "zones", "--x", "m", "--y", "pa-over-pstar"}));
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  const fs::path table = out.parent_path() / "plotted-zones.csv", png = out.parent_path() / "plotted-zones.png";
  BOOST_TEST(r.out.find("drew " + png.string()) != std::string::npos, r.out);
  std::ifstream image(png, std::ios::binary);
  std::string signature(8, '\0');
  image.read(signature.data(), 8);
  BOOST_TEST((signature == "\x89PNG\r\n\x1a\n"));
  std::map<std::pair<std::string, std::string>, std::string> drawn;  // (m, pa/p*) -> zones
  for (const std::string& line : lines_of(table)) {
    if (line.empty() || line[0] == '#') continue;
    const std::vector<std::string> f = fields(line);
    drawn[{f.at(0), f.at(1)}] = f.at(2);
  }
  const auto rows = rows_of(out);
  BOOST_TEST_REQUIRE(drawn.size() == rows.size());
  for (const auto& [index, row] : rows) {
    const std::vector<std::string> f = fields(row);
    char m[40], ratio[40];
    std::snprintf(m, sizeof m, "%.10g", std::stod(f.at(1)));
    std::snprintf(ratio, sizeof ratio, "%.10g", std::stod(f.at(6)));
    const std::string value = drawn[{m, ratio}];
    BOOST_TEST(value == f.at(8), row);
  }
  BOOST_TEST(fs::exists(out.parent_path() / "plotted-zones.gp"));
}

// The load axis answers to its column's name too: a rerun that only draws, with --y
// pa_over_pstar, writes the table that --y pa-over-pstar wrote.
BOOST_AUTO_TEST_CASE(plot_takes_the_load_axis_by_its_column_name) {
  const fs::path out = scratch("plotted_by_column.csv"), table = out.parent_path() / "plotted_by_column-zones.csv";
  const std::string names[2] = {"pa-over-pstar", "pa_over_pstar"};
  std::string drawn[2];
  for (int k = 0; k < 2; ++k) {
    const CommandResult r = run(with_profile({"--m", "0,4", "--H2", "0.02", "--n", "8", "--pa-over-pstar", "0.1,0.3",
                                              "--out", out.string(), "--plot", "zones", "--x", "m", "--y", names[k]}));
    BOOST_TEST_REQUIRE(r.status == 0, names[k] << ": " << r.err);
    for (const std::string& line : lines_of(table)) drawn[k] += line + "\n";
  }
  BOOST_TEST(!drawn[0].empty());
  BOOST_TEST(drawn[0] == drawn[1]);
}

BOOST_AUTO_TEST_CASE(bad_plots_are_refused_before_any_work) {
  const fs::path out = scratch("refused_plot.csv");
  const std::vector<std::string> grid{"--m", "0,1", "--H2", "0.02", "--n", "8,16", "--pa-over-pstar", "0.1,0.2"};
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"--plot", "speed", "--x", "m", "--y", "n"}, "no column \"speed\""},
      {{"--plot", "zones", "--x", "m", "--y", "m"}, "both m"},
      {{"--plot", "zones", "--x", "m", "--y", "harmonics"}, "no axis \"harmonics\""},
      {{"--plot", "zones", "--x", "m", "--y", "H2"}, "the axis H2 holds one value"},
      {{"--plot", "zones", "--x", "m", "--y", "n"}, "the axis pa-over-pstar holds 2 values"},
      {{"--plot", "zones"}, "--x"},
  };
  for (const auto& [plot, message] : cases) {
    std::vector<std::string> arguments = with_profile(grid);
    arguments.insert(arguments.end(), {"--out", out.string()});
    arguments.insert(arguments.end(), plot.begin(), plot.end());
    const CommandResult r = run(arguments);
    BOOST_TEST(r.status == 2, message << ": " << r.err);
    BOOST_TEST(r.err.find(message) != std::string::npos, r.err);
    BOOST_TEST(!fs::exists(out), message);
  }
}

// The library's map gives the same points on one thread as on several, each line once.
BOOST_AUTO_TEST_CASE(threads_change_nothing) {
  wavecontact::MapGrid grid;
  grid.waviness = {1.0, 10.0, 0.0, 1.0};
  grid.m = {0, 1, 3};
  grid.H2 = {0.02};
  grid.n = {8, 12};
  grid.loads = {0.2, 0.5};
  grid.loads_are_ratios = true;
  const auto solve = [&](unsigned threads) {
    std::map<std::size_t, wavecontact::MapPoint> points;
    wavecontact::MapOptions options;
    options.threads = threads;
    wavecontact::map_contacts(grid, options, {}, [&](const std::vector<wavecontact::MapPoint>& line) {
      for (const wavecontact::MapPoint& p : line) {
        BOOST_TEST(points.count(p.index) == 0u);
        points[p.index] = p;
      }
    });
    return points;
  };
  const auto serial = solve(1), parallel = solve(3);
  BOOST_TEST_REQUIRE(serial.size() == grid.point_count());
  BOOST_TEST_REQUIRE(parallel.size() == grid.point_count());
  for (const auto& [index, p] : serial) {
    const wavecontact::MapPoint& q = parallel.at(index);
    BOOST_TEST((p.m == q.m && p.H2 == q.H2 && p.n == q.n && p.P == q.P), index);
    BOOST_TEST((p.zones == q.zones && p.contact_fraction == q.contact_fraction && p.p0 == q.p0 && p.max_p == q.max_p &&
                p.error_estimate == q.error_estimate),
               index);
  }
}

// The lines are taken the finest roughness first, the highest first among equally fine ones:
// on one thread they are handed over in that order.
BOOST_AUTO_TEST_CASE(the_costliest_lines_come_first) {
  wavecontact::MapGrid grid;
  grid.waviness = {1.0, 10.0, 0.0, 1.0};
  grid.m = {0};
  grid.H2 = {0.01, 0.02};
  grid.n = {8, 12};
  grid.loads = {0.3};
  grid.loads_are_ratios = true;
  std::vector<std::pair<int, double>> taken;
  wavecontact::MapOptions options;
  options.threads = 1;
  wavecontact::map_contacts(grid, options, {}, [&](const std::vector<wavecontact::MapPoint>& line) {
    taken.emplace_back(line.front().n, line.front().H2);
  });
  const std::vector<std::pair<int, double>> expected{{12, 0.02}, {12, 0.01}, {8, 0.02}, {8, 0.01}};
  BOOST_TEST_REQUIRE(taken.size() == expected.size());
  for (std::size_t i = 0; i < taken.size(); ++i)
    BOOST_TEST((taken[i] == expected[i]),
               "line " << i << " taken: n = " << taken[i].first << ", H2 = " << taken[i].second
                       << "; expected n = " << expected[i].first << ", H2 = " << expected[i].second);
}

// A file cut short (rows missing, the last one cut mid-row) is completed: the same rows as an
// uninterrupted run, none twice.
BOOST_AUTO_TEST_CASE(a_rerun_completes_a_file_cut_short) {
  const std::vector<std::string> grid{"--m", "0,2,4", "--H2", "0.02", "--n", "8", "--pa-over-pstar", "0.1:0.5:3"};
  const fs::path whole = scratch("whole.csv"), cut = scratch("cut.csv");
  std::vector<std::string> arguments = with_profile(grid);
  arguments.insert(arguments.end(), {"--out", whole.string()});
  BOOST_TEST_REQUIRE(run(arguments).status == 0);
  const std::vector<std::string> lines = lines_of(whole);
  {
    std::ofstream out(cut);
    for (std::size_t i = 0; i < 4 + 4; ++i) out << lines.at(i) << "\n";  // the header, rows 0-3
    out << lines.at(8).substr(0, 10);                                    // row 4, cut
  }
  arguments.back() = cut.string();
  const CommandResult r = run(arguments);
  BOOST_TEST_REQUIRE(r.status == 0, r.err);
  BOOST_TEST(r.out.find("5 solved now, 4 there before") != std::string::npos, r.out);
  BOOST_TEST((rows_of(cut) == rows_of(whole)));
  BOOST_TEST(run(arguments).out.find("0 solved now, 9 there before") != std::string::npos);
}

// A run killed mid-way (SIGKILL) leaves only whole rows, or one cut row that the rerun drops;
// the rerun then writes exactly the missing ones.
BOOST_AUTO_TEST_CASE(a_killed_run_loses_no_written_row) {
  const std::vector<std::string> grid{"--m",   "0:6:7",           "--H2",     "0.05",      "--n",
                                      "16,32", "--pa-over-pstar", "0.05:1:4", "--threads", "2"};
  const fs::path whole = scratch("whole_kill.csv"), killed = scratch("killed.csv");
  std::vector<std::string> arguments = with_profile(grid);
  arguments.insert(arguments.end(), {"--out", whole.string()});
  const CommandResult full = run(arguments);
  BOOST_TEST_REQUIRE(full.status == 0, full.err);
  arguments.back() = killed.string();
  std::vector<std::string> argv{WAVECONTACT_CLI, "map"};
  argv.insert(argv.end(), arguments.begin(), arguments.end());
  std::vector<char*> args;
  for (std::string& a : argv) args.push_back(a.data());
  args.push_back(nullptr);
  pid_t pid = 0;
  BOOST_TEST_REQUIRE(posix_spawn(&pid, args[0], nullptr, nullptr, args.data(), environ) == 0);
  // Killed once some rows are written, before the end.
  const auto rows_now = [&] { return lines_of(killed).size(); };
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (rows_now() < 4 + 8 && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ::kill(pid, SIGKILL);
  int raw = 0;
  waitpid(pid, &raw, 0);
  BOOST_TEST(WIFSIGNALED(raw), "the run ended before it was killed");
  const std::size_t before = rows_of(killed).size();
  BOOST_TEST(before < rows_of(whole).size());
  const CommandResult rerun = run(arguments);
  BOOST_TEST_REQUIRE(rerun.status == 0, rerun.err);
  BOOST_TEST((rows_of(killed) == rows_of(whole)));
}

BOOST_AUTO_TEST_CASE(bad_grids_are_refused_before_any_work) {
  const fs::path out = scratch("refused.csv");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"--m", "3:0:3", "--pa-over-pstar", "0.1"}, "reversed"},
      {{"--m", "0:3:0", "--pa-over-pstar", "0.1"}, "whole number from 1 on"},
      {{"--m", "1:1:4", "--pa-over-pstar", "0.1"}, "empty"},
      {{"--m", "0", "--pa-over-pstar", "0:1:3:log"}, "log range needs start > 0"},
      {{"--m", "0", "--pa-over-pstar", "0.5,0.1"}, "ascending"},
      {{"--m", "", "--pa-over-pstar", "0.1"}, "--m: no values"},
      {{"--m", "0x10", "--pa-over-pstar", "0.1"}, "\"0x10\" is not a decimal number"},
      {{"--m", "0", "--H2", "0.02", "--pa-over-pstar", "0.1"}, "--H2 and --n go together"},
      {{"--m", "0", "--H2", "0.02", "--n", "7", "--pa-over-pstar", "0.1"}, "n = 7"},
      {{"--m", "0", "--harmonics", "0.02:8+0.01", "--pa-over-pstar", "0.1"}, "\"0.01\" is not H:n"},
      {{"--m", "0", "--harmonics", "0.02:0", "--pa-over-pstar", "0.1"}, "n = 0"},
      {{"--m", "0", "--H2", "0.02", "--n", "8", "--harmonics", "0.02:8", "--pa-over-pstar", "0.1"},
       "either --H2 and --n or --harmonics"},
      {{"--m", "0:1:400", "--pa-over-pstar", "0.1:1:400"}, "give --force"},
  };
  for (const auto& [grid, message] : cases) {
    std::vector<std::string> arguments = with_profile(grid);
    arguments.insert(arguments.end(), {"--out", out.string()});
    const CommandResult r = run(arguments);
    BOOST_TEST(r.status == 2, message << ": " << r.err);
    BOOST_TEST(r.err.find(message) != std::string::npos, r.err);
    BOOST_TEST(!fs::exists(out), message);
  }
  const CommandResult unwritable =
      run(with_profile({"--m", "0", "--pa-over-pstar", "0.1", "--out", "/nonexistent-directory/map.csv"}));
  BOOST_TEST(unwritable.status == 5, unwritable.err);
  BOOST_TEST(unwritable.err.find("cannot write --out") != std::string::npos, unwritable.err);
  // A file of another map is left as it is.
  BOOST_TEST_REQUIRE(run(with_profile({"--m", "0", "--pa-over-pstar", "0.1", "--out", out.string()})).status == 0);
  const std::vector<std::string> kept = lines_of(out);
  const CommandResult other = run(with_profile({"--m", "1", "--pa-over-pstar", "0.1", "--out", out.string()}));
  BOOST_TEST(other.status == 2, other.err);
  BOOST_TEST(other.err.find("holds a map of other parameters") != std::string::npos, other.err);
  BOOST_TEST((lines_of(out) == kept));
}
