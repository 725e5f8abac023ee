#include "block_jit.hpp"

#include <cstdlib>
#include <cstring>
#include <new>
#include <vector>

#include "cycle_model.hpp"
#include "fpu.hpp"
#include "hart_state.hpp"
#include "isa_table.hpp"
#include "profiler.hpp"

#if defined(__x86_64__) && defined(__unix__)
#include <sys/mman.h>
#define FWSIM_JIT_X86_64 1
#endif

namespace fwsim {

#ifdef FWSIM_JIT_X86_64
namespace {

static_assert(offsetof(BlockJit::State, x) == 0 && offsetof(BlockJit::State, ram) == 8 &&
              offsetof(BlockJit::State, table) == 16 && offsetof(BlockJit::State, count) == 24 &&
              offsetof(BlockJit::State, limit) == 32 && offsetof(BlockJit::State, exit) == 40 &&
              offsetof(BlockJit::State, run_start) == 44 && offsetof(BlockJit::State, cycles) == 48);
static_assert(sizeof(CostSlot) == 8 && offsetof(CostSlot, stall) == 4);
static_assert(offsetof(HartState, f) == offsetof(HartState, x) + 33 * 4);

constexpr size_t kCodeBytes = size_t{16} << 20;
constexpr size_t kBlockReserve = 32 << 10;  // more than the largest block can take
constexpr unsigned kMaxBlockInsns = 64;

// Host registers. In generated code: r12 = guest x[] (f[] follows), r15 =
// RAM, rbp = the per-entry table, r13 = instructions retired, r14 = limit,
// rbx = State; rax, rcx, rdx and xmm0 are scratch. Timed blocks also keep
// the cycle count in r8 and BlockCosts' enters, leaves and slots in r9, r10
// and r11 (caller-saved: reloaded after a profiler call).
enum Reg : int {
  RAX = 0, RCX = 1, RDX = 2, RBX = 3, RSP = 4, RBP = 5, RSI = 6, RDI = 7,
  R8 = 8, R9 = 9, R10 = 10, R11 = 11, R12 = 12, R13 = 13, R14 = 14, R15 = 15
};
constexpr int32_t kStateRunStart = 44, kStateCycles = 48;

int32_t xoff(unsigned r) { return static_cast<int32_t>(4 * r); }
int32_t foff(unsigned r) { return static_cast<int32_t>(4 * (33 + r)); }

// A minimal x86-64 encoder writing into the code buffer.
class Emitter {
 public:
  explicit Emitter(uint8_t* p) : p_(p) {}
  uint8_t* here() const { return p_; }
  void b(unsigned v) { *p_++ = static_cast<uint8_t>(v); }
  void d(uint32_t v) {
    std::memcpy(p_, &v, 4);
    p_ += 4;
  }
  void rex(bool w, int reg, int index, int base, bool force = false) {
    const unsigned r = 0x40u | (w ? 8u : 0u) | ((reg >> 3) & 1u) << 2 | ((index >> 3) & 1u) << 1 | ((base >> 3) & 1u);
    if (r != 0x40u || force) b(r);
  }
  // ModRM (+SIB, displacement) for [base + disp].
  void mem(int reg, int base, int32_t disp) {
    const int mod = (disp == 0 && (base & 7) != 5) ? 0 : (disp >= -128 && disp <= 127) ? 1 : 2;
    b(static_cast<unsigned>(mod << 6 | (reg & 7) << 3 | (base & 7)));
    if ((base & 7) == 4) b(0x24);
    if (mod == 1) b(static_cast<unsigned>(disp) & 0xff);
    if (mod == 2) d(static_cast<uint32_t>(disp));
  }
  // [base + index * 2^scale + disp]
  void memidx(int reg, int base, int index, int scale, int32_t disp) {
    const int mod = (disp == 0 && (base & 7) != 5) ? 0 : (disp >= -128 && disp <= 127) ? 1 : 2;
    b(static_cast<unsigned>(mod << 6 | (reg & 7) << 3 | 4));
    b(static_cast<unsigned>(scale << 6 | (index & 7) << 3 | (base & 7)));
    if (mod == 1) b(static_cast<unsigned>(disp) & 0xff);
    if (mod == 2) d(static_cast<uint32_t>(disp));
  }
  // prefix? REX opcode modrm with a [base + disp] operand.
  void op_mem(int prefix, bool w, std::initializer_list<uint8_t> opcode, int reg, int base, int32_t disp) {
    if (prefix) b(static_cast<unsigned>(prefix));
    rex(w, reg, 0, base);
    for (uint8_t o : opcode) b(o);
    mem(reg, base, disp);
  }
  void op_rr(int prefix, bool w, std::initializer_list<uint8_t> opcode, int reg, int rm) {
    if (prefix) b(static_cast<unsigned>(prefix));
    rex(w, reg, 0, rm);
    for (uint8_t o : opcode) b(o);
    b(static_cast<unsigned>(0xc0 | (reg & 7) << 3 | (rm & 7)));
  }
  // Guest register file accesses (r12-relative).
  void load(int reg, int32_t off) { op_mem(0, false, {0x8b}, reg, R12, off); }
  void store(int32_t off, int reg) { op_mem(0, false, {0x89}, reg, R12, off); }
  void store_imm(int32_t off, uint32_t imm) {
    op_mem(0, false, {0xc7}, 0, R12, off);
    d(imm);
  }
  // op reg32, [r12 + off] with a "reg, r/m" opcode.
  void alu_mem(uint8_t opcode, int reg, int32_t off) { op_mem(0, false, {opcode}, reg, R12, off); }
  // 81 /ext reg32, imm32
  void alu_imm(int ext, int reg, uint32_t imm) {
    op_rr(0, false, {0x81}, ext, reg);
    d(imm);
  }
  void shift_imm(int ext, int reg, unsigned n) {
    op_rr(0, false, {0xc1}, ext, reg);
    b(n);
  }
  void xor_self(int reg) { op_rr(0, false, {0x31}, reg, reg); }
  void setcc(uint8_t cc, int reg) { op_rr(0, false, {0x0f, static_cast<uint8_t>(0x90 | cc)}, 0, reg); }
  // Forward jcc rel32 / jmp rel32; returns the displacement's position.
  uint8_t* jcc32(uint8_t cc) {
    b(0x0f);
    b(0x80u | cc);
    uint8_t* at = p_;
    d(0);
    return at;
  }
  void mov_imm64(int reg, uint64_t v) {
    rex(true, 0, 0, reg);
    b(0xb8u + (reg & 7));
    std::memcpy(p_, &v, 8);
    p_ += 8;
  }
  void jmp_to(const uint8_t* target) {
    b(0xe9);
    d(static_cast<uint32_t>(target - (p_ + 4)));
  }
  static void patch(uint8_t* at, const uint8_t* target) {
    const uint32_t rel = static_cast<uint32_t>(target - (at + 4));
    std::memcpy(at, &rel, 4);
  }

 private:
  uint8_t* p_;
};

// x86 condition codes.
enum Cc : uint8_t { O = 0, B = 2, AE = 3, E = 4, NE = 5, BE = 6, A = 7, P = 0xa, NP = 0xb, L = 0xc, GE = 0xd, LE = 0xe, G = 0xf };

struct SideExit {
  uint8_t* jump;    // rel32 to patch
  uint32_t index;   // entry to resume at
  uint32_t retired; // instructions of the block before it
  uint64_t cycles;  // their cycles (timed blocks)
};

// r9, r10, r11 = BlockCosts' enters, leaves, slots.
void timing_regs(Emitter& a, const BlockJit::Timing& t) {
  a.mov_imm64(R9, reinterpret_cast<uint64_t>(t.enters));
  a.mov_imm64(R10, reinterpret_cast<uint64_t>(t.leaves));
  a.mov_imm64(R11, reinterpret_cast<uint64_t>(t.slots));
}

// The profiler's hooks, called from timed blocks at a call or return (after
// the instruction's own cost, before the jump's target is entered). They
// return the cycle count so the caller gets it back in rax.
uint64_t profile_call(BlockJit::State* st, uint32_t target, uint32_t link, uint64_t count, uint64_t cycles) noexcept {
  st->profiler->call(target, link, Cost{st->ir_base + count, cycles});
  return cycles;
}
uint64_t profile_ret(BlockJit::State* st, uint32_t target, uint32_t, uint64_t count, uint64_t cycles) noexcept {
  st->profiler->ret(target, Cost{st->ir_base + count, cycles});
  return cycles;
}
// A conditional branch's cycles and counts from a dynamic predictor.
uint64_t predict_branch(CycleModel* model, uint32_t pc, uint32_t taken, uint32_t backward, uint64_t cycles) noexcept {
  model->branch(pc, taken != 0, backward != 0, cycles);
  return cycles;
}

}  // namespace

BlockJit::BlockJit(uint32_t entry_count, uint32_t code_base, uint32_t ram_size, const Timing* timing, unsigned shift)
    : count_(entry_count), code_base_(code_base), ram_size_(ram_size), shift_(shift) {
  if (timing) timing_ = *timing;
  // Table offsets are 32-bit displacements (entry * 8).
  if (entry_count >= (1u << 28)) return;
  void* mem = mmap(nullptr, kCodeBytes, PROT_READ | PROT_WRITE | PROT_EXEC, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (mem == MAP_FAILED) return;  // no blocks: the interpreter runs everything
  table_ = static_cast<uintptr_t*>(std::calloc(size_t{entry_count} + 1, sizeof(uintptr_t)));
  if (!table_) {
    munmap(mem, kCodeBytes);
    throw std::bad_alloc();
  }
  code_ = static_cast<uint8_t*>(mem);
  code_size_ = kCodeBytes;
  Emitter a(code_);
  // Entry: uint32_t (State* rdi, code rsi). Saves the callee-saved
  // registers it uses, loads the pinned ones and jumps to the block.
  uint8_t* const start = a.here();
  a.b(0x53);  // push rbx
  a.b(0x55);  // push rbp
  for (int r : {R12, R13, R14, R15}) {
    a.b(0x41);
    a.b(0x50u + (r & 7));
  }
  a.b(0x48), a.b(0x83), a.b(0xec), a.b(0x08);  // sub rsp, 8 (keeps the stack 16-aligned)
  a.op_rr(0, true, {0x89}, RDI, RBX);           // mov rbx, rdi
  a.op_mem(0, true, {0x8b}, R12, RBX, 0);
  a.op_mem(0, true, {0x8b}, R15, RBX, 8);
  a.op_mem(0, true, {0x8b}, RBP, RBX, 16);
  a.op_mem(0, true, {0x8b}, R13, RBX, 24);
  a.op_mem(0, true, {0x8b}, R14, RBX, 32);
  if (timed()) {
    a.op_mem(0, true, {0x8b}, R8, RBX, kStateCycles);
    timing_regs(a, timing_);
  }
  a.b(0xff), a.b(0xe6);  // jmp rsi
  // Exit: eax = entry index, State::exit already set.
  uint8_t* const common = a.here();
  a.op_mem(0, true, {0x89}, R13, RBX, 24);
  if (timed()) a.op_mem(0, true, {0x89}, R8, RBX, kStateCycles);
  a.b(0x48), a.b(0x83), a.b(0xc4), a.b(0x08);  // add rsp, 8
  for (int r : {R15, R14, R13, R12}) {
    a.b(0x41);
    a.b(0x58u + (r & 7));
  }
  a.b(0x5d);  // pop rbp
  a.b(0x5b);  // pop rbx
  a.b(0xc3);
  for (uint32_t kind = 0; kind < 3; ++kind) {
    exit_offsets_[kind] = static_cast<size_t>(a.here() - code_);
    a.op_mem(0, false, {0xc7}, 0, RBX, 40);
    a.d(kind);
    a.jmp_to(common);
  }
  enter_ = reinterpret_cast<EnterFn>(start);
  prologue_end_ = used_ = static_cast<size_t>(a.here() - code_);
}

BlockJit::~BlockJit() {
  if (code_) munmap(code_, code_size_);
  std::free(table_);
}

void BlockJit::flush() {
  if (!code_) return;
  for (uint32_t i = touched_lo_; i <= touched_hi_ && i <= count_; ++i)
    if (table_[i] >= kNoBlock) table_[i] = 0;
  touched_lo_ = UINT32_MAX;
  touched_hi_ = 0;
  used_ = prologue_end_;
}

uintptr_t BlockJit::compile(const Entry* entries, uint32_t index) {
  if (!code_) return kNoBlock;
  if (used_ + kBlockReserve > code_size_) flush();
  if (index < touched_lo_) touched_lo_ = index;
  if (index > touched_hi_) touched_hi_ = index;
  uint8_t* const block = code_ + used_;
  const uint8_t* const exit_target = code_ + exit_offsets_[static_cast<int>(Exit::Target)];
  const uint8_t* const exit_here = code_ + exit_offsets_[static_cast<int>(Exit::Here)];
  const uint8_t* const exit_limit = code_ + exit_offsets_[static_cast<int>(Exit::Limit)];
  Emitter a(block);
  const bool timed = this->timed();
  constexpr uint32_t kFallThrough = UINT32_MAX;
  std::vector<SideExit> sides;
  int64_t cyc = 0;  // timed: cycles of the block's instructions before the current one
  auto side = [&](uint8_t cc, uint32_t at, uint32_t retired) {
    sides.push_back({a.jcc32(cc), at, retired, static_cast<uint64_t>(cyc)});
  };
  auto add_retired = [&](uint32_t n) {
    if (n == 0) return;
    a.rex(true, 0, 0, R13);
    a.b(0x81);
    a.b(0xc0u | (R13 & 7));  // add r13, imm32
    a.d(n);
  };
  // `n` instructions and `c` cycles of the block done.
  auto settle = [&](uint32_t n, int64_t c) {
    add_retired(n);
    if (timed && c) {
      a.op_rr(0, true, {0x81}, 0, R8);  // add r8, imm32
      a.d(static_cast<uint32_t>(static_cast<int32_t>(c)));
    }
  };
  // A taken jump from entry `from` to `to` (in ecx when dynamic) as the
  // interpreter's ENTER counts it: the run ending at `from` leaves, the one
  // at `to` enters, and `to`'s load-use stall is not charged. The stall is
  // read from its slot, which changes when the entry before `to` is decoded.
  auto enter_run = [&](uint32_t from, uint32_t to, bool dynamic) {
    a.op_mem(0, true, {0xff}, 0, R10, static_cast<int32_t>(from * 8));  // inc qword leaves[from]
    if (dynamic) {
      a.rex(true, 0, RCX, R9);
      a.b(0xff);
      a.memidx(0, R9, RCX, 3, 0);  // inc qword enters[rcx]
      a.rex(false, RAX, RCX, R11);
      a.b(0x0f), a.b(0xb7);
      a.memidx(RAX, R11, RCX, 3, 4);  // movzx eax, word slots[rcx].stall
    } else {
      a.op_mem(0, true, {0xff}, 0, R9, static_cast<int32_t>(to * 8));
      a.op_mem(0, false, {0x0f, 0xb7}, RAX, R11, static_cast<int32_t>(to * 8 + 4));
      a.op_mem(0, false, {0xc7}, 0, RBX, kStateRunStart);
      a.d(to);
    }
    a.op_rr(0, true, {0x29}, RAX, R8);  // sub r8, rax
  };
  // Calls a helper (its address) taking the cycle count as its fifth
  // argument (r8) and returning it; the other arguments are set.
  auto call_helper = [&](uint64_t fn) {
    a.mov_imm64(RAX, fn);
    a.b(0xff), a.b(0xd0);                // call rax
    a.op_rr(0, true, {0x89}, RAX, R8);  // mov r8, rax
    timing_regs(a, timing_);
  };
  // Calls the profiler's call or return hook; esi = the target's address.
  auto profile_hook = [&](bool call, uint32_t link) {
    a.b(0xba), a.d(link);                  // mov edx, link
    a.op_rr(0, true, {0x89}, R13, RCX);   // mov rcx, r13
    a.op_rr(0, true, {0x89}, RBX, RDI);   // mov rdi, rbx
    call_helper(call ? reinterpret_cast<uint64_t>(&profile_call) : reinterpret_cast<uint64_t>(&profile_ret));
  };
  // Continue at entry `to` (a constant) after `n` instructions and `c`
  // cycles of the block; `from` (unless kFallThrough) = a taken jump from
  // that entry, which checks the limit first.
  auto chain = [&](uint32_t to, uint32_t n, int64_t c, uint32_t from) {
    settle(n, c);
    if (from != kFallThrough) {
      if (timed) enter_run(from, to, false);
      a.op_rr(0, true, {0x39}, R14, R13);  // cmp r13, r14
      a.b(0x76), a.b(10);                  // jbe over the limit exit
      a.b(0xb8), a.d(to);                  // mov eax, to
      a.jmp_to(exit_limit);
    }
    a.op_mem(0, true, {0x8b}, RAX, RBP, static_cast<int32_t>(to * 8));  // mov rax, [rbp + to*8]
    a.b(0x48), a.b(0x3d), a.d(static_cast<uint32_t>(kNoBlock));          // cmp rax, kNoBlock
    a.b(0x76), a.b(2);                                                   // jbe +2
    a.b(0xff), a.b(0xe0);                                                // jmp rax
    a.b(0xb8), a.d(to);
    a.jmp_to(exit_target);
  };
  const uint32_t ram_units[3] = {ram_size_, ram_size_ >> 1, ram_size_ >> 2};
  // ecx = RAM offset of x[rs1] + imm; leaves unless in RAM and aligned.
  auto address = [&](const Entry& e, unsigned log_size, uint32_t at, uint32_t retired) {
    a.load(RCX, xoff(e.rs1));
    if (e.imm) a.alu_imm(0, RCX, static_cast<uint32_t>(e.imm));
    if (log_size == 0) {
      a.alu_imm(7, RCX, ram_units[0]);  // cmp ecx, size
    } else {
      a.op_rr(0, false, {0x89}, RCX, RAX);  // mov eax, ecx
      a.shift_imm(1, RAX, log_size);        // ror eax, log_size
      a.alu_imm(7, RAX, ram_units[log_size]);
    }
    side(AE, at, retired);
  };
  auto fp_result = [&](unsigned rd) {
    a.op_rr(0x66, false, {0x0f, 0x7e}, 0, RAX);  // movd eax, xmm0
    a.b(0xb9), a.d(fpu::kCanonicalNaN);          // mov ecx, canonical NaN
    a.op_rr(0, false, {0x0f, 0x2e}, 0, 0);       // ucomiss xmm0, xmm0
    a.op_rr(0, false, {0x0f, 0x4a}, RAX, RCX);   // cmovp eax, ecx
    a.store(foff(rd), RAX);
  };

  uint32_t n = 0;  // instructions translated
  uint32_t next = index;  // the entry after the current instruction
  for (uint32_t i = index;; i = next, ++n) {
    if (n == kMaxBlockInsns || i >= count_) {
      if (n == 0) return kNoBlock;
      chain(i, n, cyc, kFallThrough);
      break;
    }
    const Entry& e = entries[i];
    const Op op = base_op(static_cast<Op>(e.op));
    // With C, a 32-bit instruction's second half is a SKIP entry.
    next = i + (shift_ == 1 && entries[i + 1].op == static_cast<uint8_t>(Op::SKIP) ? 2 : 1);
    const uint32_t pc = code_base_ + (i << shift_);
    const bool rne = (e.imm & kRneOrDyn) != 0;
    const int64_t cost = timed ? int64_t{timing_.slots[i].cost} : 0;  // with the stall after its predecessor
    bool ends = false;  // a control transfer closed the block
    bool supported = true;
    switch (op) {
      case Op::LUI: a.store_imm(xoff(e.rd), static_cast<uint32_t>(e.imm)); break;
      case Op::AUIPC: a.store_imm(xoff(e.rd), pc + static_cast<uint32_t>(e.imm)); break;
      case Op::ADDI: case Op::XORI: case Op::ORI: case Op::ANDI: {
        const int ext = op == Op::ADDI ? 0 : op == Op::XORI ? 6 : op == Op::ORI ? 1 : 4;
        a.load(RAX, xoff(e.rs1));
        a.alu_imm(ext, RAX, static_cast<uint32_t>(e.imm));
        a.store(xoff(e.rd), RAX);
        break;
      }
      case Op::SLTI: case Op::SLTIU:
        a.load(RAX, xoff(e.rs1));
        a.xor_self(RCX);
        a.alu_imm(7, RAX, static_cast<uint32_t>(e.imm));
        a.setcc(op == Op::SLTI ? L : B, RCX);
        a.store(xoff(e.rd), RCX);
        break;
      case Op::SLLI: case Op::SRLI: case Op::SRAI:
        a.load(RAX, xoff(e.rs1));
        a.shift_imm(op == Op::SLLI ? 4 : op == Op::SRLI ? 5 : 7, RAX, static_cast<unsigned>(e.imm) & 31);
        a.store(xoff(e.rd), RAX);
        break;
      case Op::ADD: case Op::SUB: case Op::AND: case Op::OR: case Op::XOR: {
        const uint8_t opc = op == Op::ADD ? 0x03 : op == Op::SUB ? 0x2b : op == Op::AND ? 0x23 : op == Op::OR ? 0x0b : 0x33;
        a.load(RAX, xoff(e.rs1));
        a.alu_mem(opc, RAX, xoff(e.rs2));
        a.store(xoff(e.rd), RAX);
        break;
      }
      case Op::SLT: case Op::SLTU:
        a.load(RAX, xoff(e.rs1));
        a.xor_self(RCX);
        a.alu_mem(0x3b, RAX, xoff(e.rs2));
        a.setcc(op == Op::SLT ? L : B, RCX);
        a.store(xoff(e.rd), RCX);
        break;
      case Op::SLL: case Op::SRL: case Op::SRA:
        a.load(RCX, xoff(e.rs2));
        a.load(RAX, xoff(e.rs1));
        a.op_rr(0, false, {0xd3}, op == Op::SLL ? 4 : op == Op::SRL ? 5 : 7, RAX);  // shift eax, cl
        a.store(xoff(e.rd), RAX);
        break;
      case Op::MUL:
        a.load(RAX, xoff(e.rs1));
        a.op_mem(0, false, {0x0f, 0xaf}, RAX, R12, xoff(e.rs2));  // imul eax, [rs2]
        a.store(xoff(e.rd), RAX);
        break;
      case Op::MULH: case Op::MULHSU: case Op::MULHU:
        // 64-bit product of the sign- or zero-extended operands; its high half.
        if (op == Op::MULHU) a.load(RAX, xoff(e.rs1));
        else a.op_mem(0, true, {0x63}, RAX, R12, xoff(e.rs1));  // movsxd rax, [rs1]
        if (op == Op::MULH) a.op_mem(0, true, {0x63}, RCX, R12, xoff(e.rs2));
        else a.load(RCX, xoff(e.rs2));
        a.op_rr(0, true, {0x0f, 0xaf}, RAX, RCX);  // imul rax, rcx
        a.op_rr(0, true, {0xc1}, 5, RAX), a.b(32);   // shr rax, 32
        a.store(xoff(e.rd), RAX);
        break;
      case Op::LB: case Op::LH: case Op::LW: case Op::LBU: case Op::LHU: case Op::FLW: {
        const unsigned lg = (op == Op::LB || op == Op::LBU) ? 0 : (op == Op::LH || op == Op::LHU) ? 1 : 2;
        address(e, lg, i, n);
        // mov, or movsx / movzx for the narrow loads.
        const uint8_t second = op == Op::LB ? 0xbe : op == Op::LBU ? 0xb6 : op == Op::LH ? 0xbf : 0xb7;
        a.rex(false, RDX, RCX, R15);
        if (lg == 2) {
          a.b(0x8b);
        } else {
          a.b(0x0f);
          a.b(second);
        }
        a.memidx(RDX, R15, RCX, 0, 0);  // load edx, [r15 + rcx]
        a.store(op == Op::FLW ? foff(e.rd) : xoff(e.rd), RDX);
        break;
      }
      case Op::SB: case Op::SH: case Op::SW: case Op::FSW: {
        const unsigned lg = op == Op::SB ? 0 : op == Op::SH ? 1 : 2;
        address(e, lg, i, n);
        a.load(RDX, op == Op::FSW ? foff(e.rs2) : xoff(e.rs2));
        if (lg == 1) a.b(0x66);
        a.rex(false, RDX, RCX, R15);
        a.b(lg == 0 ? 0x88 : 0x89);
        a.memidx(RDX, R15, RCX, 0, 0);  // store [r15 + rcx], dl/dx/edx
        break;
      }
      case Op::BEQ: case Op::BNE: case Op::BLT: case Op::BGE: case Op::BLTU: case Op::BGEU: {
        // Jump over the taken path when the condition fails.
        const uint8_t not_taken = op == Op::BEQ ? NE : op == Op::BNE ? E : op == Op::BLT ? GE
                                : op == Op::BGE ? L : op == Op::BLTU ? AE : B;
        if (timed && timing_.predictor) {
          // The predictor's hook with the outcome, then the compare again.
          a.xor_self(RDX);
          a.load(RAX, xoff(e.rs1));
          a.alu_mem(0x3b, RAX, xoff(e.rs2));
          a.setcc(not_taken ^ 1, RDX);  // edx = taken
          a.mov_imm64(RDI, reinterpret_cast<uint64_t>(timing_.predictor));
          a.b(0xbe), a.d(pc);                     // mov esi, pc
          a.b(0xb9), a.d(e.imm < 0 ? 1u : 0u);    // mov ecx, backward
          call_helper(reinterpret_cast<uint64_t>(&predict_branch));
        }
        a.load(RAX, xoff(e.rs1));
        a.alu_mem(0x3b, RAX, xoff(e.rs2));
        uint8_t* const skip = a.jcc32(not_taken);
        const int64_t taken = timed ? int64_t{timing_.slots[i].taken} : 0;
        chain(i + static_cast<uint32_t>(e.imm), n + 1, cyc + cost + taken, i);
        Emitter::patch(skip, a.here());
        chain(next, n + 1, cyc + cost, kFallThrough);
        ends = true;
        break;
      }
      case Op::JAL: {
        a.store_imm(xoff(e.rd), pc + e.rs2);
        const uint32_t to = i + static_cast<uint32_t>(e.imm);
        if (timed && timing_.profile && e.rd == 1) {
          settle(n + 1, cyc + cost);
          a.b(0xbe), a.d(code_base_ + (to << shift_));  // mov esi, target
          profile_hook(true, pc + e.rs2);
          chain(to, 0, 0, i);
        } else {
          chain(to, n + 1, cyc + cost, i);
        }
        ends = true;
        break;
      }
      case Op::JALR: {
        a.load(RAX, xoff(e.rs1));
        a.alu_imm(0, RAX, static_cast<uint32_t>(e.imm));
        a.alu_imm(4, RAX, ~1u);
        a.b(0xa8), a.b(static_cast<uint8_t>((1u << shift_) - 1));  // test al, fetch alignment
        side(NE, i, n);
        a.op_rr(0, false, {0x89}, RAX, RCX);  // mov ecx, eax
        a.alu_imm(5, RCX, code_base_);
        a.alu_imm(7, RCX, count_ << shift_);
        side(AE, i, n);
        a.store_imm(xoff(e.rd), pc + e.rs2);
        a.shift_imm(5, RCX, shift_);  // ecx = target entry
        settle(n + 1, cyc + cost);
        if (timed) {
          a.op_mem(0, false, {0x89}, RCX, RBX, kStateRunStart);  // run_start = ecx
          const bool is_call = e.rd == 1, is_ret = e.rd == kSinkReg && e.rs1 == 1;
          if (timing_.profile && (is_call || is_ret)) {
            a.op_rr(0, false, {0x89}, RCX, RSI);  // mov esi, ecx
            a.shift_imm(4, RSI, shift_);          // shl esi, shift
            a.alu_imm(0, RSI, code_base_);        // esi = target
            profile_hook(is_call, pc + e.rs2);
            a.op_mem(0, false, {0x8b}, RCX, RBX, kStateRunStart);  // ecx = target entry again
          }
          enter_run(i, 0, true);
        }
        a.op_rr(0, true, {0x39}, R14, R13);  // cmp r13, r14
        a.b(0x76), a.b(7);
        a.op_rr(0, false, {0x89}, RCX, RAX);  // mov eax, ecx
        a.jmp_to(exit_limit);
        a.rex(true, RAX, RCX, RBP);
        a.b(0x8b);
        a.memidx(RAX, RBP, RCX, 3, 0);  // mov rax, [rbp + rcx*8]
        a.b(0x48), a.b(0x3d), a.d(static_cast<uint32_t>(kNoBlock));
        a.b(0x76), a.b(2);
        a.b(0xff), a.b(0xe0);
        a.op_rr(0, false, {0x89}, RCX, RAX);
        a.jmp_to(exit_target);
        ends = true;
        break;
      }
      case Op::FENCE: break;
      case Op::FADD_S: case Op::FSUB_S: case Op::FMUL_S: case Op::FDIV_S: case Op::FSQRT_S: {
        if (!rne) {
          supported = false;
          break;
        }
        const uint8_t opc = op == Op::FADD_S ? 0x58 : op == Op::FSUB_S ? 0x5c : op == Op::FMUL_S ? 0x59
                          : op == Op::FDIV_S ? 0x5e : 0x51;
        if (op == Op::FSQRT_S) {
          a.op_mem(0xf3, false, {0x0f, 0x51}, 0, R12, foff(e.rs1));  // sqrtss xmm0, [fs1]
        } else {
          a.op_mem(0xf3, false, {0x0f, 0x10}, 0, R12, foff(e.rs1));  // movss xmm0, [fs1]
          a.op_mem(0xf3, false, {0x0f, opc}, 0, R12, foff(e.rs2));
        }
        fp_result(e.rd);
        break;
      }
      case Op::FCVT_S_W:
        if (!rne) {
          supported = false;
          break;
        }
        a.op_mem(0xf3, false, {0x0f, 0x2a}, 0, R12, xoff(e.rs1));  // cvtsi2ss xmm0, dword [rs1]
        a.op_mem(0xf3, false, {0x0f, 0x11}, 0, R12, foff(e.rd));   // movss [fd], xmm0
        break;
      case Op::FSGNJ_S: case Op::FSGNJN_S: case Op::FSGNJX_S:
        a.load(RAX, foff(e.rs1));
        a.load(RCX, foff(e.rs2));
        if (op == Op::FSGNJN_S) a.op_rr(0, false, {0xf7}, 2, RCX);  // not ecx
        a.alu_imm(4, RCX, 0x80000000u);
        if (op == Op::FSGNJX_S) {
          a.op_rr(0, false, {0x31}, RCX, RAX);  // xor eax, ecx
        } else {
          a.alu_imm(4, RAX, 0x7fffffffu);
          a.op_rr(0, false, {0x09}, RCX, RAX);  // or eax, ecx
        }
        a.store(foff(e.rd), RAX);
        break;
      case Op::FMV_X_W:
        a.load(RAX, foff(e.rs1));
        a.store(xoff(e.rd), RAX);
        break;
      case Op::FMV_W_X:
        a.load(RAX, xoff(e.rs1));
        a.store(foff(e.rd), RAX);
        break;
      case Op::FEQ_S:
        // ucomiss (invalid on signaling NaNs only), equal and ordered.
        a.op_mem(0xf3, false, {0x0f, 0x10}, 0, R12, foff(e.rs1));
        a.xor_self(RCX);
        a.xor_self(RDX);
        a.op_mem(0, false, {0x0f, 0x2e}, 0, R12, foff(e.rs2));
        a.setcc(E, RCX);
        a.setcc(NP, RDX);
        a.op_rr(0, false, {0x21}, RDX, RCX);  // and ecx, edx
        a.store(xoff(e.rd), RCX);
        break;
      case Op::FLT_S: case Op::FLE_S:
        // comiss (invalid on any NaN): b > a or b >= a, false when unordered.
        a.op_mem(0xf3, false, {0x0f, 0x10}, 0, R12, foff(e.rs2));
        a.xor_self(RCX);
        a.op_mem(0, false, {0x0f, 0x2f}, 0, R12, foff(e.rs1));
        a.setcc(op == Op::FLT_S ? A : AE, RCX);
        a.store(xoff(e.rd), RCX);
        break;
      default:
        supported = false;
        break;
    }
    if (!supported) {
      if (n == 0) return kNoBlock;
      // The interpreter runs it (and what follows, up to its next jump).
      settle(n, cyc);
      a.b(0xb8), a.d(i);
      a.jmp_to(exit_here);
      break;
    }
    if (ends) break;
    cyc += cost;
  }
  // Cold side exits: before instruction `index`, `retired` of the block done.
  for (const SideExit& s : sides) {
    Emitter::patch(s.jump, a.here());
    settle(s.retired, static_cast<int64_t>(s.cycles));
    a.b(0xb8), a.d(s.index);
    a.jmp_to(exit_here);
  }
  used_ = static_cast<size_t>(a.here() - code_);
  used_ = (used_ + 15) & ~size_t{15};
  ++blocks_made_;
  return reinterpret_cast<uintptr_t>(block);
}

#else  // no code generator on this host

BlockJit::BlockJit(uint32_t entry_count, uint32_t code_base, uint32_t ram_size, const Timing*, unsigned shift)
    : count_(entry_count), code_base_(code_base), ram_size_(ram_size), shift_(shift) {}
BlockJit::~BlockJit() = default;
void BlockJit::flush() {}
uintptr_t BlockJit::compile(const Entry*, uint32_t) { return kNoBlock; }

#endif

}  // namespace fwsim
