// Runs a program with an argument vector (posix_spawn, no shell: any argument is passed as it
// is), its output captured, for the command-line tests.
#pragma once

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace wavecontact::test {

struct CommandResult {
  int status;  // the exit status, -1 if killed by a signal
  std::string out, err;
  double seconds;
};

struct CommandOptions {
  std::string stdout_path;               // where stdout goes instead of being captured (/dev/full)
  std::vector<std::string> environment;  // NAME=VALUE added to (or replacing in) the environment
};

inline std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline CommandResult run_command(const std::vector<std::string>& argv, const CommandOptions& options = {}) {
  namespace fs = std::filesystem;
  static int counter = 0;
  const fs::path dir = fs::temp_directory_path() / ("wavecontact_test_run_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string id = std::to_string(counter++);
  const fs::path out = options.stdout_path.empty() ? dir / ("out" + id) : fs::path(options.stdout_path);
  const fs::path err = dir / ("err" + id);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<std::string> environment;
  for (char** e = environ; *e; ++e) {
    const std::string entry = *e;
    bool replaced = false;
    for (const std::string& added : options.environment) {
      replaced = replaced || entry.substr(0, entry.find('=') + 1) == added.substr(0, added.find('=') + 1);
    }
    if (!replaced) environment.push_back(entry);
  }
  environment.insert(environment.end(), options.environment.begin(), options.environment.end());
  std::vector<char*> args, envp;
  std::vector<std::string> argv_copy = argv, env_copy = environment;
  for (std::string& a : argv_copy) args.push_back(a.data());
  for (std::string& e : env_copy) envp.push_back(e.data());
  args.push_back(nullptr), envp.push_back(nullptr);
  const auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, args[0], &actions, nullptr, args.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) throw std::runtime_error("cannot run " + argv.at(0));
  int raw = 0;
  waitpid(pid, &raw, 0);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, options.stdout_path.empty() ? slurp(out) : "", slurp(err), seconds};
}

// The argument vector of `program` with `arguments` split at spaces (the tests' arguments hold
// none).
inline std::vector<std::string> command_line(const std::string& program, const std::string& arguments) {
  std::vector<std::string> argv{program};
  std::istringstream in(arguments);
  for (std::string word; in >> word;) argv.push_back(word);
  return argv;
}

// A program's output, line by line.
inline std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> result;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) result.push_back(line);
  return result;
}

// The numbers of a CSV row.
inline std::vector<double> fields(const std::string& line) {
  std::vector<double> values;
  std::istringstream in(line);
  for (std::string field; std::getline(in, field, ',');) values.push_back(std::stod(field));
  return values;
}

}  // namespace wavecontact::test
