// wavecontact: command-line front end of the runtime library.
#include <cstdio>
#include <iostream>

#include "app.hpp"
#include "exit_status.hpp"

int main(int argc, char** argv) {
  const int status = wavecontact::cli::run(argc, argv, std::cout, std::cerr);
  // What the standard output still buffers must reach it, or the run failed.
  std::cout.flush();
  if (status == wavecontact::exit_status::success && (!std::cout || std::fflush(stdout) != 0 || std::ferror(stdout))) {
    std::cerr << "wavecontact: cannot write the output (standard output)\n";
    return wavecontact::exit_status::io_error;
  }
  return status;
}
