// Control and status registers: fcsr/frm/fflags, the user counters
// cycle/time/instret (and their high halves), and a few machine-mode
// registers that a bare-metal crt0 touches (mstatus to enable the FPU on
// QEMU, mtvec, mscratch...). Traps are not delivered: these are plain storage.
#pragma once
#include <cstdint>

#include "hart_state.hpp"

namespace fwsim {

enum class CsrOp : uint8_t { Write, Set, Clear };

class CsrFile {
 public:
  // Timebase of the `time` CSR, as on QEMU's virt machine.
  static constexpr uint64_t kTimebaseHz = 10'000'000;

  explicit CsrFile(uint64_t clock_hz = 100'000'000) : clock_hz_(clock_hz) {}
  void set_clock_hz(uint64_t hz) { clock_hz_ = hz ? hz : 1; }

  // Performs a csrrw/csrrs/csrrc. `write` is false for csrrs/csrrc with
  // rs1 = x0 (or a zero immediate), which must not write. `hart.instret` and
  // `hart.cycles` must be current. Returns false for an unknown CSR or a write
  // to a read-only one (the caller raises an illegal instruction).
  bool access(HartState& hart, unsigned csr, CsrOp op, uint32_t operand, bool write, uint32_t& old);

 private:
  bool read(HartState& hart, unsigned csr, uint32_t& value) const;
  uint64_t clock_hz_;
  uint32_t mstatus_ = 0, mtvec_ = 0, mscratch_ = 0, mepc_ = 0, mcause_ = 0, mtval_ = 0, mie_ = 0;
};

}  // namespace fwsim
