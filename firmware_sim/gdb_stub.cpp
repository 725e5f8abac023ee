#include "gdb_stub.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <utility>
#include <vector>

#include "compressed.hpp"
#include "decoder.hpp"
#include "disassembler.hpp"
#include "fpu.hpp"
#include "isa_table.hpp"

namespace fwsim {
namespace {

// GDB's register numbers for RISC-V: x0..x31, pc, f0..f31, then CSRs at
// 65 + the CSR number (fflags 1, frm 2, fcsr 3).
constexpr unsigned kRegPc = 32, kRegF0 = 33, kRegFflags = 66, kRegFrm = 67, kRegFcsr = 68;
constexpr unsigned kRegCsr0 = 65;
// Instructions run between checks for gdb's interrupt (Ctrl-C) while continuing.
constexpr uint64_t kInterruptCheckInterval = 1u << 22;

// Signal numbers gdb expects in stop replies.
constexpr int kSigInt = 2, kSigIll = 4, kSigTrap = 5, kSigBus = 7, kSigSegv = 11;

std::string hex_u32_le(uint32_t v) {
  char buf[9];
  std::snprintf(buf, sizeof buf, "%02x%02x%02x%02x", v & 0xff, (v >> 8) & 0xff, (v >> 16) & 0xff, v >> 24);
  return buf;
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// Parses a big-endian hex number (addresses, lengths); false on junk.
bool parse_hex(const std::string& s, uint64_t& v) {
  if (s.empty() || s.size() > 16) return false;
  v = 0;
  for (char c : s) {
    const int d = hex_digit(c);
    if (d < 0) return false;
    v = v << 4 | static_cast<unsigned>(d);
  }
  return true;
}

// Parses 8 hex digits of a little-endian 32-bit register value.
bool parse_u32_le(const std::string& s, size_t pos, uint32_t& v) {
  if (pos + 8 > s.size()) return false;
  v = 0;
  for (unsigned i = 0; i < 4; ++i) {
    const int hi = hex_digit(s[pos + 2 * i]), lo = hex_digit(s[pos + 2 * i + 1]);
    if (hi < 0 || lo < 0) return false;
    v |= static_cast<uint32_t>(hi << 4 | lo) << (8 * i);
  }
  return true;
}

bool read_register(Machine& m, unsigned n, uint32_t& v) {
  HartState& h = m.hart();
  if (n < 32) v = n == 0 ? 0 : h.x[n];
  else if (n == kRegPc) v = h.pc;
  else if (n >= kRegF0 && n < kRegF0 + 32) v = h.f[n - kRegF0];
  else if (n == kRegFflags) v = h.fflags;
  else if (n == kRegFrm) v = h.frm;
  else if (n == kRegFcsr) v = static_cast<uint32_t>(h.frm) << 5 | h.fflags;
  // Other CSRs: gdb numbers CSR c as register kRegCsr0 + c.
  else if (n >= kRegCsr0 && n < kRegCsr0 + 4096) return m.csr().access(h, n - kRegCsr0, CsrOp::Set, 0, false, v);
  else return false;
  return true;
}

bool write_register(Machine& m, unsigned n, uint32_t v) {
  HartState& h = m.hart();
  if (n < 32) {
    if (n) h.x[n] = v;
  } else if (n == kRegPc) h.pc = v;
  else if (n >= kRegF0 && n < kRegF0 + 32) h.f[n - kRegF0] = v;
  else if (n == kRegFflags) h.fflags = v & 0x1f;
  else if (n == kRegFrm) h.frm = v & 7;
  else if (n == kRegFcsr) {
    h.fflags = v & 0x1f;
    h.frm = (v >> 5) & 7;
  } else if (n >= kRegCsr0 && n < kRegCsr0 + 4096) {
    uint32_t old;
    return m.csr().access(h, n - kRegCsr0, CsrOp::Write, v, true, old);
  } else return false;
  return true;
}

}  // namespace

const std::string& gdb_target_xml() {
  static const std::string xml = [] {
    std::string s =
        "<?xml version=\"1.0\"?>\n<!DOCTYPE target SYSTEM \"gdb-target.dtd\">\n<target version=\"1.0\">\n"
        "<architecture>riscv:rv32</architecture>\n<feature name=\"org.gnu.gdb.riscv.cpu\">\n";
    for (unsigned i = 0; i < 32; ++i) {
      const char* type = i == 1 ? "code_ptr" : i == 2 ? "data_ptr" : "int";
      s += "  <reg name=\"" + std::string(x_reg_name(i)) + "\" bitsize=\"32\" type=\"" + type + "\" regnum=\"" +
           std::to_string(i) + "\"/>\n";
    }
    s += "  <reg name=\"pc\" bitsize=\"32\" type=\"code_ptr\" regnum=\"32\"/>\n</feature>\n"
         "<feature name=\"org.gnu.gdb.riscv.fpu\">\n";
    for (unsigned i = 0; i < 32; ++i)
      s += "  <reg name=\"" + std::string(f_reg_name(i)) + "\" bitsize=\"32\" type=\"ieee_single\" regnum=\"" +
           std::to_string(kRegF0 + i) + "\"/>\n";
    s += "  <reg name=\"fflags\" bitsize=\"32\" type=\"int\" regnum=\"66\"/>\n"
         "  <reg name=\"frm\" bitsize=\"32\" type=\"int\" regnum=\"67\"/>\n"
         "  <reg name=\"fcsr\" bitsize=\"32\" type=\"int\" regnum=\"68\"/>\n</feature>\n"
         "<feature name=\"org.gnu.gdb.riscv.csr\">\n";
    // The machine-mode CSRs firmware-sim keeps (csr.cpp), and the counters.
    const std::pair<const char*, unsigned> csrs[] = {
        {"mstatus", 0x300}, {"misa", 0x301}, {"mie", 0x304}, {"mtvec", 0x305}, {"mscratch", 0x340},
        {"mepc", 0x341},    {"mcause", 0x342}, {"mtval", 0x343}, {"mip", 0x344}, {"cycle", 0xc00},
        {"instret", 0xc02}, {"cycleh", 0xc80}, {"instreth", 0xc82}};
    for (const auto& [name, csr] : csrs)
      s += std::string("  <reg name=\"") + name + "\" bitsize=\"32\" type=\"int\" regnum=\"" +
           std::to_string(kRegCsr0 + csr) + "\"/>\n";
    s += "</feature>\n</target>\n";
    return s;
  }();
  return xml;
}

GdbStub::GdbStub(int port) {
  listen_fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (listen_fd_ < 0) throw std::runtime_error(std::string("gdb: cannot create a socket: ") + std::strerror(errno));
  const int one = 1;
  ::setsockopt(listen_fd_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);  // never reachable from other machines
  addr.sin_port = htons(static_cast<uint16_t>(port));
  if (::bind(listen_fd_, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0 || ::listen(listen_fd_, 1) != 0) {
    const int err = errno;
    ::close(listen_fd_);
    throw std::runtime_error("gdb: cannot listen on 127.0.0.1:" + std::to_string(port) + ": " + std::strerror(err));
  }
  socklen_t len = sizeof addr;
  ::getsockname(listen_fd_, reinterpret_cast<sockaddr*>(&addr), &len);
  port_ = ntohs(addr.sin_port);
}

GdbStub::~GdbStub() {
  if (fd_ >= 0) ::close(fd_);
  if (listen_fd_ >= 0) ::close(listen_fd_);
}

bool GdbStub::read_packet(std::string& packet) {
  // Packets are "$payload#cs"; acknowledgements (+/-) and stray bytes
  // between packets are skipped.
  for (;;) {
    const size_t start = inbuf_.find('$');
    if (start != std::string::npos) {
      const size_t hash = inbuf_.find('#', start);
      if (hash != std::string::npos && inbuf_.size() >= hash + 3) {
        packet = inbuf_.substr(start + 1, hash - start - 1);
        unsigned sum = 0;
        for (unsigned char c : packet) sum += c;
        const int hi = hex_digit(inbuf_[hash + 1]), lo = hex_digit(inbuf_[hash + 2]);
        inbuf_.erase(0, hash + 3);
        const bool ok = hi >= 0 && lo >= 0 && static_cast<unsigned>(hi << 4 | lo) == (sum & 0xff);
        if (::send(fd_, ok ? "+" : "-", 1, MSG_NOSIGNAL) != 1) return false;
        if (ok) return true;
        continue;
      }
    } else {
      inbuf_.clear();
    }
    char buf[4096];
    const ssize_t n = ::recv(fd_, buf, sizeof buf, 0);
    if (n <= 0) {
      if (n < 0 && errno == EINTR) continue;
      return false;
    }
    inbuf_.append(buf, static_cast<size_t>(n));
  }
}

void GdbStub::send_packet(const std::string& payload) {
  std::string out = "$";
  unsigned sum = 0;
  for (char c : payload) {
    if (c == '$' || c == '#' || c == '}' || c == '*') {
      out += '}';
      sum += '}';
      c = static_cast<char>(c ^ 0x20);
    }
    out += c;
    sum += static_cast<unsigned char>(c);
  }
  char tail[4];
  std::snprintf(tail, sizeof tail, "#%02x", sum & 0xff);
  out += tail;
  // gdb acknowledges with '+'; read_packet skips it.
  for (size_t done = 0; done < out.size();) {
    const ssize_t n = ::send(fd_, out.data() + done, out.size() - done, MSG_NOSIGNAL);
    if (n <= 0) {
      if (n < 0 && errno == EINTR) continue;
      return;  // the next read sees the closed connection
    }
    done += static_cast<size_t>(n);
  }
}

bool GdbStub::interrupt_pending() {
  pollfd p{fd_, POLLIN, 0};
  if (::poll(&p, 1, 0) <= 0) return false;
  char buf[256];
  const ssize_t n = ::recv(fd_, buf, sizeof buf, MSG_DONTWAIT);
  if (n <= 0) return true;  // connection closed: stop and let serve() notice
  bool interrupt = false;
  for (ssize_t i = 0; i < n; ++i) {
    if (buf[i] == 0x03) interrupt = true;
    else inbuf_ += buf[i];
  }
  return interrupt;
}

std::string GdbStub::stop_reply(const StopInfo& s) const {
  char buf[16];
  int sig = kSigTrap;
  switch (s.cause) {
    case StopCause::Exit:
      std::snprintf(buf, sizeof buf, "W%02x", s.exit_code & 0xff);
      return buf;
    case StopCause::UartStall: case StopCause::HostIo: case StopCause::InstructionLimit:
      std::snprintf(buf, sizeof buf, "W%02x", exit_status(s));
      return buf;
    case StopCause::IllegalInstruction: case StopCause::Ecall: sig = kSigIll; break;
    case StopCause::LoadFault: case StopCause::StoreFault: case StopCause::FetchFault: sig = kSigSegv; break;
    case StopCause::MisalignedLoad: case StopCause::MisalignedStore: case StopCause::MisalignedFetch:
      sig = kSigBus;
      break;
    case StopCause::None: sig = kSigInt; break;  // interrupted by gdb
    case StopCause::Watchpoint: {
      char t[48];
      std::snprintf(t, sizeof t, "T%02x%s:%08x;", kSigTrap,
                    s.watch_kind == 2 ? "watch" : s.watch_kind == 3 ? "rwatch" : "awatch", s.addr);
      return t;
    }
    default: break;  // breakpoint, step, ebreak: SIGTRAP
  }
  std::snprintf(buf, sizeof buf, "S%02x", sig);
  return buf;
}

StopInfo GdbStub::step(Machine& m, uint64_t max_instructions) {
  // One instruction: temporary breakpoints on every possible successor
  // (fall-through, branch or jump target), the user's breakpoint at pc
  // lifted meanwhile. An instruction that jumps to itself is stopped by
  // the instruction limit (checked at taken jumps) instead.
  HartState& h = m.hart();
  const uint32_t pc = h.pc;
  std::vector<uint32_t> next{pc + 4};
  if (m.bus().in_code(pc, 2) && !(pc & 1)) {
    uint32_t word = 0;
    std::memcpy(&word, m.bus().code_at(pc), m.bus().in_code(pc, 4) ? 4 : 2);
    const DecodedInsn d = m.compressed() ? decode_any(word) : decode(word);
    next = {pc + d.length};
    const Format f = op_info(d.op).format;
    if (f == Format::Branch) next.push_back(pc + static_cast<uint32_t>(d.imm));
    else if (f == Format::J) next = {pc + static_cast<uint32_t>(d.imm)};
    else if (f == Format::Jalr) next = {(h.x[d.rs1] + static_cast<uint32_t>(d.imm)) & ~1u};
  }
  const bool user_bp_here = breakpoints_.count(pc) != 0;
  if (user_bp_here) m.clear_breakpoint(pc);
  std::vector<uint32_t> temporary;
  bool self_loop = false;
  for (uint32_t a : next) {
    if (a == pc) self_loop = true;
    else if (!breakpoints_.count(a) && m.set_breakpoint(a)) temporary.push_back(a);
  }
  // run(N) stops at the first taken jump once more than N have retired.
  const uint64_t limit = self_loop ? std::min(h.instret, max_instructions) : max_instructions;
  StopInfo s = m.run(limit);
  if (s.cause == StopCause::InstructionLimit && self_loop && h.instret <= max_instructions)
    s.cause = StopCause::Breakpoint;
  for (uint32_t a : temporary) m.clear_breakpoint(a);
  if (user_bp_here) m.set_breakpoint(pc);
  return s;
}

StopInfo GdbStub::resume(Machine& m, uint64_t max_instructions) {
  // Off a breakpoint first, then run in slices so gdb's Ctrl-C is seen.
  if (breakpoints_.count(m.hart().pc)) {
    const StopInfo s = step(m, max_instructions);
    if (s.cause != StopCause::Breakpoint) return s;
    if (breakpoints_.count(m.hart().pc)) return s;
  }
  for (;;) {
    const uint64_t slice_end = m.hart().instret + kInterruptCheckInterval;
    const bool last_slice = slice_end >= max_instructions;
    StopInfo s = m.run(last_slice ? max_instructions : slice_end);
    if (s.cause != StopCause::InstructionLimit || last_slice) return s;
    if (interrupt_pending()) {
      s.cause = StopCause::None;  // reported as SIGINT
      return s;
    }
  }
}

std::string GdbStub::handle_query(const std::string& q) {
  if (q.rfind("qSupported", 0) == 0) return "PacketSize=4000;qXfer:features:read+";
  if (q == "qAttached") return "1";
  if (q == "qC") return "QC1";
  if (q == "qfThreadInfo") return "m1";
  if (q == "qsThreadInfo") return "l";
  const std::string xfer = "qXfer:features:read:target.xml:";
  if (q.rfind(xfer, 0) == 0) {
    const std::string range = q.substr(xfer.size());
    const size_t comma = range.find(',');
    uint64_t off = 0, len = 0;
    if (comma == std::string::npos || !parse_hex(range.substr(0, comma), off) ||
        !parse_hex(range.substr(comma + 1), len))
      return "E01";
    const std::string& xml = gdb_target_xml();
    if (off >= xml.size()) return "l";
    const std::string part = xml.substr(off, len);
    return (off + part.size() >= xml.size() ? "l" : "m") + part;
  }
  if (q.rfind("qXfer:", 0) == 0) return "E00";
  return "";  // unsupported
}

std::string GdbStub::handle_monitor(Machine& m, const std::string& hex_command, const HartState& reset_state,
                                    StopInfo& last) {
  std::string command;
  for (size_t i = 0; i + 1 < hex_command.size(); i += 2) {
    const int hi = hex_digit(hex_command[i]), lo = hex_digit(hex_command[i + 1]);
    if (hi < 0 || lo < 0) return "E01";
    command += static_cast<char>(hi << 4 | lo);
  }
  std::string text;
  if (command == "icount") {
    text = "instructions: " + std::to_string(m.hart().instret) + ", cycles: " + std::to_string(m.hart().cycles) + "\n";
  } else if (command == "reset") {
    // Like a hardware reset: registers, pc and counters as at the start;
    // memory keeps what the program wrote.
    m.hart() = reset_state;
    last = StopInfo{};
    last.cause = StopCause::Breakpoint;
    last.pc = m.hart().pc;
    char pc[16];
    std::snprintf(pc, sizeof pc, "0x%08x", m.hart().pc);
    text = std::string("reset: pc ") + pc + "\n";
  } else {
    text = "monitor commands: icount (instructions and cycles so far), reset (registers, pc and counters)\n";
    if (command != "help") text = "unknown monitor command '" + command + "'; " + text;
  }
  std::string out = "O";
  for (unsigned char c : text) {
    char b[3];
    std::snprintf(b, sizeof b, "%02x", c);
    out += b;
  }
  send_packet(out);
  return "OK";
}

StopInfo GdbStub::serve(Machine& m, uint64_t max_instructions, bool& killed) {
  killed = false;
  std::fprintf(stderr, "firmware-sim: waiting for gdb on 127.0.0.1:%d\n", port_);
  std::fflush(stderr);
  do {
    fd_ = ::accept4(listen_fd_, nullptr, nullptr, SOCK_CLOEXEC);
  } while (fd_ < 0 && errno == EINTR);
  if (fd_ < 0) throw std::runtime_error(std::string("gdb: accept failed: ") + std::strerror(errno));
  const int one = 1;
  ::setsockopt(fd_, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
  ::close(listen_fd_);
  listen_fd_ = -1;

  StopInfo last;
  last.cause = StopCause::Breakpoint;  // "stopped at the entry point"
  last.pc = m.hart().pc;
  const HartState reset_state = m.hart();  // for "monitor reset"
  auto finished = [](const StopInfo& s) {
    return s.cause == StopCause::Exit || s.cause == StopCause::UartStall || s.cause == StopCause::HostIo ||
           s.cause == StopCause::InstructionLimit;
  };
  auto run_free = [&] {  // gdb gone: no breakpoints, run to the end
    for (uint32_t a : breakpoints_) m.clear_breakpoint(a);
    breakpoints_.clear();
    m.clear_watchpoints();
    return finished(last) ? last : m.run(max_instructions);
  };
  std::string p;
  for (;;) {
    if (!read_packet(p)) return run_free();  // gdb went away: behave as after a detach
    if (p.empty()) {
      send_packet("");
      continue;
    }
    const char cmd = p[0];
    const std::string args = p.substr(1);
    if (cmd == '?') {
      send_packet(stop_reply(last));
    } else if (p.rfind("qRcmd,", 0) == 0) {
      send_packet(handle_monitor(m, p.substr(6), reset_state, last));
    } else if (cmd == 'q') {
      send_packet(handle_query(p));
    } else if (cmd == 'Q') {
      send_packet("");
    } else if (cmd == 'H' || cmd == 'T') {
      send_packet("OK");
    } else if (cmd == 'g') {
      std::string out;
      for (unsigned i = 0; i <= kRegPc; ++i) {
        uint32_t v = 0;
        read_register(m, i, v);
        out += hex_u32_le(v);
      }
      send_packet(out);
    } else if (cmd == 'G') {
      bool ok = args.size() >= 8 * (kRegPc + 1);
      for (unsigned i = 0; ok && i <= kRegPc; ++i) {
        uint32_t v;
        ok = parse_u32_le(args, 8 * i, v) && write_register(m, i, v);
      }
      send_packet(ok ? "OK" : "E01");
    } else if (cmd == 'p') {
      uint64_t n;
      uint32_t v;
      send_packet(parse_hex(args, n) && n < 4096 && read_register(m, static_cast<unsigned>(n), v) ? hex_u32_le(v)
                                                                                                   : "E01");
    } else if (cmd == 'P') {
      const size_t eq = args.find('=');
      uint64_t n;
      uint32_t v;
      const bool ok = eq != std::string::npos && parse_hex(args.substr(0, eq), n) && n < 4096 &&
                      parse_u32_le(args, eq + 1, v) && write_register(m, static_cast<unsigned>(n), v);
      send_packet(ok ? "OK" : "E01");
    } else if (cmd == 'm' || cmd == 'M') {
      const size_t comma = args.find(',');
      const size_t colon = args.find(':');
      uint64_t addr = 0, len = 0;
      const bool parsed = comma != std::string::npos && parse_hex(args.substr(0, comma), addr) &&
                          parse_hex(args.substr(comma + 1, cmd == 'M' ? colon - comma - 1 : std::string::npos), len) &&
                          addr <= UINT32_MAX && len <= 0x10000;
      if (!parsed) {
        send_packet("E01");
      } else if (cmd == 'm') {
        // RAM and ROM only: device registers have side effects a debugger must not trigger.
        std::string out;
        for (uint64_t i = 0; i < len && m.bus().host_at(static_cast<uint32_t>(addr + i), 1); ++i) {
          char b[3];
          std::snprintf(b, sizeof b, "%02x", *m.bus().host_at(static_cast<uint32_t>(addr + i), 1));
          out += b;
        }
        send_packet(out.empty() && len ? "E01" : out);
      } else {
        bool ok = colon != std::string::npos && args.size() - colon - 1 == 2 * len &&
                  (len == 0 || m.bus().host_at(static_cast<uint32_t>(addr), static_cast<uint32_t>(len)));
        for (uint64_t i = 0; ok && i < len; ++i) {
          const int hi = hex_digit(args[colon + 1 + 2 * i]), lo = hex_digit(args[colon + 2 + 2 * i]);
          if (hi < 0 || lo < 0) ok = false;
          else *m.bus().host_at(static_cast<uint32_t>(addr + i), 1) = static_cast<uint8_t>(hi << 4 | lo);
        }
        if (ok && len) {
          m.invalidate_code(static_cast<uint32_t>(addr), static_cast<uint32_t>(len));
          // Breakpoints in the rewritten words stay armed.
          for (uint32_t a : breakpoints_) m.set_breakpoint(a);
        }
        send_packet(ok ? "OK" : "E01");
      }
    } else if ((cmd == 'Z' || cmd == 'z') && !args.empty() && args[0] >= '2' && args[0] <= '4') {
      // Z2/Z3/Z4: write, read and access watchpoints over ADDR,LEN.
      const size_t c1 = args.find(','), c2 = args.find(',', c1 + 1);
      uint64_t addr = 0, len = 0;
      const bool ok = c1 == 1 && c2 != std::string::npos && parse_hex(args.substr(c1 + 1, c2 - c1 - 1), addr) &&
                      parse_hex(args.substr(c2 + 1), len) && addr <= UINT32_MAX && len > 0 && len <= UINT32_MAX;
      const uint8_t kind = static_cast<uint8_t>(args[0] - '0');
      if (!ok) send_packet("E01");
      else if (cmd == 'Z') {
        m.add_watchpoint(static_cast<uint32_t>(addr), static_cast<uint32_t>(len), kind);
        send_packet("OK");
      } else {
        m.remove_watchpoint(static_cast<uint32_t>(addr), static_cast<uint32_t>(len), kind);
        send_packet("OK");
      }
    } else if (cmd == 'Z' || cmd == 'z') {
      // Z0/z0: software breakpoints (hardware ones, Z1, are the same to us).
      const size_t c1 = args.find(','), c2 = args.find(',', c1 + 1);
      uint64_t addr;
      if (args.empty() || (args[0] != '0' && args[0] != '1') || c1 == std::string::npos ||
          c2 == std::string::npos || !parse_hex(args.substr(c1 + 1, c2 - c1 - 1), addr) || addr > UINT32_MAX) {
        send_packet("");
      } else if (cmd == 'Z') {
        const bool ok = m.set_breakpoint(static_cast<uint32_t>(addr));
        if (ok) breakpoints_.insert(static_cast<uint32_t>(addr));
        send_packet(ok ? "OK" : "E01");
      } else {
        if (breakpoints_.erase(static_cast<uint32_t>(addr))) m.clear_breakpoint(static_cast<uint32_t>(addr));
        send_packet("OK");
      }
    } else if (cmd == 'c' || cmd == 's') {
      uint64_t addr;
      if (!args.empty() && parse_hex(args, addr)) m.hart().pc = static_cast<uint32_t>(addr);
      if (!finished(last)) last = cmd == 's' ? step(m, max_instructions) : resume(m, max_instructions);
      send_packet(stop_reply(last));
      if (finished(last)) return last;
    } else if (cmd == 'D') {
      send_packet("OK");
      return run_free();
    } else if (cmd == 'k') {
      killed = true;
      return last;
    } else if (p.rfind("vKill", 0) == 0) {
      send_packet("OK");
      killed = true;
      return last;
    } else {
      send_packet("");  // vCont?, vMustReplyEmpty, X... : not supported
    }
  }
}

}  // namespace fwsim
