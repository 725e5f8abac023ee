// The GDB stub at the packet level (the gdb-multiarch session is
// gdb-session.sh): target description, registers, bad packets, Ctrl-C while
// the firmware spins, kill, and the command-line errors of --gdb.
#include <catch2/catch.hpp>

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <string>

#include "cli_runner.hpp"

using namespace cli;

namespace {

struct StubSession {
  pid_t pid = -1;
  int err = -1, sock = -1;

  explicit StubSession(const char* mode) {
    int pipe_fds[2];
    REQUIRE(::pipe(pipe_fds) == 0);
    pid = ::fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
      ::dup2(pipe_fds[1], 2);
      ::close(pipe_fds[0]);
      ::freopen("/dev/null", "w", stdout);  // the firmware's UART output
      ::execl(FWSIM_BINARY, FWSIM_BINARY, "--gdb", "0", kElf.c_str(), "--", mode, static_cast<char*>(nullptr));
      ::_exit(127);
    }
    ::close(pipe_fds[1]);
    err = pipe_fds[0];
    std::string line;
    char c;
    while (::read(err, &c, 1) == 1 && c != '\n') line += c;
    const std::string prefix = "firmware-sim: waiting for gdb on 127.0.0.1:";
    REQUIRE(line.rfind(prefix, 0) == 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    addr.sin_port = htons(static_cast<uint16_t>(std::stoi(line.substr(prefix.size()))));
    sock = ::socket(AF_INET, SOCK_STREAM, 0);
    REQUIRE(::connect(sock, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0);
  }
  ~StubSession() {
    if (sock >= 0) ::close(sock);
    if (err >= 0) ::close(err);
  }

  void send_raw(const std::string& bytes) { REQUIRE(::write(sock, bytes.data(), bytes.size()) == static_cast<ssize_t>(bytes.size())); }
  // Sends a packet, returns the reply's payload (acks skipped, checksum checked).
  std::string request(const std::string& payload) {
    unsigned sum = 0;
    for (unsigned char ch : payload) sum += ch;
    char cs[3];
    std::snprintf(cs, sizeof cs, "%02x", sum & 0xff);
    send_raw("$" + payload + "#" + cs);
    return reply();
  }
  std::string reply() {
    std::string got;
    char c;
    while (::read(sock, &c, 1) == 1 && c != '$') {}
    while (::read(sock, &c, 1) == 1 && c != '#') got += c;
    char cs[2];
    REQUIRE(::read(sock, cs, 2) == 2);
    unsigned sum = 0;
    for (unsigned char ch : got) sum += ch;
    CHECK(std::stoul(std::string(cs, 2), nullptr, 16) == (sum & 0xff));
    send_raw("+");
    return got;
  }
  int wait_status() {
    int status = 0;
    ::waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 1000 + WTERMSIG(status);
  }
};

}  // namespace

TEST_CASE("gdb stub: packets, Ctrl-C on a spinning firmware, kill", "[cli][gdb]") {
  StubSession s("spin");
  CHECK(s.request("qSupported:multiprocess+;swbreak+").find("qXfer:features:read+") != std::string::npos);
  const std::string xml = s.request("qXfer:features:read:target.xml:0,3fff");
  CHECK(xml.rfind("l<?xml", 0) == 0);
  CHECK(xml.find("<architecture>riscv:rv32</architecture>") != std::string::npos);
  CHECK(xml.find("<reg name=\"ft0\" bitsize=\"32\" type=\"ieee_single\" regnum=\"33\"/>") != std::string::npos);
  CHECK(xml.find("<reg name=\"fcsr\" bitsize=\"32\" type=\"int\" regnum=\"68\"/>") != std::string::npos);
  // A read in two parts gives the same document ('m' = more to come).
  const std::string part1 = s.request("qXfer:features:read:target.xml:0,10");
  CHECK(part1 == "m" + xml.substr(1, 16));
  CHECK(s.request("?") == "S05");
  // At the entry point: pc, a0 = argc = 3, a3 = the boot magic, little-endian hex.
  const std::string regs = s.request("g");
  CHECK(regs.size() == 33 * 8);
  CHECK(regs.substr(32 * 8) == "00000080");     // pc 0x80000000
  CHECK(regs.substr(10 * 8, 8) == "02000000");  // a0: argc (ELF, "spin")
  CHECK(regs.substr(13 * 8, 8) == "56475241");  // a3: MINRT_BOOT_MAGIC
  CHECK(s.request("p20") == "00000080");
  CHECK(s.request("P5=78563412") == "OK");
  CHECK(s.request("p5") == "78563412");
  CHECK(s.request("P5=00000000") == "OK");
  // The first instruction word, read from RAM: lui t0, 0x6 = 0x000062b7.
  CHECK(s.request("m80000000,4") == "b7620000");
  CHECK(s.request("m40000000,4") == "E01");  // no RAM there; devices are not read
  CHECK(s.request("Z0,40000000,4") == "E01");
  CHECK(s.request("vMustReplyEmpty").empty());
  // Continue: the firmware spins until gdb interrupts it.
  s.send_raw("$c#63");
  ::usleep(200 * 1000);
  s.send_raw("\x03");
  CHECK(s.reply() == "S02");
  const std::string pc = s.request("p20");
  CHECK(pc.size() == 8);
  CHECK(pc != "00000080");
  s.send_raw("$k#6b");
  CHECK(s.wait_status() == 8);
  std::string err;
  char c;
  while (::read(s.err, &c, 1) == 1) err += c;
  CHECK(err.rfind("firmware-sim: error: killed by gdb at pc 0x", 0) == 0);
}

TEST_CASE("gdb stub: step, breakpoint and continue to the exit", "[cli][gdb]") {
  StubSession s("args");  // prints its arguments, exits 0
  CHECK(s.request("s") == "S05");
  CHECK(s.request("p20") == "04000080");  // one instruction further
  CHECK(s.request("s") == "S05");
  CHECK(s.request("p20") == "08000080");
  // A breakpoint on the jump's target after crt0's bss loop is hit with
  // the instruction not yet run; continuing from it steps over it.
  CHECK(s.request("Z0,80000048,4") == "OK");
  CHECK(s.request("c") == "S05");
  CHECK(s.request("p20") == "48000080");
  CHECK(s.request("z0,80000048,4") == "OK");
  CHECK(s.request("c") == "W00");
  CHECK(s.wait_status() == 0);
}

TEST_CASE("gdb option errors", "[cli][gdb][usage]") {
  for (const char* args : {"--gdb 70000 ", "--gdb x ", "--gdb -1 ", "--gdb 1234 --pty "}) {
    CAPTURE(args);
    Result r = sim(args + kElf);
    CHECK(r.status == 2);
    CHECK(r.err.rfind("firmware-sim: error: --gdb", 0) == 0);
  }
}

namespace {
std::string hex_text(const std::string& text) {
  std::string out;
  char b[3];
  for (unsigned char c : text) {
    std::snprintf(b, sizeof b, "%02x", c);
    out += b;
  }
  return out;
}
}  // namespace

TEST_CASE("gdb stub: monitor icount, monitor reset, CSR registers", "[cli][gdb]") {
  StubSession s("spin");
  CHECK(s.request("qRcmd," + hex_text("icount")) == "O" + hex_text("instructions: 0, cycles: 0\n"));
  CHECK(s.reply() == "OK");
  CHECK(s.request("s") == "S05");
  CHECK(s.request("s") == "S05");
  CHECK(s.request("qRcmd," + hex_text("icount")) == "O" + hex_text("instructions: 2, cycles: 2\n"));
  CHECK(s.reply() == "OK");
  CHECK(s.request("p20") == "08000080");  // pc after two instructions
  CHECK(s.request("P5=78563412") == "OK");
  CHECK(s.request("qRcmd," + hex_text("reset")) == "O" + hex_text("reset: pc 0x80000000\n"));
  CHECK(s.reply() == "OK");
  CHECK(s.request("p20") == "00000080");
  CHECK(s.request("p5") == "00000000");
  CHECK(s.request("qRcmd," + hex_text("icount")) == "O" + hex_text("instructions: 0, cycles: 0\n"));
  CHECK(s.reply() == "OK");
  // CSRs as gdb numbers them (65 + CSR), listed in the target description.
  const std::string xml = s.request("qXfer:features:read:target.xml:0,3fff");
  CHECK(xml.find("<reg name=\"mstatus\" bitsize=\"32\" type=\"int\" regnum=\"833\"/>") != std::string::npos);
  CHECK(s.request("p381") == "00000000");  // mscratch (0x340)
  CHECK(s.request("P381=efbeadde") == "OK");
  CHECK(s.request("p381") == "efbeadde");
  CHECK(s.request("pc43") == "00000000");  // instret (0xc02) after the reset
  CHECK(s.request("p801") == "E01");       // CSR 0x7c0: not kept
  const std::string help = s.request("qRcmd," + hex_text("frobnicate"));
  CHECK(help.rfind("O" + hex_text("unknown monitor command 'frobnicate'"), 0) == 0);
  CHECK(s.reply() == "OK");
  s.send_raw("$k#6b");
  CHECK(s.wait_status() == 8);
}

namespace {
// The word at the hex little-endian address `pc_le` minus 4, as gdb reads it.
uint32_t word_before(StubSession& s, const std::string& pc_le) {
  const uint32_t pc = static_cast<uint32_t>(std::stoul(pc_le.substr(6, 2) + pc_le.substr(4, 2) + pc_le.substr(2, 2) +
                                                       pc_le.substr(0, 2), nullptr, 16));
  char req[32];
  std::snprintf(req, sizeof req, "m%x,4", pc - 4);
  const std::string w = s.request(req);
  return static_cast<uint32_t>(std::stoul(w.substr(6, 2) + w.substr(4, 2) + w.substr(2, 2) + w.substr(0, 2), nullptr, 16));
}
}  // namespace

TEST_CASE("gdb stub: write, read and access watchpoints", "[cli][gdb]") {
  StubSession s("spin");
  // Any store to RAM: the stop comes after the store, which is the word before pc.
  CHECK(s.request("Z2,80000000,400000") == "OK");
  const std::string w = s.request("c");
  CHECK(w.rfind("T05watch:8", 0) == 0);
  CHECK((word_before(s, s.request("p20")) & 0x7f) == 0x23);  // a store
  CHECK(s.request("z2,80000000,400000") == "OK");
  // Any load from RAM.
  CHECK(s.request("Z3,80000000,400000") == "OK");
  CHECK(s.request("c").rfind("T05rwatch:8", 0) == 0);
  const uint32_t load = word_before(s, s.request("p20"));
  CHECK(((load & 0x7f) == 0x03 || (load & 0x7f) == 0x07));  // lw.. or flw
  CHECK(s.request("z3,80000000,400000") == "OK");
  CHECK(s.request("Z4,80000000,400000") == "OK");
  CHECK(s.request("c").rfind("T05awatch:8", 0) == 0);
  CHECK(s.request("Z2,80000000,0") == "E01");
  s.send_raw("$k#6b");
  CHECK(s.wait_status() == 8);
}
