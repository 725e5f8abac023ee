#include "decode_cache.hpp"

#include <cstring>

#include "compressed.hpp"
#include "hart_state.hpp"

namespace fwsim {

void DecodeCache::fill(uint32_t index, const uint8_t* code) {
  if (index < filled_lo_) filled_lo_ = index;
  if (index > filled_hi_) filled_hi_ = index;
  const uint32_t offset = index << shift_;
  uint32_t word = 0;
  if (compressed()) {
    uint16_t half;
    std::memcpy(&half, code + offset, 2);
    word = half;
    if (!is_compressed(word)) {
      // A 32-bit instruction at a halfword: its second half must be code too.
      if (offset + 4 > size_) {
        entries_[index] = Entry{static_cast<uint8_t>(Op::FETCH_FAULT), 0, 0, 0, 0};
        return;
      }
      std::memcpy(&word, code + offset, 4);
    }
  } else {
    std::memcpy(&word, code + offset, 4);
  }
  const DecodedInsn d = compressed() ? decode_any(word) : decode(word);
  Entry e{static_cast<uint8_t>(d.op), d.rd, d.rs1, d.rs2, d.imm};
  // An instruction the board lacks (or a compressed one without C) traps with a
  // message naming the extension (the interpreter decodes it again then).
  if (check_isa_ && (d.op != Op::ILLEGAL || (word & 3) != 3) && missing_extension(isa_, word, d)) {
    entries_[index] = Entry{static_cast<uint8_t>(Op::OUTSIDE_ISA), 0, 0, 0, 0};
    return;
  }
  const Format fmt = op_info(d.op).format;
  // Integer destinations of x0 go to the sink register.
  switch (fmt) {
    case Format::R: case Format::I: case Format::Shift: case Format::U:
    case Format::J: case Format::Jalr: case Format::Csr: case Format::CsrI: case Format::FCmp:
    case Format::FMvXF:
      if (e.rd == 0) e.rd = kSinkReg;
      break;
    case Format::FCvtXF:
      if (e.rd == 0) e.rd = kSinkReg;
      e.imm = d.rm;
      break;
    case Format::FR: case Format::FUnary: case Format::FCvtFX:
      e.imm = d.rm | (d.rm == 0 || d.rm == 7 ? kRneOrDyn : 0);
      break;
    case Format::FR4:
      e.imm = d.rm | (d.rs3 << 8) | (d.rm == 0 || d.rm == 7 ? kRneOrDyn : 0);
      break;
    case Format::Load: case Format::FLoad:
      if (e.rd == 0 && fmt == Format::Load) e.rd = kSinkReg;
      e.imm = static_cast<int32_t>(static_cast<uint32_t>(d.imm) - ram_base_);
      break;
    case Format::Store: case Format::FStore:
      e.imm = static_cast<int32_t>(static_cast<uint32_t>(d.imm) - ram_base_);
      break;
    default:
      break;
  }
  switch (fmt) {
    case Format::J: case Format::Jalr:
      e.rs2 = d.length;
      break;
    default:
      break;
  }
  if (fmt == Format::Branch || fmt == Format::J) {
    // Keep direct targets as entry offsets; targets off the entry grid,
    // outside RAM or inside a 32-bit instruction are checked when the jump
    // is taken (slow path).
    const int32_t unit = 1 << shift_;
    const int64_t target = int64_t{index} + d.imm / unit;
    if ((d.imm & (unit - 1)) || target < 0 || target >= count_ ||
        entries_[target].op == static_cast<uint8_t>(Op::SKIP))
      e.op = static_cast<uint8_t>(Op::SLOW_CTI);
    e.imm = d.imm / unit;
    if (e.op == static_cast<uint8_t>(Op::SLOW_CTI)) e.imm = d.imm;
  }
  if (self_jump_halts_ && (fmt == Format::Branch || fmt == Format::J) && d.imm == 0)
    e.op = static_cast<uint8_t>(Op::SELF_JUMP);
  entries_[index] = e;
  if (index > 0) fuse(index - 1);
  if (compressed() && d.length == 4) {
    // The second half: stepped over, never fused with.
    if (index + 1 < count_) entries_[index + 1] = Entry{static_cast<uint8_t>(Op::SKIP), 0, 0, 0, 0};
    if (index + 1 > filled_hi_) filled_hi_ = index + 1;
    return;
  }
  fuse(index);
}

void DecodeCache::fuse(uint32_t index) {
  if (index + 1 >= count_) return;
  Entry& first = entries_[index];
  const Op f = fused_op(base_op(static_cast<Op>(first.op)), base_op(static_cast<Op>(entries_[index + 1].op)));
  if (f != Op::UNDECODED) first.op = static_cast<uint8_t>(f);
}

}  // namespace fwsim
