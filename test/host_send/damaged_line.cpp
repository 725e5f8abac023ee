#include "damaged_line.hpp"

#include <catch2/catch.hpp>

#include "test_support.hpp"

namespace hs_test {

DamagedLine::DamagedLine(Board who, const std::string& protocol, const std::vector<std::string>& faults,
                         const std::string& size, const std::string& format) {
  if (who == Board::kStandin) {
    start_standin(board, size, format, protocol);
  } else {
    // firmware-sim with the firmware on its own pty. Raw mode gets
    // --idle-polls 0: a damaged line has silences longer than the default
    // count of empty polls (a fraction of a second in the simulator);
    // framed mode must cope with them at the default (its allowance is
    // MINRT_FRAMED_IDLE_FACTOR times longer).
    minrt::send::SimConfig cfg;
    cfg.simulator = HS_FIRMWARE_SIM;
    cfg.firmware = HS_FIRMWARE_ELF;
    cfg.firmware_args = {"--size", size, "--format", format, "--protocol=" + protocol};
    if (protocol == "raw") {
      cfg.firmware_args.push_back("--idle-polls");
      cfg.firmware_args.push_back("0");
    }
    std::string err;
    REQUIRE(board.start(cfg, err));
  }
  std::string err;
  minrt::send::SimConfig r;
  r.exact_args = {HS_FAULT_RELAY};
  r.exact_args.insert(r.exact_args.end(), faults.begin(), faults.end());
  r.exact_args.push_back(board.pty_path());
  REQUIRE(relay.start(r, err));
  port = relay.pty_path();
}

DamagedLine::~DamagedLine() {
  relay.stop(3000);
  board.stop(3000);
}

std::string DamagedLine::report() {
  relay.stop(3000);
  return relay.output();
}

}  // namespace hs_test
