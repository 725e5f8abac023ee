// Why a run ended, and the process exit status each reason maps to.
#pragma once
#include <cstdint>
#include <string>

namespace fwsim {

// Exit statuses of firmware-sim other than the firmware's own exit code.
inline constexpr int kExitUsage = 2;       // bad command line
inline constexpr int kExitLoad = 3;        // ELF missing, unreadable or not RV32 LE
inline constexpr int kExitTrap = 4;        // illegal instruction, access fault, ebreak, ecall...
inline constexpr int kExitLimit = 5;       // --max-instructions exceeded
inline constexpr int kExitUartStall = 6;   // firmware polls the UART forever after input EOF
inline constexpr int kExitIo = 7;          // host I/O problem (output file, pty)
inline constexpr int kExitKilled = 8;      // gdb killed the program (--gdb)

enum class StopCause : uint8_t {
  None,
  Exit,                // finisher written
  IllegalInstruction,
  Ebreak,
  Ecall,
  LoadFault,           // load outside RAM and devices
  StoreFault,
  MisalignedLoad,
  MisalignedStore,
  FetchFault,          // pc outside RAM
  MisalignedFetch,
  InstructionLimit,
  UartStall,
  HostIo,
  Breakpoint,          // a debugger breakpoint (gdb_stub.hpp); the instruction has not run
  OutsideIsa,          // an instruction the board's ISA lacks (--board)
  Watchpoint,          // a debugger watchpoint (gdb_stub.hpp); the accessing instruction has run
};

struct StopInfo {
  StopCause cause = StopCause::None;
  uint32_t pc = 0;        // pc of the instruction that stopped the run
  uint32_t addr = 0;      // faulting data address / jump target
  int exit_code = 0;      // for StopCause::Exit
  const char* detail = nullptr;  // OutsideIsa: what the instruction needs
  uint8_t watch_kind = 0;        // Watchpoint: 2 write, 3 read, 4 access (gdb's Z numbers)
};

const char* describe(StopCause c);
int exit_status(const StopInfo& s);

}  // namespace fwsim
