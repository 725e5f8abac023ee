// Starts firmware-sim (or anything with the same command line) with --pty
// and the renderer firmware, and finds the pseudo-terminal it announces on
// standard error ("firmware-sim: uart on /dev/pts/N").
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace minrt::send {

struct SimConfig {
  std::string simulator;  // firmware-sim binary
  std::string firmware;   // ELF
  std::uint32_t baud = 0; // 0: no --baud (unpaced)
  std::string ram_size;   // --ram-size for the simulator ("" = its default, 4 MiB)
  std::string board;      // --board FILE for the simulator ("" = its reference board)
  std::vector<std::string> firmware_args;  // after "--"
  int startup_timeout_ms = 10000;
  // When set: the whole command line, used as is (for helpers such as
  // fault-relay that announce a pty the same way); the fields above are
  // then ignored except startup_timeout_ms.
  std::vector<std::string> exact_args;
};

// The simulator path built in at configure time unless MINRT_FIRMWARE_SIM
// is set; likewise the firmware ELF and MINRT_FIRMWARE_ELF.
std::string default_simulator();
std::string default_firmware();

// Finds the pty path in one line of the simulator's standard error.
bool parse_pty_line(const std::string& line, std::string& path);

class SimLauncher {
 public:
  SimLauncher() = default;
  ~SimLauncher();
  SimLauncher(const SimLauncher&) = delete;
  SimLauncher& operator=(const SimLauncher&) = delete;

  // Starts the simulator and waits for its pty line; returns false with a
  // one-line message in `error`.
  bool start(const SimConfig& config, std::string& error);
  const std::string& pty_path() const { return pty_; }
  pid_t pid() const { return pid_; }
  // Waits up to timeout_ms for the simulator to exit, then terminates it.
  // Returns its exit status (or -1 if it had to be killed or failed).
  int stop(int timeout_ms);
  // Everything the simulator printed after the pty line.
  std::string output();

 private:
  void drain();
  bool spawn(std::vector<std::string> args, int startup_timeout_ms, std::string& error);

  pid_t pid_ = -1;
  int err_fd_ = -1;
  std::string pty_;
  std::thread drainer_;
  std::mutex mu_;
  std::string output_;
  int status_ = -1;
};

}  // namespace minrt::send
