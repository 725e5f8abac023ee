// End-to-end tests of the firmware-sim command line on the test firmware
// (test/sim/firmware/test_firmware.c): the contract other tools rely on.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <sys/wait.h>
#include <termios.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "cli_runner.hpp"

using namespace cli;

TEST_CASE("the workload runs, prints over the UART and exits 0", "[cli]") {
  Result r = sim(kElf);
  CHECK(r.status == 0);
  CHECK(r.out.rfind("fwsim test workload\nhash ", 0) == 0);
  CHECK(r.out.find("recur ") != std::string::npos);
  CHECK(r.err.empty());
}

TEST_CASE("stats option prints the contract lines", "[cli]") {
  Result r = sim("--stats " + kElf);
  REQUIRE(r.status == 0);
  CHECK(std::regex_search(r.err, std::regex("(^|\n)instructions: [0-9]+\n")));
  CHECK(std::regex_search(r.err, std::regex("(^|\n)cycles: [0-9]+\n")));
  CHECK(std::regex_search(r.err, std::regex("(^|\n)host MIPS: [0-9]+(\\.[0-9]+)?\n")));
  // Deterministic: the same program retires the same instructions every run.
  CHECK(stat_value(r.err, "instructions") == stat_value(sim("--stats " + kElf).err, "instructions"));
}

TEST_CASE("ARGS after -- reach main(argc, argv)", "[cli][args]") {
  Result r = sim(kElf + " -- args alpha 'two words' ''");
  CHECK(r.status == 0);
  CHECK(r.out == "5 args alpha two words \n");
  CHECK(sim("--ram-size 8M " + kElf + " -- args x").out == "3 args x\n");
}

TEST_CASE("the firmware's exit code becomes the process status", "[cli]") {
  CHECK(sim(kElf + " -- exit 42").status == 42);
  CHECK(sim(kElf + " -- exit 0").status == 0);
}

TEST_CASE("traps stop with cause, pc, instruction and symbol, status 4", "[cli][faults]") {
  Result r = sim(kElf + " -- illegal");
  CHECK(r.status == 4);
  CHECK(r.err.find("illegal instruction at pc 0x8") != std::string::npos);
  CHECK(r.err.find("(main+0x") != std::string::npos);
  CHECK(r.err.find("<illegal 0xffffffff>") != std::string::npos);
  r = sim(kElf + " -- load-fault");
  CHECK(r.status == 4);
  CHECK(r.err.find("load access fault") != std::string::npos);
  CHECK(r.err.find("address 0x40000000") != std::string::npos);
  CHECK(r.err.find(": lw ") != std::string::npos);
  r = sim(kElf + " -- misaligned");
  CHECK(r.status == 4);
  CHECK(r.err.find("misaligned load") != std::string::npos);
  CHECK(sim(kElf + " -- ebreak").err.find("ebreak at pc") != std::string::npos);
  CHECK(sim(kElf + " -- ecall").status == 4);
}

TEST_CASE("max-instructions option stops a runaway firmware with status 5", "[cli]") {
  Result r = sim("--max-instructions 100000 " + kElf + " -- spin");
  CHECK(r.status == 5);
  CHECK(r.err.find("instruction limit exceeded") != std::string::npos);
  CHECK(sim("--max-instructions 100000000 " + kElf).status == 0);
}

TEST_CASE("UART input from stdin and files, output to a file", "[cli][uart]") {
  CHECK(sim(kElf + " -- echo", "hello\nq").out == "HELLO\n");
  const std::string in = temp_path("uin"), out = temp_path("uout");
  spit(in, "abc q");
  Result r = sim("--uart-in " + in + " --uart-out " + out + " " + kElf + " -- echo");
  CHECK(r.status == 0);
  CHECK(r.out.empty());
  CHECK(slurp(out) == "ABC ");
  std::remove(in.c_str());
  std::remove(out.c_str());
}

TEST_CASE("a firmware polling the UART after input EOF stops with status 6", "[cli][uart]") {
  Result r = sim(kElf + " -- echo", "abc");
  CHECK(r.status == 6);
  CHECK(r.out == "ABC");
  CHECK(r.err.find("UART input at end of file") != std::string::npos);
}

TEST_CASE("baud option paces the UART in simulated time without changing the bytes", "[cli][uart]") {
  Result fast = sim("--stats " + kElf + " -- echo", "hello world q");
  Result slow = sim("--stats --baud 9600 " + kElf + " -- echo", "hello world q");
  REQUIRE(fast.status == 0);
  REQUIRE(slow.status == 0);
  CHECK(fast.out == slow.out);
  // 12 bytes in, 12 out at 9600 baud and 100 MHz: >= 12 * 104166 cycles of waiting.
  CHECK(stat_value(slow.err, "cycles") > stat_value(fast.err, "cycles") + 12 * 100000);
}

TEST_CASE("bad usage is a one-line error with status 2", "[cli][usage]") {
  for (const char* args : {"", "--bogus x.elf", "--baud", "--baud fast x.elf", "--max-instructions -3 x.elf",
                           "--ram-size 3 x.elf", "a.elf b.elf"}) {
    CAPTURE(args);
    Result r = sim(args);
    CHECK(r.status == 2);
    CHECK(r.err.rfind("firmware-sim: error: ", 0) == 0);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  }
  Result no_input = sim("--uart-in /nonexistent/in.txt " + kElf);
  CHECK(no_input.status == 2);
  CHECK(no_input.err == "firmware-sim: error: /nonexistent/in.txt: No such file or directory\n");
  Result missing = sim("/nonexistent/fw.elf");
  CHECK(missing.status == 2);
  CHECK(missing.err == "firmware-sim: error: /nonexistent/fw.elf: No such file or directory\n");
  // A directory or a device as the ELF: refused before anything is read
  // (/dev/zero used to be read without end).
  Result dir = sim("/tmp");
  CHECK(dir.status == 2);
  CHECK(dir.err == "firmware-sim: error: /tmp: Is a directory\n");
  Result dev = sim("/dev/zero");
  CHECK(dev.status == 2);
  CHECK(dev.err == "firmware-sim: error: /dev/zero: not a regular file (a device)\n");
  // A file larger than the RAM it would load into: refused before reading.
  const std::string big = temp_path("big.elf");
  spit(big, slurp(kElf) + std::string(5u << 20, '\0'));
  Result large = sim("--ram-size 4M " + big);
  CHECK(large.status == 3);
  CHECK_THAT(large.err, Catch::Contains("larger than the 4194304-byte RAM"));
  CHECK(sim(std::string(FWSIM_SOURCE_DIR) + "/firmware_sim/models/default.cfg").status == 3);
  // A truncated copy of a valid ELF: clean error, no crash.
  const std::string cut = temp_path("cut.elf");
  spit(cut, slurp(kElf).substr(0, 100));
  Result t = sim(cut);
  CHECK(t.status == 3);
  CHECK(t.err == "firmware-sim: error: " + cut + ": segment beyond end of file\n");
  std::remove(cut.c_str());
  const std::string bad = temp_path("bad.cfg");
  spit(bad, "alu = 1\nwarp = 9\n");
  Result r = sim("--cycle-model " + bad + " " + kElf);
  CHECK(r.status == 2);
  CHECK(r.err.find(bad + ":2: unknown key 'warp'") != std::string::npos);
  std::remove(bad.c_str());
  CHECK(sim("--help").status == 0);
  CHECK(sim("--help").out.find("Usage: firmware-sim") != std::string::npos);
  CHECK(sim("--version").out.rfind("firmware-sim ", 0) == 0);
}

TEST_CASE("cycle model from a file changes cycles, not behaviour", "[cli][cycle]") {
  const std::string cfg = temp_path("slow.cfg");
  spit(cfg, "alu = 2\nfp_div = 40\n");
  Result d = sim("--stats --cycle-model default " + kElf);
  Result s = sim("--stats --cycle-model " + cfg + " " + kElf);
  std::remove(cfg.c_str());
  REQUIRE(d.status == 0);
  REQUIRE(s.status == 0);
  CHECK(d.out == s.out);
  CHECK(stat_value(d.err, "instructions") == stat_value(s.err, "instructions"));
  CHECK(stat_value(s.err, "cycles") > stat_value(d.err, "cycles"));
  CHECK(d.err.find("instruction mix: ") != std::string::npos);
}

TEST_CASE("counters CSRs work from firmware", "[cli][counters]") {
  CHECK(sim(kElf + " -- counters").out == "counters ok\n");
  CHECK(sim("--cycle-model default " + kElf + " -- counters").out == "counters ok\n");
}

TEST_CASE("trace option disassembles every executed instruction", "[cli][trace]") {
  Result r = sim("--trace " + kElf + " -- exit 3");
  CHECK(r.status == 3);
  CHECK(r.err.rfind("80000000: ", 0) == 0);
  CHECK(r.err.find("csrs") == std::string::npos);  // csrrs is shown as such, not an alias
  CHECK(r.err.find("csrrs zero, 0x300, t0") != std::string::npos);
}

TEST_CASE("profiles: callgrind and folded stacks agree with the run", "[cli][profile]") {
  const std::string cg = temp_path("cg.out"), folded = temp_path("folded.txt");
  Result r = sim("--stats --profile-out " + cg + " --folded-out " + folded + " " + kElf + " -- recur 15");
  REQUIRE(r.status == 0);
  // The firmware counts its own calls of recur.
  REQUIRE(r.out.find(' ') != std::string::npos);
  const unsigned calls = static_cast<unsigned>(std::stoul(r.out.substr(r.out.find(' ') + 1)));
  CHECK(calls == 1973);
  const std::string prof = slurp(cg), fold = slurp(folded);
  CHECK(prof.find("events: Ir Cycles\n") != std::string::npos);
  CHECK(prof.find(" recur\n") != std::string::npos);
  // One call from main, the rest recursive.
  CHECK(std::regex_search(prof, std::regex("cfn=\\([0-9]+\\) recur\ncalls=1 0\n")));
  CHECK(prof.find("calls=" + std::to_string(calls - 1) + " 0\n") != std::string::npos);
  // Folded stacks: exclusive cycles over all paths sum to the total.
  uint64_t sum = 0;
  std::istringstream lines(fold);
  for (std::string line; std::getline(lines, line);) sum += std::stoull(line.substr(line.rfind(' ') + 1));
  CHECK(sum == stat_value(r.err, "cycles"));
  CHECK(fold.find("_start;main;recur;recur;recur ") != std::string::npos);

  if (std::system("command -v callgrind_annotate >/dev/null 2>&1") != 0) {
    WARN("callgrind_annotate not installed (valgrind): skipping the annotate check");
  } else {
    Result a{0, "", ""};
    const std::string ann = temp_path("ann.txt");
    const int rc = std::system(("callgrind_annotate " + cg + " >" + ann + " 2>&1").c_str());
    a.out = slurp(ann);
    std::remove(ann.c_str());
    CHECK(rc == 0);
    CHECK(a.out.find("PROGRAM TOTALS") != std::string::npos);
    CHECK(a.out.find(":recur [") != std::string::npos);
    // Totals in callgrind_annotate's thousands-separated form.
    std::string total = std::to_string(stat_value(r.err, "instructions"));
    for (int i = static_cast<int>(total.size()) - 3; i > 0; i -= 3) total.insert(static_cast<size_t>(i), ",");
    CHECK(a.out.find(total) != std::string::npos);
  }
  std::remove(cg.c_str());
  std::remove(folded.c_str());
}

namespace {
// Starts `firmware-sim --pty ELF -- mode`, opens the announced slave like a
// serial terminal program (raw mode) and returns its fd; pid for waitpid,
// err_fd = the simulator's stderr after the announcement line.
int open_sim_pty(const char* mode, pid_t& pid, int& err_fd) {
  int err_pipe[2];
  REQUIRE(::pipe(err_pipe) == 0);
  pid = ::fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    ::dup2(err_pipe[1], 2);
    ::close(err_pipe[0]);
    ::execl(FWSIM_BINARY, FWSIM_BINARY, "--pty", kElf.c_str(), "--", mode, static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(err_pipe[1]);
  std::string line;
  char c;
  while (::read(err_pipe[0], &c, 1) == 1 && c != '\n') line += c;
  err_fd = err_pipe[0];
  REQUIRE(line.rfind("firmware-sim: uart on /dev/pts/", 0) == 0);
  const std::string slave = line.substr(std::string("firmware-sim: uart on ").size());
  const int fd = ::open(slave.c_str(), O_RDWR | O_NOCTTY);
  REQUIRE(fd >= 0);
  termios t{};
  REQUIRE(::tcgetattr(fd, &t) == 0);
  ::cfmakeraw(&t);
  REQUIRE(::tcsetattr(fd, TCSANOW, &t) == 0);
  return fd;
}

std::string read_n(int fd, size_t n) {
  std::string got;
  char c;
  while (got.size() < n && ::read(fd, &c, 1) == 1) got += c;
  return got;
}

int wait_status(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 1000 + WTERMSIG(status);
}
}  // namespace

TEST_CASE("pty option: the UART is a pseudo-terminal a host can talk to", "[cli][pty]") {
  pid_t pid;
  int err;
  const int fd = open_sim_pty("echo", pid, err);
  REQUIRE(::write(fd, "pty!q", 5) == 5);
  CHECK(read_n(fd, 4) == "PTY!");
  CHECK(wait_status(pid) == 0);
  ::close(fd);
  ::close(err);
}

TEST_CASE("pty option: the host closing the pty is end of input", "[cli][pty]") {
  pid_t pid;
  int err;
  const int fd = open_sim_pty("echo", pid, err);
  REQUIRE(::write(fd, "ab", 2) == 2);
  CHECK(read_n(fd, 2) == "AB");
  ::close(fd);
  // The echo firmware keeps polling after EOF: stall detected, status 6.
  CHECK(read_n(err, 200).find("UART input at end of file") != std::string::npos);
  CHECK(wait_status(pid) == 6);
  ::close(err);
}

TEST_CASE("Ctrl-C ends a run with status 130 and one line saying where it stopped", "[cli][interrupt]") {
  int err_pipe[2];
  REQUIRE(::pipe(err_pipe) == 0);
  const pid_t pid = ::fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    const int null = ::open("/dev/null", O_RDWR);
    ::dup2(null, 0);
    ::dup2(null, 1);
    ::dup2(err_pipe[1], 2);
    ::close(err_pipe[0]);
    ::execl(FWSIM_BINARY, FWSIM_BINARY, kElf.c_str(), "--", "spin", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(err_pipe[1]);
  ::sleep(1);  // well into the endless loop, the handler long installed
  ::kill(pid, SIGINT);
  const int status = wait_status(pid);
  std::string err;
  char c;
  while (::read(err_pipe[0], &c, 1) == 1) err += c;
  ::close(err_pipe[0]);
  CHECK(status == 130);
  // One line, and no progress line: standard error is a pipe here.
  CHECK(std::regex_match(
      err, std::regex("firmware-sim: interrupted at pc 0x[0-9a-f]{8} after [0-9]+ instructions \\([0-9.]+ s, [0-9]+ MIPS\\)\n")));
}
