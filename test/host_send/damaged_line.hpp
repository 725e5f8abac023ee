// A board (the stand-in, or the firmware in firmware-sim) on its own pty
// behind tools/fault_relay: host-send connects to `port` and gets the line
// damaged as `faults` says (fault-relay's options).
#pragma once

#include <string>
#include <vector>

#include "sim_launcher.hpp"

namespace hs_test {

enum class Board { kStandin, kFirmware };

struct DamagedLine {
  minrt::send::SimLauncher board, relay;
  std::string port;  // where host-send connects

  // `size`/`format`/`protocol` as the board renders and speaks.
  DamagedLine(Board who, const std::string& protocol, const std::vector<std::string>& faults,
              const std::string& size = "32x32", const std::string& format = "p6");
  ~DamagedLine();
  // What the relay did ("fault-relay: board->host N bytes: ..."), once stopped.
  std::string report();
};

}  // namespace hs_test
