// wavecontact: command-line front end of the runtime library.
#include <iostream>

#include "app.hpp"

int main(int argc, char** argv) { return wavecontact::cli::run(argc, argv, std::cout, std::cerr); }
