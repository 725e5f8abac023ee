// fwsim-fuzzgen SEED OUT.S: writes a random RV32IMF test body as assembly.
// `fuzz_body` loads seeded edge values into the x and f registers and fcsr,
// runs random instructions (forward branches only, memory only inside a
// scratch buffer, no pc-dependent results), then stores x1, x5..x26,
// x28..x31, f0..f31 and fcsr into `fuzz_dump`. The same body is linked with
// linux_main.S (qemu-riscv32) and bare_main.S (firmware-sim) and the dumps
// compared. x2-x4 (sp, gp, tp) are never touched; x27 holds the scratch base.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace {

std::mt19937 rng;
unsigned pick(unsigned n) { return static_cast<unsigned>(rng() % n); }
template <typename T, size_t N>
const T& pick(const T (&a)[N]) { return a[pick(N)]; }

const char* const kX[32] = {"zero", "ra", "sp", "gp", "tp", "t0", "t1", "t2", "s0", "s1", "a0",
                            "a1",   "a2", "a3", "a4", "a5", "a6", "a7", "s2", "s3", "s4", "s5",
                            "s6",   "s7", "s8", "s9", "s10", "s11", "t3", "t4", "t5", "t6"};
const unsigned kWritable[] = {1,  5,  6,  7,  8,  9,  10, 11, 12, 13, 14, 15, 16,
                              17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 28, 29, 30, 31};

std::string xd() { return kX[pick(kWritable)]; }
std::string xs() { return pick(8) == 0 ? "zero" : kX[pick(kWritable)]; }
std::string fr() { return "f" + std::to_string(pick(32)); }
std::string rm() {
  static const char* const modes[] = {"rne", "rtz", "rdn", "rup", "rmm", "dyn", "dyn", "dyn"};
  return pick(modes);
}

uint32_t x_value() {
  static const uint32_t edges[] = {0, 1, 0xffffffffu, 0x80000000u, 0x7fffffffu, 0x80000001u, 2, 31, 32,
                                   0xfffffffeu, 0x10000, 0xffff8000u, 16777217u, 0x4f000000u};
  return pick(2) ? pick(edges) : static_cast<uint32_t>(rng());
}

uint32_t f_value() {
  static const uint32_t edges[] = {
      0x00000000u, 0x80000000u, 0x7f800000u, 0xff800000u, 0x7fc00000u, 0xffc00000u, 0x7f800001u,
      0xff812345u, 0x7fc12345u, 0x00000001u, 0x807fffffu, 0x00800000u, 0x80800000u, 0x7f7fffffu,
      0xff7fffffu, 0x3f800000u, 0xbf800000u, 0x3f000000u, 0x3fc00000u, 0x40200000u, 0xc0200000u,
      0x4f000000u, 0xcf000000u, 0x4f800000u, 0x4effffffu, 0x33800000u, 0x34000000u, 0x3f800001u};
  switch (pick(4)) {
    case 0: return static_cast<uint32_t>(rng());
    case 1: return (static_cast<uint32_t>(rng()) & 0x807fffffu) | ((120 + pick(16)) << 23);
    default: return pick(edges);
  }
}

std::string instruction(int& label) {
  static const char* const alu_r[] = {"add", "sub", "sll", "slt", "sltu", "xor", "srl", "sra", "or",
                                      "and", "mul", "mulh", "mulhsu", "mulhu", "div", "divu", "rem", "remu"};
  static const char* const alu_i[] = {"addi", "slti", "sltiu", "xori", "ori", "andi"};
  static const char* const shifts[] = {"slli", "srli", "srai"};
  static const char* const loads[] = {"lb", "lh", "lw", "lbu", "lhu"};
  static const char* const stores[] = {"sb", "sh", "sw"};
  static const char* const f_rrr[] = {"fadd.s", "fsub.s", "fmul.s", "fdiv.s"};
  static const char* const f_sgn[] = {"fsgnj.s", "fsgnjn.s", "fsgnjx.s", "fmin.s", "fmax.s"};
  static const char* const f_fused[] = {"fmadd.s", "fmsub.s", "fnmsub.s", "fnmadd.s"};
  static const char* const f_cmp[] = {"feq.s", "flt.s", "fle.s"};
  static const char* const branches[] = {"beq", "bne", "blt", "bge", "bltu", "bgeu"};
  switch (pick(24)) {
    case 0: case 1: case 2: return std::string(pick(alu_r)) + " " + xd() + ", " + xs() + ", " + xs();
    case 3: return std::string(pick(alu_i)) + " " + xd() + ", " + xs() + ", " + std::to_string(static_cast<int>(pick(4096)) - 2048);
    case 4: return std::string(pick(shifts)) + " " + xd() + ", " + xs() + ", " + std::to_string(pick(32));
    case 5: return "lui " + xd() + ", " + std::to_string(pick(1u << 20));
    case 6: {
      const unsigned w = pick(3);
      const char* op = w == 0 ? loads[pick(2) ? 0 : 3] : w == 1 ? loads[pick(2) ? 1 : 4] : loads[2];
      return std::string(op) + " " + xd() + ", " + std::to_string(pick(64 >> w) << w) + "(s11)";
    }
    case 7: {
      const unsigned w = pick(3);
      return std::string(stores[w]) + " " + xs() + ", " + std::to_string(pick(64 >> w) << w) + "(s11)";
    }
    case 8: return "flw " + fr() + ", " + std::to_string(pick(64) * 4) + "(s11)";
    case 9: return "fsw " + fr() + ", " + std::to_string(pick(64) * 4) + "(s11)";
    case 10: case 11: case 12: return std::string(pick(f_rrr)) + " " + fr() + ", " + fr() + ", " + fr() + ", " + rm();
    case 13: return "fsqrt.s " + fr() + ", " + fr() + ", " + rm();
    case 14: return std::string(pick(f_sgn)) + " " + fr() + ", " + fr() + ", " + fr();
    case 15: case 16:
      return std::string(pick(f_fused)) + " " + fr() + ", " + fr() + ", " + fr() + ", " + fr() + ", " + rm();
    case 17: return std::string(pick(2) ? "fcvt.w.s " : "fcvt.wu.s ") + xd() + ", " + fr() + ", " + rm();
    case 18: return std::string(pick(2) ? "fcvt.s.w " : "fcvt.s.wu ") + fr() + ", " + xs() + ", " + rm();
    case 19: {
      static const char* const moves[] = {"fmv.x.w", "fclass.s"};
      if (pick(3) == 0) return "fmv.w.x " + fr() + ", " + xs();
      return std::string(pick(moves)) + " " + xd() + ", " + fr();
    }
    case 20: return std::string(pick(f_cmp)) + " " + xd() + ", " + fr() + ", " + fr();
    case 21: {
      // Dynamic rounding mode changes and flag reads/clears.
      switch (pick(3)) {
        case 0: return "csrrwi " + xd() + ", frm, " + std::to_string(pick(5));
        case 1: return "csrrs " + xd() + ", fflags, zero";
        default: return "csrrci " + xd() + ", fflags, " + std::to_string(pick(32));
      }
    }
    case 22: {
      // Forward branch over 1..3 instructions.
      const int l = ++label;
      std::string s = std::string(pick(branches)) + " " + xs() + ", " + xs() + ", .Lf" + std::to_string(l);
      const unsigned skip = 1 + pick(3);
      for (unsigned i = 0; i < skip; ++i) s += "\n  " + instruction(label);
      return s + "\n.Lf" + std::to_string(l) + ":";
    }
    default: return "addi " + xd() + ", " + xs() + ", " + std::to_string(static_cast<int>(pick(64)) - 32);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: fwsim-fuzzgen SEED OUT.S\n");
    return 2;
  }
  rng.seed(static_cast<uint32_t>(std::strtoul(argv[1], nullptr, 0)));
  std::ofstream out(argv[2]);
  out << "# generated by fwsim-fuzzgen " << argv[1] << "\n  .data\n  .p2align 2\nfuzz_init_x:\n";
  for (int i = 0; i < 32; ++i) out << "  .word " << x_value() << "\n";
  out << "fuzz_init_f:\n";
  for (int i = 0; i < 32; ++i) out << "  .word " << f_value() << "\n";
  out << "fuzz_scratch:\n";
  for (int i = 0; i < 64; ++i) out << "  .word " << x_value() << "\n";
  out << "fuzz_saved_ra:\n  .word 0\n  .globl fuzz_dump\nfuzz_dump:\n  .space " << (27 + 32 + 1) * 4 << "\n";
  out << "\n  .text\n  .globl fuzz_body\n  .p2align 2\nfuzz_body:\n";
  out << "  la t0, fuzz_saved_ra\n  sw ra, 0(t0)\n  li t0, " << pick(5) * 32 << "\n  csrw fcsr, t0\n";
  out << "  la s11, fuzz_init_f\n";
  for (int i = 0; i < 32; ++i) out << "  flw f" << i << ", " << i * 4 << "(s11)\n";
  out << "  la s11, fuzz_init_x\n";
  for (unsigned r : kWritable) out << "  lw " << kX[r] << ", " << r * 4 << "(s11)\n";
  out << "  la s11, fuzz_scratch\n";
  int label = 0;
  const int count = 120 + static_cast<int>(pick(80));
  for (int i = 0; i < count; ++i) out << "  " << instruction(label) << "\n";
  out << "  la s11, fuzz_dump\n";
  int slot = 0;
  for (unsigned r : kWritable) out << "  sw " << kX[r] << ", " << 4 * slot++ << "(s11)\n";
  for (int i = 0; i < 32; ++i) out << "  fsw f" << i << ", " << 4 * slot++ << "(s11)\n";
  out << "  csrr t0, fcsr\n  sw t0, " << 4 * slot << "(s11)\n";
  out << "  la t0, fuzz_saved_ra\n  lw ra, 0(t0)\n  ret\n";
  return out ? 0 : 1;
}
