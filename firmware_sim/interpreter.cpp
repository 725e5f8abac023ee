// The hot loop: threaded dispatch (computed goto) over pre-decoded entries.
// Plain variant: no per-instruction work beyond the semantics and one counter
// increment; the instruction limit is checked only on taken control transfers
// (every loop has one). Timed variant: the same handlers plus cycle-model,
// profiler and trace hooks, selected at compile time.
//
// FP fast path: in round-to-nearest-even the host's IEEE single operations
// give bit-identical results, and the host's sticky exception flags (MXCSR)
// are exactly the RISC-V ones (both detect tininess after rounding), so they
// are left to accumulate and merged into fflags when the firmware reads it.
// Only NaN results need fixing (RISC-V returns the canonical NaN). Other
// rounding modes and the fused ops go through the bit-exact soft FPU.
#include <bit>
#include <cstddef>
#include <cstring>

#include "commit_trace.hpp"
#include "compressed.hpp"
#include "decoder.hpp"
#include "disassembler.hpp"
#include "fpu.hpp"
#include "fpu_approx.hpp"
#include "host_fma.hpp"
#include "isa_subset.hpp"
#include "block_costs.hpp"
#include "machine.hpp"

namespace fwsim {

// The interpreter's entry pointer, the register file's base and the cycle
// count are global register variables in this file (GCC, x86-64): in this
// large function GCC keeps locals in stack slots around every slow path, so
// each load and store handler put a store and a reload of them on the
// dependency chain, and the timed loop updated the cycle count through
// memory. The registers are callee-saved, so code in other files preserves
// them; Machine::run saves and restores the caller's values (PinnedRegs),
// on unwinding too.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
register uint32_t* g_x asm("r12");
register uint64_t g_cycles asm("r14");
register Entry* g_ip asm("rbx");
struct PinnedRegs {
  uint32_t* x = g_x;
  uint64_t cycles = g_cycles;
  Entry* ip = g_ip;
  PinnedRegs() = default;
  PinnedRegs(const PinnedRegs&) = delete;
  PinnedRegs& operator=(const PinnedRegs&) = delete;
  ~PinnedRegs() {
    g_x = x;
    g_cycles = cycles;
    g_ip = ip;
  }
};
#define FWSIM_GLOBAL_REGS 1
#endif

namespace {

inline float as_float(uint32_t b) { return std::bit_cast<float>(b); }
// r != r is a quiet compare (ucomiss): it raises nothing for the quiet NaNs
// arithmetic produces.
inline uint32_t host_result(float r) {
  return __builtin_expect(r != r, 0) ? fpu::kCanonicalNaN : std::bit_cast<uint32_t>(r);
}
// Host compares give the RISC-V results and flags: < and <= compile to
// comiss (invalid on any NaN, like flt.s/fle.s), == to ucomiss (invalid on a
// signaling NaN only, like feq.s); unordered operands compare false.
inline uint32_t host_lt(uint32_t a, uint32_t b) { return as_float(a) < as_float(b); }
inline uint32_t host_le(uint32_t a, uint32_t b) { return as_float(a) <= as_float(b); }
inline uint32_t host_eq(uint32_t a, uint32_t b) { return as_float(a) == as_float(b); }

bool branch_condition(Op op, uint32_t a, uint32_t b) {
  switch (op) {
    case Op::BEQ: return a == b;
    case Op::BNE: return a != b;
    case Op::BLT: return static_cast<int32_t>(a) < static_cast<int32_t>(b);
    case Op::BGE: return static_cast<int32_t>(a) >= static_cast<int32_t>(b);
    case Op::BLTU: return a < b;
    case Op::BGEU: return a >= b;
    default: return true;  // jal
  }
}

uint32_t div_s(uint32_t a, uint32_t b) {
  if (b == 0) return ~0u;
  if (a == 0x80000000u && b == ~0u) return a;
  return static_cast<uint32_t>(static_cast<int32_t>(a) / static_cast<int32_t>(b));
}
uint32_t rem_s(uint32_t a, uint32_t b) {
  if (b == 0) return a;
  if (a == 0x80000000u && b == ~0u) return 0;
  return static_cast<uint32_t>(static_cast<int32_t>(a) % static_cast<int32_t>(b));
}

}  // namespace

uint32_t Machine::instruction_at(uint32_t pc) {
  uint32_t word = 0;
  std::memcpy(&word, bus_.code_at(pc), 2);
  if (!code_.compressed() || !is_compressed(word)) {
    if (bus_.in_code(pc, 4)) std::memcpy(&word, bus_.code_at(pc), 4);
  }
  return word;
}

void Machine::trace_instruction(uint32_t pc) {
  const uint32_t word = instruction_at(pc);
  if (spike_trace_) write_spike_commit(trace_, pc, word, hart_);
  else write_commit_trace(trace_, pc, word, hart_);
}

StopInfo Machine::run(uint64_t max_instructions) {
  StopInfo s;
  if (!bus_.in_code(hart_.pc, 1u << code_.shift())) {
    s.cause = StopCause::FetchFault;
    s.pc = s.addr = hart_.pc;
    return s;
  }
  if (hart_.pc & ((1u << code_.shift()) - 1)) {
    s.cause = StopCause::MisalignedFetch;
    s.pc = s.addr = hart_.pc;
    return s;
  }
#ifdef FWSIM_GLOBAL_REGS
  const PinnedRegs saved;
#endif
  fpu::clear_host_flags();
  // Plain; timed with pre-computed costs (both with generated code for hot
  // runs); timed with per-instruction hooks (trace, caches), which the
  // pre-computed costs cannot express.
  if (!model_ && !profiler_ && !trace_ && watches_.empty()) {
    // Generated code covers the IEEE arithmetic only.
    if (jit_enabled_ && !fpu_model_ && !jit_)
      jit_ = std::make_unique<BlockJit>(code_.count(), bus_.code_base(), bus_.ram_size(), nullptr, code_.shift());
    if (jit_enabled_ && !fpu_model_ && jit_->available()) s = run_loop<3>(max_instructions);
    else s = run_loop<0>(max_instructions);
  }
  // Block costs assume one entry per instruction: not with the C extension.
  else if (model_ && !trace_ && watches_.empty() && !model_->per_access_state() && !code_.compressed())
    s = run_loop<1>(max_instructions);
  else s = run_loop<2>(max_instructions);
  hart_.fflags |= fpu::take_host_flags();
  return s;
}

// RAM's base pointer: a local register variable that an empty asm at every
// step keeps in its register (GCC otherwise reloads it from a stack slot in
// every load and store handler).
#ifdef FWSIM_GLOBAL_REGS
#define FWSIM_PINNED(type, name, reg) register type name asm(reg)
#define FWSIM_KEEP(v) __asm__("" : "+r"(v))
#else
#define FWSIM_PINNED(type, name, reg) type name
#define FWSIM_KEEP(v) ((void)0)
#endif

template <int Mode>
StopInfo Machine::run_loop(uint64_t max_instructions) {
  constexpr bool Timed = Mode == 1 || Mode == 2;
  constexpr bool Hooks = Mode == 2;  // per-instruction model calls
  // Fused ops run as their first instruction except in the RNE table of the
  // plain and block-costed loops (kLabelsFused), where one handler runs the
  // pair (each half still steps its own cost).
  static const void* const kLabels[] = {
#define FWSIM_LABEL(name, mn, cls, fmt) &&L_##name,
      FWSIM_OPS(FWSIM_LABEL)
#undef FWSIM_LABEL
#define FWSIM_FUSED_LABEL(name, a, b) &&L_##a,
      FWSIM_FUSED(FWSIM_FUSED_LABEL)
#undef FWSIM_FUSED_LABEL
  };
  static_assert(sizeof kLabels / sizeof kLabels[0] == static_cast<size_t>(Op::Count));
  // While frm is RNE (almost always), FP arithmetic dispatches through this
  // table to handlers that skip the rounding-mode decode.
  static const void* kLabelsRne[sizeof kLabels / sizeof kLabels[0]];
  static const void* kLabelsFused[sizeof kLabels / sizeof kLabels[0]];
  static bool rne_table_ready = false;
  if (!rne_table_ready) {
    std::memcpy(kLabelsRne, kLabels, sizeof kLabels);
    kLabelsRne[static_cast<int>(Op::FADD_S)] = &&R_FADD_S;
    kLabelsRne[static_cast<int>(Op::FSUB_S)] = &&R_FSUB_S;
    kLabelsRne[static_cast<int>(Op::FMUL_S)] = &&R_FMUL_S;
    kLabelsRne[static_cast<int>(Op::FDIV_S)] = &&R_FDIV_S;
    kLabelsRne[static_cast<int>(Op::FSQRT_S)] = &&R_FSQRT_S;
    kLabelsRne[static_cast<int>(Op::FMADD_S)] = &&R_FMADD_S;
    kLabelsRne[static_cast<int>(Op::FMSUB_S)] = &&R_FMSUB_S;
    kLabelsRne[static_cast<int>(Op::FNMSUB_S)] = &&R_FNMSUB_S;
    kLabelsRne[static_cast<int>(Op::FNMADD_S)] = &&R_FNMADD_S;
    kLabelsRne[static_cast<int>(Op::FCVT_S_W)] = &&R_FCVT_S_W;
    kLabelsRne[static_cast<int>(Op::FCVT_S_WU)] = &&R_FCVT_S_WU;
    for (unsigned op = kBaseOpCount; op < static_cast<unsigned>(Op::Count); ++op)
      kLabelsRne[op] = kLabelsRne[static_cast<unsigned>(base_op(static_cast<Op>(op)))];
    std::memcpy(kLabelsFused, kLabelsRne, sizeof kLabels);
#define FWSIM_FUSED_ROUTE(name, a, b) kLabelsFused[static_cast<int>(Op::name)] = &&F_##name;
    FWSIM_FUSED(FWSIM_FUSED_ROUTE)
#undef FWSIM_FUSED_ROUTE
    rne_table_ready = true;
  }
  // With an FPU model, the ops it replaces dispatch to the M_ handlers in
  // both tables; the IEEE tables and handlers stay untouched.
  constexpr size_t kOpCount = sizeof kLabels / sizeof kLabels[0];
  const void* model_labels[kOpCount];
  const void* model_labels_rne[kOpCount];
  const void* const* labels_any = kLabels;
  const void* const* labels_rne = Mode != 2 ? kLabelsFused : kLabelsRne;
  const FpuApprox* const approx = fpu_model_;
  if (approx) {
    std::memcpy(model_labels, kLabels, sizeof kLabels);
    std::memcpy(model_labels_rne, kLabelsRne, sizeof kLabels);
    // A macro, not a lambda: with the label addresses passed through a
    // lambda, GCC -O2 left fdiv.s on the IEEE handler (the tests catch it).
#define ROUTE(op, handler) \
  model_labels[static_cast<int>(op)] = model_labels_rne[static_cast<int>(op)] = (handler)
    if (approx->models_add()) {
      ROUTE(Op::FADD_S, &&M_FADD_S);
      ROUTE(Op::FSUB_S, &&M_FSUB_S);
    }
    if (approx->models_mul()) ROUTE(Op::FMUL_S, &&M_FMUL_S);
    if (approx->models_div()) ROUTE(Op::FDIV_S, &&M_FDIV_S);
    if (approx->models_sqrt()) ROUTE(Op::FSQRT_S, &&M_FSQRT_S);
#undef ROUTE
    for (unsigned op = kBaseOpCount; op < static_cast<unsigned>(Op::Count); ++op) {
      const unsigned b = static_cast<unsigned>(base_op(static_cast<Op>(op)));
      model_labels[op] = model_labels[b];
      model_labels_rne[op] = model_labels_rne[b];
    }
    labels_any = model_labels;
    labels_rne = model_labels_rne;
  }
  // Indexed by "frm is RNE"; kept in memory so the hot loop spends no
  // registers on it (only CSR instructions read it).
  const void* const* const dispatch_tables[2] = {labels_any, labels_rne};
  const void* const* labels = dispatch_tables[hart_.frm == fpu::RNE];
  CycleModel default_model(default_cycle_model());
  CycleModel& model = model_ ? *model_ : default_model;
#ifdef FWSIM_GLOBAL_REGS
  g_cycles = hart_.cycles;  // timed variant only
#define CYC g_cycles
#else
  uint64_t CYC = hart_.cycles;  // timed variant only
#endif
  // Hoisted so the hooks test registers, not members, per instruction.
  const bool tracing = trace_ != nullptr;
  Profiler* const profiler = profiler_;
  const bool halt_on_ecall = bus_.map().halt == HaltKind::Ecall;

  Entry* const base = code_.entries();
  const uint32_t ram_base = bus_.ram_base();
  // Code memory: RAM, or the board's ROM (data accesses to it take the bus).
  const uint32_t code_base = bus_.code_base();
  const uint32_t code_size = bus_.code_size();
  const uint8_t* const code_mem = bus_.code();
  // Code bytes per entry: 4, or 2 with the C extension (decode_cache.hpp).
  const unsigned shift = code_.shift();
  const uint32_t fetch_align = (1u << shift) - 1;
#ifdef FWSIM_GLOBAL_REGS
  g_ip = base + ((hart_.pc - code_base) >> shift);
#define ip g_ip
#else
  Entry* ip = base + ((hart_.pc - code_base) >> shift);
#endif
#ifdef FWSIM_GLOBAL_REGS
  g_x = hart_.x;
#define XR g_x
#else
  uint32_t* const XR = hart_.x;
#endif
  // f[] directly follows x[] in HartState: addressing it from x saves a register.
  static_assert(offsetof(HartState, f) == offsetof(HartState, x) + sizeof(HartState::x));
#define f (XR + 33)
  FWSIM_PINNED(uint8_t*, ram, "r15") = bus_.ram();
  const uint32_t ram_size = bus_.ram_size();
  // RAM size in units of 1, 2 and 4 bytes: the limits of the rotated offsets.
  const uint32_t ram_units[3] = {ram_size, ram_size >> 1, ram_size >> 2};
  const uint64_t start = hart_.instret;
  const uint64_t limit = max_instructions > start ? max_instructions - start : 0;
  // Instructions are counted per straight-line run, in bytes of entries:
  // `k` is (count up to the last jump target) * sizeof(Entry) minus that
  // target's address, so the running count is (k + ip) / sizeof(Entry), a
  // taken jump updates k with one subtraction and straight-line code pays
  // nothing for counting.
  static_assert(sizeof(Entry) == 8);
  // The plain loop keeps k in the cycle count's register, which it has no
  // other use for: a taken jump then updates it without a stack load and
  // store.
  uint64_t k_timed = 0;
#define K_VALUE() (Timed ? k_timed : static_cast<uint64_t>(CYC))
#define K_SET(v)                      \
  do {                                \
    if constexpr (Timed) k_timed = (v); \
    else CYC = (v);                   \
  } while (0)
  K_SET(0 - reinterpret_cast<uint64_t>(ip));
  // Block-costed timing (Mode 1): slots, enters and leaves parallel the
  // entries with the same stride, so each is `ip` plus a fixed distance.
  Entry* const start_ip = ip;
  Entry* run_start = ip;      // first entry of the current straight-line run
  // A run entered by a jump is not charged its first entry's stall (the
  // slot's `stall`, subtracted on entry). Every run after the first was; the
  // first is while k + run_start is 0 (any taken jump makes it the count).
  bool start_discounted = false;
#define DISCOUNTED() (start_discounted || K_VALUE() + reinterpret_cast<uint64_t>(run_start) != 0)
  // The slots' distance is read by every instruction of the block-costed
  // loop: pinned like `ram` (GCC otherwise may leave it in a stack slot).
  FWSIM_PINNED(intptr_t, slot_bias, "r13") = 0;
  intptr_t enter_bias = 0, leave_bias = 0;
  bool static_branches = false;  // branch cycles come from the slots (BlockCosts)
  // Generated code for hot runs: plain blocks in Mode 3, timed blocks in
  // Mode 1 (block_jit.hpp).
  BlockJit* jit = Mode == 3 ? jit_.get() : nullptr;
  if constexpr (Mode == 1) {
    if (costs_.built_for() != model_) {
      costs_.build(code_, model);
      if (timed_jit_) timed_jit_->flush();  // its blocks add the old slots
    }
    static_branches = costs_.static_branches();
    if (jit_enabled_ && !fpu_model_) {
      const BlockJit::Timing timing{costs_.slots(), costs_.enters(), costs_.leaves(), profiler_ != nullptr,
                                    static_branches ? nullptr : &model};
      if (!timed_jit_ || !(timed_jit_->timing() == timing)) {
        const uint64_t made = timed_jit_ ? timed_jit_->blocks_made() : 0;
        timed_jit_ = std::make_unique<BlockJit>(code_.count(), code_base, ram_size, &timing);
        timed_jit_->add_blocks_made(made);
      }
      if (timed_jit_->available()) jit = timed_jit_.get();
    }
    slot_bias = reinterpret_cast<char*>(costs_.slots()) - reinterpret_cast<char*>(base);
    enter_bias = reinterpret_cast<char*>(costs_.enters()) - reinterpret_cast<char*>(base);
    leave_bias = reinterpret_cast<char*>(costs_.leaves()) - reinterpret_cast<char*>(base);
  }
#define SLOT(p) (*reinterpret_cast<CostSlot*>(reinterpret_cast<char*>(p) + slot_bias))
#define ENTERS(p) (*reinterpret_cast<uint64_t*>(reinterpret_cast<char*>(p) + enter_bias))
#define LEAVES(p) (*reinterpret_cast<uint64_t*>(reinterpret_cast<char*>(p) + leave_bias))
  if constexpr (Mode == 1) {
    ++ENTERS(ip);
    // Resuming right after the previous run's last instruction: the stall
    // (if any) applies as in straight-line code.
    start_discounted = resume_pc_ != hart_.pc;
    if (start_discounted) CYC -= SLOT(ip).stall;
  }
  const uint64_t limit8 = limit > (UINT64_MAX >> 3) ? UINT64_MAX : limit << 3;
  uintptr_t* const jit_table = jit ? jit->table() : nullptr;
  (void)jit_table;
  StopInfo stop;
  Bus::Result bus_result = Bus::Result::Ok;
  bool retire_stopper = false;

  // The cycle count lives in a register; the model's hooks take it by reference.
#define MODEL_CALL(fn, ...)         \
  do {                              \
    uint64_t cycles_ = CYC;      \
    model.fn(__VA_ARGS__, cycles_); \
    CYC = cycles_;               \
  } while (0)
#define PC_OF(p) (code_base + (static_cast<uint32_t>((p) - base) << shift))
#define RETIRED() ((K_VALUE() + reinterpret_cast<uint64_t>(ip)) >> 3)
#define NOW() (Timed ? CYC : start + RETIRED())
#define SYNC()                                                 \
  do {                                                         \
    hart_.instret = start + RETIRED();                         \
    hart_.cycles = Timed ? CYC : start + RETIRED();   \
  } while (0)
#define KEEP_PINNED()                                   \
  do {                                                  \
    FWSIM_KEEP(ram);                                    \
    if constexpr (Mode == 1) FWSIM_KEEP(slot_bias);     \
  } while (0)
#define DISPATCH()      \
  do {                  \
    KEEP_PINNED();      \
    goto* labels[ip->op]; \
  } while (0)
#define STEP()                                           \
  do {                                                   \
    if constexpr (Hooks) {                               \
      MODEL_CALL(instruction, *ip, PC_OF(ip));         \
      if (tracing) trace_instruction(PC_OF(ip));         \
    } else if constexpr (Timed) {                        \
      CYC += SLOT(ip).cost;                           \
    }                                                    \
  } while (0)
#define NEXT_THEN(cont) \
  do {                  \
    STEP();             \
    ++ip;               \
    KEEP_PINNED();      \
    cont;               \
  } while (0)
#define NEXT() NEXT_THEN(DISPATCH())
  // On the stop paths: past the second half of the 32-bit instruction just
  // retired (with C), which is not counted.
#define PAST_SKIP()                                    \
  do {                                                 \
    if (ip->op == static_cast<uint8_t>(Op::SKIP)) {    \
      ++ip;                                            \
      K_SET(K_VALUE() - sizeof(Entry));                \
    }                                                  \
  } while (0)
  // Closes the straight-line run at the current instruction (which retires)
  // and starts one at `target`; `done` is the count so far, in bytes.
#define ENTER(target, done)                                   \
  do {                                                        \
    if constexpr (Mode == 1) {                                \
      ++LEAVES(ip);                                           \
      ++ENTERS(target);                                       \
      run_start = (target);                                   \
      CYC -= SLOT(run_start).stall;                           \
    }                                                         \
    K_SET((done) - reinterpret_cast<uint64_t>(target));       \
    ip = (target);                                            \
    if ((done) > limit8) goto limit_reached;                  \
    if constexpr (Mode == 3) goto jit_enter;                  \
    if constexpr (Mode == 1) {                                \
      if (jit_table) goto jit_enter;                          \
    }                                                         \
  } while (0)
#define DONE() (K_VALUE() + reinterpret_cast<uint64_t>(ip + 1))
#define JUMP(target)                          \
  do {                                        \
    STEP();                                   \
    Entry* const to_ = (target);              \
    const uint64_t done_ = DONE();            \
    ENTER(to_, done_);                        \
    DISPATCH();                               \
  } while (0)
#define FAULT(c, a)      \
  do {                   \
    stop.cause = (c);    \
    stop.addr = (a);     \
    goto fault;          \
  } while (0)
#define BRANCH_THEN(cond, cont)                                                   \
  do {                                                                 \
    const bool taken = (cond);                                         \
    if constexpr (Mode == 1) {                                         \
      if (!static_branches) MODEL_CALL(branch, PC_OF(ip), taken, ip->imm < 0); \
      else if (taken) CYC += static_cast<uint64_t>(int64_t{SLOT(ip).taken});  \
    } else if constexpr (Timed) {                                      \
      MODEL_CALL(branch, PC_OF(ip), taken, ip->imm < 0);               \
    }                                                                  \
    if (taken) JUMP(ip + ip->imm);                                     \
    NEXT_THEN(cont);                                                            \
  } while (0)
#define BRANCH(cond) BRANCH_THEN(cond, DISPATCH())
#define RS1 XR[ip->rs1]
#define RS2 XR[ip->rs2]
#define RD XR[ip->rd]
#define ALU_THEN(expr, cont) \
  do {            \
    RD = (expr);  \
    NEXT_THEN(cont);       \
  } while (0)
#define ALU(expr) ALU_THEN(expr, DISPATCH())
  // Memory: one range+alignment check for RAM, everything else on the bus.
  // Load and store immediates are decoded minus the RAM base, so base + imm
  // is already the offset into RAM.
  // Debugger watchpoints, checked only in the hooked loop.
#define WATCH(size, store)                                                 \
  do {                                                                     \
    if constexpr (Hooks) {                                                 \
      if (!watches_.empty()) {                                             \
        if (const uint8_t kind_ = watch_hit(addr, (size), (store))) {      \
          stop.addr = addr;                                                \
          stop.watch_kind = kind_;                                         \
          goto watch_stop;                                                 \
        }                                                                  \
      }                                                                    \
    }                                                                      \
  } while (0)
  // Rotating the offset right by log2(size) moves misaligned low bits to the
  // top, so one unsigned compare checks both range and alignment.
#define IN_RAM(T)                                                                   \
  __builtin_expect(std::rotr(off, std::countr_zero(sizeof(T))) < ram_units[std::countr_zero(sizeof(T))], 1)
#define BUS_FAULTS(misaligned, fault)                                 \
  if (bus_result == Bus::Result::Misaligned) FAULT(misaligned, addr); \
  if (bus_result == Bus::Result::Fault) FAULT(fault, addr)
#define LOAD_THEN(T, dest, cont)                                                                   \
  do {                                                                                  \
    const uint32_t off = RS1 + static_cast<uint32_t>(ip->imm);                          \
    const uint32_t addr = off + ram_base;                                               \
    T v;                                                                                \
    if (IN_RAM(T)) {                                                                    \
      std::memcpy(&v, ram + off, sizeof(T));                                            \
    } else {                                                                            \
      SYNC();                                                                           \
      uint32_t raw = 0;                                                                 \
      bus_result = bus_.load(addr, sizeof(T), raw, NOW());                              \
      BUS_FAULTS(StopCause::MisalignedLoad, StopCause::LoadFault);                      \
      if (bus_result == Bus::Result::Stop) {                                            \
        stop.addr = addr;                                                               \
        goto device_stop;                                                               \
      }                                                                                 \
      v = static_cast<T>(raw);                                                          \
    }                                                                                   \
    if constexpr (Hooks) MODEL_CALL(data, addr);                                              \
    dest = static_cast<uint32_t>(v);                                                    \
    WATCH(sizeof(T), false);                                                            \
    NEXT_THEN(cont);                                                                             \
  } while (0)
#define LOAD(T, dest) LOAD_THEN(T, dest, DISPATCH())
#define STORE_THEN(T, value, cont)                                                                  \
  do {                                                                                   \
    const uint32_t off = RS1 + static_cast<uint32_t>(ip->imm);                           \
    const uint32_t addr = off + ram_base;                                                \
    const T v = static_cast<T>(value);                                                   \
    if (IN_RAM(T)) {                                                                     \
      std::memcpy(ram + off, &v, sizeof(T));                                             \
    } else {                                                                             \
      SYNC();                                                                            \
      bus_result = bus_.store(addr, sizeof(T), v, NOW());                                \
      BUS_FAULTS(StopCause::MisalignedStore, StopCause::StoreFault);                     \
      if (bus_result == Bus::Result::Stop) {                                             \
        stop.addr = addr;                                                                \
        retire_stopper = true;                                                           \
        goto device_stop;                                                                \
      }                                                                                  \
    }                                                                                    \
    if constexpr (Hooks) MODEL_CALL(data, addr);                                               \
    WATCH(sizeof(T), true);                                                              \
    NEXT_THEN(cont);                                                                              \
  } while (0)
#define STORE(T, value) STORE_THEN(T, value, DISPATCH())
#define CSR(op, operand, write)                                                         \
  do {                                                                                  \
    SYNC();                                                                             \
    uint32_t old;                                                                       \
    if (!csr_.access(hart_, static_cast<unsigned>(ip->imm) & 0xfff, op, operand, write, old)) \
      FAULT(StopCause::IllegalInstruction, 0);                                          \
    RD = old;                                                                           \
    labels = dispatch_tables[hart_.frm == fpu::RNE];                                    \
    NEXT();                                                                             \
  } while (0)
  // Effective rounding mode; reserved modes are illegal instructions.
#define ROUNDING(var)                                                      \
  const unsigned var = entry_rm(*ip) == fpu::DYN ? hart_.frm : entry_rm(*ip); \
  if (var > fpu::RMM) FAULT(StopCause::IllegalInstruction, 0)
#define FP_ARITH(host_expr, soft_fn)                                           \
  do {                                                                         \
    ROUNDING(rm);                                                              \
    const float a = as_float(f[ip->rs1]), b = as_float(f[ip->rs2]);            \
    (void)b;                                                                   \
    f[ip->rd] = rm == fpu::RNE ? host_result(host_expr)                        \
                               : soft_fn;                                      \
    NEXT();                                                                    \
  } while (0)
  // Host FMA when present; a NaN addend takes the soft path because RISC-V
  // requires NV for inf*0 even then, which the host need not raise.
#define FP_FUSED(neg_product, neg_addend)                                                      \
  do {                                                                                         \
    ROUNDING(rm);                                                                              \
    const uint32_t c = f[entry_rs3(*ip)];                                                      \
    if (rm == fpu::RNE && kHostHasFma && !fpu::is_nan(c)) {                                    \
      const uint32_t a = f[ip->rs1] ^ ((neg_product) ? 0x80000000u : 0u);                     \
      const uint32_t b = c ^ ((neg_addend) ? 0x80000000u : 0u);                               \
      f[ip->rd] = host_result(host_fma(as_float(a), as_float(f[ip->rs2]), as_float(b)));     \
    } else {                                                                                   \
      f[ip->rd] = fpu::fma(f[ip->rs1], f[ip->rs2], c, neg_product, neg_addend, rm, hart_.fflags); \
    }                                                                                          \
    NEXT();                                                                                    \
  } while (0)

  // RNE-table handlers: fall back to the generic handler for static modes.
#define FP_RNE_THEN(generic, expr, cont)                                        \
  do {                                                               \
    if (!(ip->imm & kRneOrDyn)) goto generic;                        \
    const float a = as_float(f[ip->rs1]), b = as_float(f[ip->rs2]);  \
    (void)a;                                                         \
    (void)b;                                                         \
    f[ip->rd] = host_result(expr);                                   \
    NEXT_THEN(cont);                                                          \
  } while (0)
#define FP_RNE(generic, expr) FP_RNE_THEN(generic, expr, DISPATCH())
#define FP_RNE_FUSED(generic, neg_product, neg_addend)                                   \
  do {                                                                                   \
    const uint32_t c = f[entry_rs3(*ip)];                                                \
    if (!(ip->imm & kRneOrDyn) || !kHostHasFma || fpu::is_nan(c)) goto generic;          \
    const uint32_t a = f[ip->rs1] ^ ((neg_product) ? 0x80000000u : 0u);                  \
    const uint32_t b = c ^ ((neg_addend) ? 0x80000000u : 0u);                            \
    f[ip->rd] = host_result(host_fma(as_float(a), as_float(f[ip->rs2]), as_float(b)));  \
    NEXT();                                                                              \
  } while (0)

  // FPU-model handlers: the rounding-mode field is still checked (reserved
  // modes stay illegal); the model decides what it does with the mode.
#define FP_MODEL(expr)            \
  do {                            \
    ROUNDING(rm);                 \
    f[ip->rd] = (expr);           \
    NEXT();                       \
  } while (0)

  DISPATCH();

M_FADD_S: FP_MODEL(approx->add(f[ip->rs1], f[ip->rs2], rm, hart_.fflags));
M_FSUB_S: FP_MODEL(approx->sub(f[ip->rs1], f[ip->rs2], rm, hart_.fflags));
M_FMUL_S: FP_MODEL(approx->mul(f[ip->rs1], f[ip->rs2], rm, hart_.fflags));
M_FDIV_S: FP_MODEL(approx->div(f[ip->rs1], f[ip->rs2], rm, hart_.fflags));
M_FSQRT_S: FP_MODEL(approx->sqrt(f[ip->rs1], rm, hart_.fflags));

R_FADD_S: FP_RNE(L_FADD_S, a + b);
R_FSUB_S: FP_RNE(L_FSUB_S, a - b);
R_FMUL_S: FP_RNE(L_FMUL_S, a * b);
R_FDIV_S: FP_RNE(L_FDIV_S, a / b);
R_FSQRT_S: FP_RNE(L_FSQRT_S, __builtin_sqrtf(a));
R_FMADD_S: FP_RNE_FUSED(L_FMADD_S, false, false);
R_FMSUB_S: FP_RNE_FUSED(L_FMSUB_S, false, true);
R_FNMSUB_S: FP_RNE_FUSED(L_FNMSUB_S, true, false);
R_FNMADD_S: FP_RNE_FUSED(L_FNMADD_S, true, true);
R_FCVT_S_W: FP_RNE(L_FCVT_S_W, static_cast<float>(static_cast<int32_t>(XR[ip->rs1])));
R_FCVT_S_WU: FP_RNE(L_FCVT_S_WU, static_cast<float>(XR[ip->rs1]));

  // Fused pairs (isa_table.hpp FWSIM_FUSED): the first instruction's body,
  // then straight to the second's handler without a dispatch.
#define BODY_FLW(cont) LOAD_THEN(uint32_t, f[ip->rd], cont)
#define BODY_LW(cont) LOAD_THEN(uint32_t, RD, cont)
#define BODY_FMUL_S(cont) FP_RNE_THEN(L_FMUL_S, a * b, cont)
#define BODY_FADD_S(cont) FP_RNE_THEN(L_FADD_S, a + b, cont)
#define BODY_FSUB_S(cont) FP_RNE_THEN(L_FSUB_S, a - b, cont)
#define BODY_FSGNJX_S(cont)                                      \
  do {                                                           \
    f[ip->rd] = f[ip->rs1] ^ (f[ip->rs2] & 0x80000000u);         \
    NEXT_THEN(cont);                                             \
  } while (0)
#define BODY_FLT_S(cont) ALU_THEN(host_lt(f[ip->rs1], f[ip->rs2]), cont)
#define BODY_FLE_S(cont) ALU_THEN(host_le(f[ip->rs1], f[ip->rs2]), cont)
#define BODY_ADDI(cont) ALU_THEN(RS1 + static_cast<uint32_t>(ip->imm), cont)
#define BODY_ADD(cont) ALU_THEN(RS1 + RS2, cont)
#define BODY_SLLI(cont) ALU_THEN(RS1 << ip->imm, cont)
#define BODY_AND(cont) ALU_THEN(RS1 & RS2, cont)
#define BODY_BEQ(cont) BRANCH_THEN(RS1 == RS2, cont)
#define BODY_BNE(cont) BRANCH_THEN(RS1 != RS2, cont)
#define BODY_BGE(cont) BRANCH_THEN(static_cast<int32_t>(RS1) >= static_cast<int32_t>(RS2), cont)
#define BODY_LUI(cont) ALU_THEN(static_cast<uint32_t>(ip->imm), cont)
#define BODY_SLT(cont) ALU_THEN(static_cast<int32_t>(RS1) < static_cast<int32_t>(RS2), cont)
#define BODY_SLTU(cont) ALU_THEN(RS1 < RS2, cont)
#define BODY_LBU(cont) LOAD_THEN(uint8_t, RD, cont)
#define BODY_FSW(cont) STORE_THEN(uint32_t, f[ip->rs2], cont)
#define BODY_FMV_W_X(cont) \
  do {                     \
    f[ip->rd] = RS1;       \
    NEXT_THEN(cont);       \
  } while (0)
  // The second instruction's handler in the RNE table.
#define SECOND_FLW L_FLW
#define SECOND_LW L_LW
#define SECOND_FMUL_S R_FMUL_S
#define SECOND_FADD_S R_FADD_S
#define SECOND_FSUB_S R_FSUB_S
#define SECOND_FSGNJX_S L_FSGNJX_S
#define SECOND_FLT_S L_FLT_S
#define SECOND_FLE_S L_FLE_S
#define SECOND_XORI L_XORI
#define SECOND_ADDI L_ADDI
#define SECOND_ADD L_ADD
#define SECOND_BEQ L_BEQ
#define SECOND_BNE L_BNE
#define SECOND_BGE L_BGE
#define SECOND_LUI L_LUI
#define SECOND_FMV_W_X L_FMV_W_X
#define SECOND_FSW L_FSW
#define SECOND_AND L_AND
#define SECOND_SLT L_SLT
#define SECOND_SLTU L_SLTU
#define FWSIM_FUSED_HANDLER(name, a, b) \
  F_##name:                             \
  BODY_##a(goto SECOND_##b);
  FWSIM_FUSED(FWSIM_FUSED_HANDLER)
#undef FWSIM_FUSED_HANDLER

L_UNDECODED: {
  code_.fill(static_cast<uint32_t>(ip - base), code_mem);
  if constexpr (Mode == 1) {
    const uint64_t old_stall = SLOT(ip).stall;
    costs_.update(code_, model, static_cast<uint32_t>(ip - base));
    // A block starting after this entry added its old slot.
    if (jit_table) jit->drop(static_cast<uint32_t>(ip - base) + 1);
    // A run entered here by a jump was discounted before the stall was known.
    if (ip == run_start && DISCOUNTED()) CYC = CYC + old_stall - SLOT(ip).stall;
  }
  DISPATCH();
}
L_ILLEGAL: FAULT(StopCause::IllegalInstruction, 0);
L_OUTSIDE_ISA: {
  const uint32_t word = instruction_at(PC_OF(ip));
  stop.detail = missing_extension(code_.isa(), word, code_.compressed() ? decode_any(word) : decode(word));
  FAULT(StopCause::OutsideIsa, 0);
}
L_SKIP:
  // Straight-line code steps over the second half of a 32-bit instruction
  // without counting it.
  ++ip;
  K_SET(K_VALUE() - sizeof(Entry));
  DISPATCH();
L_SELF_JUMP: {
  // The board's "loop" halt: a taken jump or branch to itself ends the run.
  const DecodedInsn d = decode_any(instruction_at(PC_OF(ip)));
  if (branch_condition(d.op, XR[d.rs1], XR[d.rs2])) {
    if (d.op == Op::JAL && d.rd != 0) XR[d.rd] = PC_OF(ip) + d.length;
    stop.exit_code = static_cast<int>(XR[10]);
    goto halt_exit;
  }
  if constexpr (Timed) MODEL_CALL(branch, PC_OF(ip), false, false);
  NEXT();
}
L_FETCH_FAULT: FAULT(StopCause::FetchFault, PC_OF(ip));
L_BREAKPOINT: FAULT(StopCause::Breakpoint, PC_OF(ip));
L_SLOW_CTI: {
  // A branch or jal whose target is outside code memory, off the entry
  // grid, or inside a 32-bit instruction (overlapping instructions, which
  // are not supported: an illegal instruction).
  const DecodedInsn d = decode_any(instruction_at(PC_OF(ip)));
  const bool taken = branch_condition(d.op, XR[d.rs1], XR[d.rs2]);
  if (!taken) {
    if constexpr (Timed) MODEL_CALL(branch, PC_OF(ip), false, false);
    NEXT();
  }
  const uint32_t target = PC_OF(ip) + static_cast<uint32_t>(d.imm);
  FAULT((target & fetch_align)               ? StopCause::MisalignedFetch
        : target - code_base >= code_size ? StopCause::FetchFault
                                             : StopCause::IllegalInstruction,
        target);
}
L_LUI: ALU(static_cast<uint32_t>(ip->imm));
L_AUIPC: ALU(PC_OF(ip) + static_cast<uint32_t>(ip->imm));
L_JAL: {
  Entry* const target = ip + ip->imm;
  const uint32_t link = PC_OF(ip) + ip->rs2;
  RD = link;
  STEP();
  const uint64_t done = DONE();
  if constexpr (Timed) {
    if (profiler && ip->rd == 1) profiler->call(PC_OF(target), link, Cost{start + (done >> 3), CYC});
  }
  ENTER(target, done);
  DISPATCH();
}
L_JALR: {
  const uint32_t target = (RS1 + static_cast<uint32_t>(ip->imm)) & ~1u;
  if (target & fetch_align) FAULT(StopCause::MisalignedFetch, target);
  if (target - code_base >= code_size) FAULT(StopCause::FetchFault, target);
  Entry* const to = base + ((target - code_base) >> shift);
  if (to->op == static_cast<uint8_t>(Op::SKIP)) FAULT(StopCause::IllegalInstruction, target);
  const uint32_t link = PC_OF(ip) + ip->rs2;
  RD = link;
  STEP();
  const uint64_t done = DONE();
  if constexpr (Timed) {
    if (profiler) {
      const Cost now{start + (done >> 3), CYC};
      if (ip->rd == 1) profiler->call(target, link, now);
      else if (ip->rd == kSinkReg && ip->rs1 == 1) profiler->ret(target, now);
    }
  }
  ENTER(to, done);
  DISPATCH();
}
L_BEQ: BRANCH(RS1 == RS2);
L_BNE: BRANCH(RS1 != RS2);
L_BLT: BRANCH(static_cast<int32_t>(RS1) < static_cast<int32_t>(RS2));
L_BGE: BRANCH(static_cast<int32_t>(RS1) >= static_cast<int32_t>(RS2));
L_BLTU: BRANCH(RS1 < RS2);
L_BGEU: BRANCH(RS1 >= RS2);
L_LB: LOAD(int8_t, RD);
L_LH: LOAD(int16_t, RD);
L_LW: LOAD(uint32_t, RD);
L_LBU: LOAD(uint8_t, RD);
L_LHU: LOAD(uint16_t, RD);
L_SB: STORE(uint8_t, RS2);
L_SH: STORE(uint16_t, RS2);
L_SW: STORE(uint32_t, RS2);
L_ADDI: ALU(RS1 + static_cast<uint32_t>(ip->imm));
L_SLTI: ALU(static_cast<int32_t>(RS1) < ip->imm);
L_SLTIU: ALU(RS1 < static_cast<uint32_t>(ip->imm));
L_XORI: ALU(RS1 ^ static_cast<uint32_t>(ip->imm));
L_ORI: ALU(RS1 | static_cast<uint32_t>(ip->imm));
L_ANDI: ALU(RS1 & static_cast<uint32_t>(ip->imm));
L_SLLI: ALU(RS1 << ip->imm);
L_SRLI: ALU(RS1 >> ip->imm);
L_SRAI: ALU(static_cast<uint32_t>(static_cast<int32_t>(RS1) >> ip->imm));
L_ADD: ALU(RS1 + RS2);
L_SUB: ALU(RS1 - RS2);
L_SLL: ALU(RS1 << (RS2 & 31));
L_SLT: ALU(static_cast<int32_t>(RS1) < static_cast<int32_t>(RS2));
L_SLTU: ALU(RS1 < RS2);
L_XOR: ALU(RS1 ^ RS2);
L_SRL: ALU(RS1 >> (RS2 & 31));
L_SRA: ALU(static_cast<uint32_t>(static_cast<int32_t>(RS1) >> (RS2 & 31)));
L_OR: ALU(RS1 | RS2);
L_AND: ALU(RS1 & RS2);
L_FENCE: NEXT();
L_FENCE_I:
  // The entry after it (its second half, with C) is dropped too: step past
  // it before anything decodes it as an instruction.
  NEXT_THEN(code_.invalidate_all(); if (shift == 1) { ++ip; K_SET(K_VALUE() - sizeof(Entry)); } DISPATCH());
L_ECALL:
  if (halt_on_ecall && XR[17] == kEcallExit) {
    stop.exit_code = static_cast<int>(XR[10]);
    goto halt_exit;
  }
  FAULT(StopCause::Ecall, 0);
L_EBREAK: FAULT(StopCause::Ebreak, 0);
L_MUL: ALU(RS1 * RS2);
L_MULH: ALU(static_cast<uint32_t>((int64_t{static_cast<int32_t>(RS1)} * static_cast<int32_t>(RS2)) >> 32));
L_MULHSU: ALU(static_cast<uint32_t>((int64_t{static_cast<int32_t>(RS1)} * int64_t{RS2}) >> 32));
L_MULHU: ALU(static_cast<uint32_t>((uint64_t{RS1} * RS2) >> 32));
L_DIV: ALU(div_s(RS1, RS2));
L_DIVU: ALU(RS2 ? RS1 / RS2 : ~0u);
L_REM: ALU(rem_s(RS1, RS2));
L_REMU: ALU(RS2 ? RS1 % RS2 : RS1);
L_CSRRW: CSR(CsrOp::Write, RS1, true);
L_CSRRS: CSR(CsrOp::Set, RS1, ip->rs1 != 0);
L_CSRRC: CSR(CsrOp::Clear, RS1, ip->rs1 != 0);
L_CSRRWI: CSR(CsrOp::Write, ip->rs1, true);
L_CSRRSI: CSR(CsrOp::Set, ip->rs1, ip->rs1 != 0);
L_CSRRCI: CSR(CsrOp::Clear, ip->rs1, ip->rs1 != 0);
L_FLW: LOAD(uint32_t, f[ip->rd]);
L_FSW: STORE(uint32_t, f[ip->rs2]);
L_FMADD_S: FP_FUSED(false, false);
L_FMSUB_S: FP_FUSED(false, true);
L_FNMSUB_S: FP_FUSED(true, false);
L_FNMADD_S: FP_FUSED(true, true);
L_FADD_S: FP_ARITH(a + b, fpu::add(f[ip->rs1], f[ip->rs2], rm, hart_.fflags));
L_FSUB_S: FP_ARITH(a - b, fpu::sub(f[ip->rs1], f[ip->rs2], rm, hart_.fflags));
L_FMUL_S: FP_ARITH(a * b, fpu::mul(f[ip->rs1], f[ip->rs2], rm, hart_.fflags));
L_FDIV_S: FP_ARITH(a / b, fpu::div(f[ip->rs1], f[ip->rs2], rm, hart_.fflags));
L_FSQRT_S: FP_ARITH(__builtin_sqrtf(a), fpu::sqrt(f[ip->rs1], rm, hart_.fflags));
L_FSGNJ_S: {
  f[ip->rd] = (f[ip->rs1] & 0x7fffffffu) | (f[ip->rs2] & 0x80000000u);
  NEXT();
}
L_FSGNJN_S: {
  f[ip->rd] = (f[ip->rs1] & 0x7fffffffu) | (~f[ip->rs2] & 0x80000000u);
  NEXT();
}
L_FSGNJX_S: {
  f[ip->rd] = f[ip->rs1] ^ (f[ip->rs2] & 0x80000000u);
  NEXT();
}
L_FMIN_S: {
  f[ip->rd] = fpu::min(f[ip->rs1], f[ip->rs2], hart_.fflags);
  NEXT();
}
L_FMAX_S: {
  f[ip->rd] = fpu::max(f[ip->rs1], f[ip->rs2], hart_.fflags);
  NEXT();
}
L_FCVT_W_S: {
  ROUNDING(rm);
  ALU(fpu::to_int32(f[ip->rs1], rm, hart_.fflags));
}
L_FCVT_WU_S: {
  ROUNDING(rm);
  ALU(fpu::to_uint32(f[ip->rs1], rm, hart_.fflags));
}
L_FMV_X_W: ALU(f[ip->rs1]);
L_FEQ_S: ALU(host_eq(f[ip->rs1], f[ip->rs2]));
L_FLT_S: ALU(host_lt(f[ip->rs1], f[ip->rs2]));
L_FLE_S: ALU(host_le(f[ip->rs1], f[ip->rs2]));
L_FCLASS_S: ALU(fpu::classify(f[ip->rs1]));
L_FCVT_S_W: {
  ROUNDING(rm);
  f[ip->rd] = rm == fpu::RNE ? host_result(static_cast<float>(static_cast<int32_t>(RS1)))
                             : fpu::from_int32(static_cast<int32_t>(RS1), rm, hart_.fflags);
  NEXT();
}
L_FCVT_S_WU: {
  ROUNDING(rm);
  f[ip->rd] = rm == fpu::RNE ? host_result(static_cast<float>(RS1)) : fpu::from_uint32(RS1, rm, hart_.fflags);
  NEXT();
}
L_FMV_W_X: {
  f[ip->rd] = RS1;
  NEXT();
}

device_stop:
  // A device ended the run: the finisher (the store retires), a UART whose
  // input is exhausted while the firmware keeps polling, or a host I/O error.
  stop.pc = PC_OF(ip);
  if (retire_stopper) {
    STEP();
    ++ip;
    PAST_SKIP();
  }
  if (bus_.finished()) {
    stop.cause = StopCause::Exit;
    stop.exit_code = bus_.exit_code();
  } else if (bus_.uart() && bus_.uart()->stalled()) {
    stop.cause = StopCause::UartStall;
  } else {
    stop.cause = StopCause::HostIo;
  }
  goto out;
jit_enter:
  __attribute__((unused));  // reached only from the loop with generated code
  // A run entered by a taken jump (or left by generated code at a target it
  // has no block for): counted until hot, then translated and run.
  if constexpr (Mode == 3 || Mode == 1) {
    uintptr_t* const slot = jit_table + (ip - base);
    uintptr_t v = *slot;
    if (v < BlockJit::kHot) {
      *slot = v + 1;
      DISPATCH();
    }
    if (jit->epoch() != code_.epoch()) {
      // Decoded entries changed (fence.i, debugger): every block is stale.
      jit->flush();
      jit->set_epoch(code_.epoch());
      DISPATCH();
    }
    if (v == BlockJit::kHot) v = *slot = jit->compile(base, static_cast<uint32_t>(ip - base));
    // Blocks assume frm = RNE for dynamic-rounding FP ops.
    if (v == BlockJit::kNoBlock || hart_.frm != fpu::RNE) DISPATCH();
    BlockJit::State st{XR, ram, jit_table, RETIRED(), limit, 0, static_cast<uint32_t>(run_start - base),
                       Timed ? static_cast<uint64_t>(CYC) : 0, start, profiler};
    ip = base + jit->run(st, v);
    if constexpr (Mode == 1) {
      CYC = st.cycles;
      run_start = base + st.run_start;
    }
    K_SET(st.count * sizeof(Entry) - reinterpret_cast<uint64_t>(ip));
    if (st.exit == static_cast<uint32_t>(BlockJit::Exit::Target)) goto jit_enter;
    if (st.exit == static_cast<uint32_t>(BlockJit::Exit::Limit)) goto limit_reached;
    DISPATCH();
  }
  DISPATCH();
watch_stop:
  __attribute__((unused));  // reached only from the hooked loop
  // The accessing instruction has run: report the stop after it.
  stop.pc = PC_OF(ip);
  STEP();
  ++ip;
  PAST_SKIP();
  stop.cause = StopCause::Watchpoint;
  goto out;
halt_exit:
  // The board's ecall or jump-to-self halt: the instruction retires.
  stop.pc = PC_OF(ip);
  STEP();
  ++ip;
  PAST_SKIP();
  stop.cause = StopCause::Exit;
  goto out;
limit_reached:
  stop.cause = StopCause::InstructionLimit;
  stop.pc = PC_OF(ip);
  goto out;
fault:
  stop.pc = PC_OF(ip);
out:
  if constexpr (Mode == 1) {
    uint32_t last = BlockCosts::kNoEntry;
    if (ip != run_start) {
      ++LEAVES(ip - 1);
      last = static_cast<uint32_t>(ip - 1 - base);
      resume_pc_ = PC_OF(ip);
    } else {
      // Nothing of this run retired: undo its entry.
      --ENTERS(ip);
      if (DISCOUNTED()) CYC += SLOT(ip).stall;
      if (ip != start_ip) resume_pc_ = ~0u;
    }
    costs_.fold(code_, code_mem, model, last);
  }
  hart_.pc = PC_OF(ip);
  SYNC();  // ip is not retired: the count runs up to it
  XR[0] = 0;
  return stop;

#undef PC_OF
#undef f
#undef x
#undef CYC
#undef NOW
#undef RETIRED
#undef K_VALUE
#undef DISCOUNTED
#undef K_SET
#undef ENTER
#undef SLOT
#undef ENTERS
#undef LEAVES
#undef DONE
#undef SYNC
#undef DISPATCH
#undef STEP
#undef NEXT
#undef PAST_SKIP
#undef JUMP
#undef FAULT
#undef BRANCH
#undef RS1
#undef RS2
#undef RD
#undef ALU
#undef LOAD
#undef IN_RAM
#undef WATCH
#undef BUS_FAULTS
#undef STORE
#undef CSR
#undef ROUNDING
#undef FP_ARITH
#undef FP_FUSED
#undef FP_RNE
#undef FP_RNE_FUSED
#undef FP_MODEL
}

template StopInfo Machine::run_loop<0>(uint64_t);
template StopInfo Machine::run_loop<1>(uint64_t);
template StopInfo Machine::run_loop<2>(uint64_t);
template StopInfo Machine::run_loop<3>(uint64_t);

}  // namespace fwsim
