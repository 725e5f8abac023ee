// Pre-decoded instructions, one compact entry per word of code memory (RAM,
// or the board's ROM), indexed by (pc - code base) / 4; on a board with the
// C extension one per halfword, indexed by (pc - code base) / 2, where a
// 32-bit instruction's second halfword holds Op::SKIP (straight-line code
// steps over it uncounted). Entries are decoded lazily on first execution (op 0 =
// UNDECODED), so any code in RAM works; code written after it first ran is
// decoded again after a fence.i (invalidate_all), as RISC-V requires.
#pragma once
#include <cstdint>
#include <cstdlib>
#include <new>

#include "decoder.hpp"
#include "isa_subset.hpp"

namespace fwsim {

struct Entry {
  uint8_t op;              // Op
  uint8_t rd, rs1, rs2;    // rd = kSinkReg when the instruction writes x0
  int32_t imm;             // immediate; branch/jal: offset in entries;
                           // loads/stores: offset minus the RAM base;
                           // FP: rm in bits 0..7, rs3 in bits 8..15
                           // jal/jalr: rs2 = the instruction's length (the link is pc + rs2)
};
static_assert(sizeof(Entry) == 8);

// Set in FP entries whose rounding mode is RNE or dynamic: while frm is RNE
// these take the host-FPU fast path without decoding the mode.
inline constexpr int32_t kRneOrDyn = 1 << 16;

inline unsigned entry_rm(const Entry& e) { return static_cast<uint32_t>(e.imm) & 0xff; }
inline unsigned entry_rs3(const Entry& e) { return (static_cast<uint32_t>(e.imm) >> 8) & 0xff; }

class DecodeCache {
 public:
  // One entry per word plus a sentinel that faults when execution runs off
  // the end of RAM. calloc keeps untouched pages unallocated.
  explicit DecodeCache(uint32_t ram_size) : size_(ram_size) { allocate(2); }
  ~DecodeCache() { std::free(entries_); }
  DecodeCache(const DecodeCache&) = delete;
  DecodeCache& operator=(const DecodeCache&) = delete;

  Entry* entries() { return entries_; }
  uint32_t count() const { return count_; }
  // log2 of the code bytes per entry: 2, or 1 with the C extension.
  unsigned shift() const { return shift_; }
  bool compressed() const { return shift_ == 1; }
  // The board's instruction set: words outside it decode to OUTSIDE_ISA.
  // With `self_jump_halts`, a jump or branch to itself decodes to SELF_JUMP
  // (the board's "loop" halt).
  // With C, entries become per halfword (everything decoded is dropped).
  void configure(const IsaSpec& isa, bool self_jump_halts) {
    if ((isa.c ? 1u : 2u) != shift_) {
      std::free(entries_);
      allocate(isa.c ? 1 : 2);
      ++epoch_;
    }
    isa_ = isa;
    check_isa_ = true;
    self_jump_halts_ = self_jump_halts;
  }
  const IsaSpec& isa() const { return isa_; }
  // Changes whenever decoded entries are dropped or replaced (not when an
  // undecoded one is filled): code translated from entries is stale then.
  uint64_t epoch() const { return epoch_; }
  bool self_jump_halts() const { return self_jump_halts_; }
  // Load and store immediates are stored minus `ram_base` (interpreter.cpp).
  void set_ram_base(uint32_t ram_base) { ram_base_ = ram_base; }
  // Fills entry `index` from the instruction at that position of `code`
  // (code memory, of the size given to the constructor).
  void fill(uint32_t index, const uint8_t* code);
  // Debugger support: a breakpoint replaces the entry (the instruction in RAM
  // stays as it is); invalidating makes the word decode again on its next run.
  void set_breakpoint(uint32_t index) {
    ++epoch_;
    entries_[index] = Entry{static_cast<uint8_t>(Op::BREAKPOINT), 0, 0, 0, 0};
    unfuse_before(index);
  }
  void invalidate(uint32_t index) {
    ++epoch_;
    entries_[index] = Entry{};
    unfuse_before(index);
  }
  // Invalidates every entry whose instruction may cover [offset, offset + len)
  // of code memory (with C: a 32-bit instruction starting 2 bytes before, and
  // the second half of one starting at the end).
  void invalidate_bytes(uint32_t offset, uint32_t len) {
    const uint32_t unit = 1u << shift_;
    uint64_t lo = offset & ~(unit - 1), hi = uint64_t{offset} + len;
    if (compressed()) {
      lo = lo >= 2 ? lo - 2 : 0;
      hi += 2;
    }
    for (uint64_t a = lo; a < hi && (a >> shift_) < count_; a += unit) invalidate(static_cast<uint32_t>(a >> shift_));
  }
  // fence.i: every entry decodes again on its next run; debugger breakpoints
  // stay. Only the span filled since the last call is visited, so untouched
  // pages stay unallocated.
  void invalidate_all() {
    ++epoch_;
    for (uint32_t i = filled_lo_; i <= filled_hi_ && i < count_; ++i)
      if (entries_[i].op != static_cast<uint8_t>(Op::BREAKPOINT)) entries_[i] = Entry{};
    filled_lo_ = UINT32_MAX;
    filled_hi_ = 0;
  }

 private:
  // Pairs (fused_op): entry i fuses with i+1 once both are decoded; a
  // changed entry i+1 undoes it.
  void fuse(uint32_t index);
  void unfuse_before(uint32_t index) {
    if (index > 0) entries_[index - 1].op = static_cast<uint8_t>(base_op(static_cast<Op>(entries_[index - 1].op)));
  }

  void allocate(unsigned shift) {
    shift_ = shift;
    count_ = size_ >> shift;
    entries_ = static_cast<Entry*>(std::calloc(count_ + 1, sizeof(Entry)));
    if (!entries_) throw std::bad_alloc();
    entries_[count_].op = static_cast<uint8_t>(Op::FETCH_FAULT);
    filled_lo_ = UINT32_MAX;
    filled_hi_ = 0;
  }

  Entry* entries_ = nullptr;
  uint32_t size_;
  uint32_t count_ = 0;
  unsigned shift_ = 2;
  IsaSpec isa_;
  bool check_isa_ = false;  // without a board: today's rv32imf, nothing filtered
  bool self_jump_halts_ = false;
  uint32_t ram_base_ = 0;
  uint32_t filled_lo_ = UINT32_MAX, filled_hi_ = 0;  // span of entries filled since the last invalidate_all
  uint64_t epoch_ = 0;
};

}  // namespace fwsim
