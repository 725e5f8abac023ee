// Command line of firmware-sim: `firmware-sim [OPTIONS] ELF [-- ARGS...]`.
#pragma once
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace fwsim {

// The bounds of an unattended run (--no-limit lifts both): 4e12
// instructions, about an hour of generated code at 1,000 MIPS and 75 times
// the longest render the benches run (53 billion); 1 GiB of UART output,
// five times the largest image (4096x4096 as P3, 12 bytes a pixel).
inline constexpr uint64_t kDefaultMaxInstructions = 4'000'000'000'000ull;
inline constexpr uint64_t kDefaultMaxOutput = uint64_t{1} << 30;

struct CliOptions {
  std::string elf;                // the ELF, or with load_hex the image file
  bool load_hex = false;          // --load-hex: elf names a $readmemh/.mem/.coe image
  std::vector<std::string> args;  // after "--", passed to main(argc, argv)
  std::string uart_in, uart_out;  // empty = stdin / stdout
  bool pty = false;
  bool real_board = false;        // --real-board: no boot arguments; with --pty, hosts come and go
  uint64_t baud = 0;              // 0 = no pacing
  std::string cycle_model;        // file, or "default"
  std::string fpu_model;          // FPU model file; empty = IEEE
  std::vector<std::string> fpu_settings;  // --fpu lists, applied in order after the file
  bool fpu_check = false;         // measure the FPU model's error instead of running an ELF
  std::string profile_out, folded_out;
  uint64_t max_instructions = kDefaultMaxInstructions;  // UINT64_MAX = unlimited
  uint64_t max_output = kDefaultMaxOutput;              // UART bytes; UINT64_MAX = unlimited
  bool jit = true;                // --no-jit: no generated code (block_jit.hpp)
  uint32_t ram_size = 0;          // --ram-size; 0 = from the map
  // Memory map (memory_map.hpp): the machine file first, then --ram,
  // --ram-size, --uart and --finisher on top of it; empty = unchanged.
  std::string machine_file;
  std::string board_file;         // --board: board description (board_file.hpp)
  std::string ram_spec, uart_base, finisher_base;
  bool stats = false;
  bool trace = false;
  std::string commit_log;         // --commit-log FILE (spike's commit-log layout)
  std::string flame_out;          // flame graph SVG
  int gdb_port = -1;              // -1 = no GDB stub; 0 = any free port
};

// A bad option value, thrown while the command line is read.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Parses argv[1..argc) with the table parser (posix/command_line.hpp).
// False when firmware-sim ends now with `status`: 0 after --help or
// --version, 2 after the one-line usage error.
bool parse_cli(int argc, char** argv, const char* version, CliOptions& o, int& status);

}  // namespace fwsim
