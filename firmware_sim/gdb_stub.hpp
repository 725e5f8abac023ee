// GDB remote serial protocol stub: firmware-sim --gdb PORT waits on
// 127.0.0.1:PORT for one gdb connection and runs the machine under its
// control (registers, memory, software breakpoints, step, continue).
#pragma once
#include <cstdint>
#include <set>
#include <string>

#include "machine.hpp"

namespace fwsim {

class GdbStub {
 public:
  // Listens on 127.0.0.1:port (0 = a free port the system picks). Throws
  // std::runtime_error with the reason when the port cannot be opened.
  explicit GdbStub(int port);
  ~GdbStub();
  GdbStub(const GdbStub&) = delete;
  GdbStub& operator=(const GdbStub&) = delete;

  int port() const { return port_; }
  // Waits for gdb, then serves it until the program ends (its stop is
  // returned), gdb kills it (`killed` set) or detaches (the program then
  // runs on to its end without the debugger). Never runs past
  // `max_instructions`.
  StopInfo serve(Machine& m, uint64_t max_instructions, bool& killed);

 private:
  bool read_packet(std::string& packet);  // false: connection closed
  void send_packet(const std::string& payload);
  std::string handle_query(const std::string& q);
  // "monitor CMD" (qRcmd): icount, reset, help; output goes as an O packet.
  std::string handle_monitor(Machine& m, const std::string& hex_command, const HartState& reset_state, StopInfo& last);
  // Runs one instruction or until a breakpoint/stop/interrupt.
  StopInfo step(Machine& m, uint64_t max_instructions);
  StopInfo resume(Machine& m, uint64_t max_instructions);
  bool interrupt_pending();
  std::string stop_reply(const StopInfo& s) const;

  int listen_fd_ = -1, fd_ = -1;
  int port_ = 0;
  std::string inbuf_;
  std::set<uint32_t> breakpoints_;
};

// The target description gdb reads through qXfer:features:read.
const std::string& gdb_target_xml();

}  // namespace fwsim
