// host-send: sends a scene to the renderer firmware over a serial line (or
// to firmware-sim) and writes the image it sends back.
#include <cstdio>
#include <string>

#include "cli.hpp"
#include "run.hpp"

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
