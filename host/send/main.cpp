// host-send: sends an SLD scene to the min-rt firmware and receives the PPM.
#include <cstdio>
#include <string>

#include "cli.hpp"

int main(int argc, char** argv) {
  minrt::send::Options options;
  std::string error;
  switch (minrt::send::parse_command_line(argc, argv, options, error)) {
    case minrt::send::ParseResult::kHelp:
      minrt::send::print_help();
      return 0;
    case minrt::send::ParseResult::kVersion:
      std::printf("host-send %s\n", MINRT_VERSION);
      return 0;
    case minrt::send::ParseResult::kError:
      std::fprintf(stderr, "host-send: error: %s (see host-send --help)\n", error.c_str());
      return minrt::send::kExitUsage;
    case minrt::send::ParseResult::kRun:
      break;
  }
  return minrt::send::run(options);
}
