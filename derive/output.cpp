#include "output.hpp"

#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <set>
#include <stdexcept>
#include <string>

namespace wavecontact::derive {

namespace fs = std::filesystem;

namespace {

const std::string staging_marker = ".staging-";

std::string staging_prefix(const fs::path& directory) {
  return "." + directory.filename().string() + staging_marker;
}

// Staging directories of runs that no longer exist.
void remove_stale_staging(const fs::path& directory) {
  const std::string prefix = staging_prefix(directory);
  for (const auto& entry : fs::directory_iterator(directory.parent_path())) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    const std::string pid = name.substr(prefix.size());
    if (pid.empty() || pid.find_first_not_of("0123456789") != std::string::npos) continue;
    if (::kill(static_cast<pid_t>(std::stol(pid)), 0) != 0 && errno == ESRCH) {
      fs::remove_all(entry.path());
    }
  }
}

void write_file(const fs::path& path, const std::string& contents) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << contents;
  out.flush();
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace

void write_directory_atomically(const fs::path& requested, const std::vector<GeneratedFile>& files) {
  const fs::path directory = fs::absolute(requested).lexically_normal();
  const fs::path target = directory.filename().empty() ? directory.parent_path() : directory;
  fs::create_directories(target.parent_path());
  remove_stale_staging(target);

  const fs::path staging = target.parent_path() / (staging_prefix(target) + std::to_string(::getpid()));
  fs::remove_all(staging);
  fs::create_directory(staging);

  std::set<std::string> written;
  for (const auto& file : files) written.insert(file.name);
  const bool existed = fs::exists(target);
  if (existed) {
    if (!fs::is_directory(target)) throw std::runtime_error(target.string() + " is not a directory");
    for (const auto& entry : fs::directory_iterator(target)) {
      if (written.count(entry.path().filename().string())) continue;
      fs::copy(entry.path(), staging / entry.path().filename(),
               fs::copy_options::recursive | fs::copy_options::copy_symlinks);
    }
  }
  for (const auto& file : files) write_file(staging / file.name, file.contents);

  if (existed) {
    if (::renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, target.c_str(), RENAME_EXCHANGE) != 0) {
      throw std::runtime_error("cannot exchange " + staging.string() + " with " + target.string() +
                               ": " + std::strerror(errno));
    }
    fs::remove_all(staging);  // now the previous contents
  } else {
    fs::rename(staging, target);
  }
}

}  // namespace wavecontact::derive
