#include "stop_reason.hpp"

namespace fwsim {

const char* describe(StopCause c) {
  switch (c) {
    case StopCause::None: return "no stop";
    case StopCause::Exit: return "exit";
    case StopCause::IllegalInstruction: return "illegal instruction";
    case StopCause::Ebreak: return "ebreak";
    case StopCause::Ecall: return "ecall (no environment to call)";
    case StopCause::LoadFault: return "load access fault";
    case StopCause::StoreFault: return "store access fault";
    case StopCause::MisalignedLoad: return "misaligned load";
    case StopCause::MisalignedStore: return "misaligned store";
    case StopCause::FetchFault: return "instruction fetch outside RAM";
    case StopCause::MisalignedFetch: return "misaligned jump target";
    case StopCause::InstructionLimit: return "instruction limit exceeded";
    case StopCause::UartStall: return "UART input at end of file and firmware keeps polling it";
    case StopCause::HostIo: return "host I/O error";
    case StopCause::Breakpoint: return "breakpoint";
    case StopCause::Watchpoint: return "watchpoint";
    case StopCause::OutsideIsa: return "instruction outside the board's ISA";
  }
  return "?";
}

int exit_status(const StopInfo& s) {
  switch (s.cause) {
    case StopCause::Exit: return s.exit_code & 0xff;
    case StopCause::InstructionLimit: return kExitLimit;
    case StopCause::UartStall: return kExitUartStall;
    case StopCause::HostIo: return kExitIo;
    default: return kExitTrap;
  }
}

}  // namespace fwsim
