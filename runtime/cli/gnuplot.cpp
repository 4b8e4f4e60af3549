#include "gnuplot.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>

#include "refusals.hpp"

extern char** environ;

namespace wavecontact::cli {

namespace fs = std::filesystem;

namespace {

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

void write_file(const fs::path& path, const std::string& contents) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << contents;
  out.close();
  if (!out) throw OutputError("cannot write " + path.string() + ": " + std::strerror(errno));
}

std::string gnuplot_preamble(const std::string& png) {
  return "set terminal pngcairo size 1100,650 font 'DejaVu Sans,10'\nset output '" + png +
         "'\nset datafile separator ','\nset grid\n";
}

void run_gnuplot(const fs::path& dir, const std::string& script, const std::string& png) {
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
  require_png(dir / png);
}

}  // namespace wavecontact::cli
