// firmware-sim under hostile input: special files and oversized files to
// every file option, a symbol whose readable form would take gigabytes, lost
// output (a full device, a closed pipe), a program that prints without end,
// and a board file whose UART region wraps round the address space. Each
// case asserts the status, the one error line and what was (not) written;
// the runs are killed after 20 s, so a hang fails instead of blocking.
#include <elf.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

struct Run {
  int status = -1;  // exit status, or 128 + signal
  std::string out, err;
  double seconds = 0;
  long max_rss_kib = 0;
};

const std::string kSim = FWSIM_BINARY;
const std::string kElf = FWSIM_TEST_ELF;

std::string tmp(const std::string& name) {
  return std::string(std::getenv("TMPDIR") ? std::getenv("TMPDIR") : "/tmp") + "/fwsim_hostile_" +
         std::to_string(::getpid()) + "_" + name;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void spit(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

// Runs firmware-sim with `args`; standard output to `stdout_fd` when >= 0,
// else to a file that is read back.
Run sim(const std::vector<std::string>& args, int stdout_fd = -1) {
  const std::string out_path = tmp("out"), err_path = tmp("err");
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int in = ::open("/dev/null", O_RDONLY);
    const int out = stdout_fd >= 0 ? stdout_fd : ::open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(in, 0);
    ::dup2(out, 1);
    ::dup2(err, 2);
    std::vector<char*> argv{const_cast<char*>(kSim.c_str())};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  int st = 0;
  rusage ru{};
  for (;;) {
    if (::wait4(pid, &st, WNOHANG, &ru) == pid) break;
    if (std::chrono::steady_clock::now() - t0 > std::chrono::seconds(20)) ::kill(pid, SIGKILL);
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  Run r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
  r.max_rss_kib = ru.ru_maxrss;
  if (stdout_fd < 0) r.out = slurp(out_path);
  r.err = slurp(err_path);
  ::unlink(out_path.c_str());
  ::unlink(err_path.c_str());
  return r;
}

bool one_line(const std::string& s) {
  return !s.empty() && s.back() == '\n' && s.find('\n') == s.size() - 1 && s.rfind("firmware-sim: error: ", 0) == 0;
}

// A minimal RV32 executable at 0x80000000: `code` in one executable
// segment and section, and one function symbol over it named `symbol`.
std::string make_elf(const std::vector<uint32_t>& code, const std::string& symbol) {
  const uint32_t code_off = sizeof(Elf32_Ehdr) + sizeof(Elf32_Phdr);
  const uint32_t code_size = static_cast<uint32_t>(code.size() * 4);
  const std::string strtab = std::string(1, '\0') + symbol + '\0';
  const std::string shstr = std::string("\0.text\0.symtab\0.strtab\0.shstrtab\0", 33);
  Elf32_Sym syms[2]{};
  syms[1].st_name = 1;
  syms[1].st_value = 0x80000000u;
  syms[1].st_size = code_size;
  syms[1].st_info = ELF32_ST_INFO(STB_GLOBAL, STT_FUNC);
  syms[1].st_shndx = 1;
  const uint32_t sym_off = code_off + code_size;
  const uint32_t str_off = sym_off + sizeof syms;
  const uint32_t shstr_off = str_off + static_cast<uint32_t>(strtab.size());
  const uint32_t sh_off = (shstr_off + static_cast<uint32_t>(shstr.size()) + 3) & ~3u;
  Elf32_Ehdr eh{};
  std::memcpy(eh.e_ident, ELFMAG, SELFMAG);
  eh.e_ident[EI_CLASS] = ELFCLASS32;
  eh.e_ident[EI_DATA] = ELFDATA2LSB;
  eh.e_ident[EI_VERSION] = EV_CURRENT;
  eh.e_type = ET_EXEC;
  eh.e_machine = EM_RISCV;
  eh.e_version = EV_CURRENT;
  eh.e_entry = 0x80000000u;
  eh.e_phoff = sizeof(Elf32_Ehdr);
  eh.e_shoff = sh_off;
  eh.e_ehsize = sizeof(Elf32_Ehdr);
  eh.e_phentsize = sizeof(Elf32_Phdr);
  eh.e_phnum = 1;
  eh.e_shentsize = sizeof(Elf32_Shdr);
  eh.e_shnum = 5;
  eh.e_shstrndx = 4;
  Elf32_Phdr ph{};
  ph.p_type = PT_LOAD;
  ph.p_offset = code_off;
  ph.p_vaddr = ph.p_paddr = 0x80000000u;
  ph.p_filesz = ph.p_memsz = code_size;
  ph.p_flags = PF_R | PF_X;
  Elf32_Shdr sh[5]{};
  sh[1] = {1, SHT_PROGBITS, SHF_ALLOC | SHF_EXECINSTR, 0x80000000u, code_off, code_size, 0, 0, 4, 0};
  sh[2] = {7, SHT_SYMTAB, 0, 0, sym_off, sizeof syms, 3, 1, 4, sizeof(Elf32_Sym)};
  sh[3] = {15, SHT_STRTAB, 0, 0, str_off, static_cast<uint32_t>(strtab.size()), 0, 0, 1, 0};
  sh[4] = {23, SHT_STRTAB, 0, 0, shstr_off, static_cast<uint32_t>(shstr.size()), 0, 0, 1, 0};
  std::string f(reinterpret_cast<const char*>(&eh), sizeof eh);
  f.append(reinterpret_cast<const char*>(&ph), sizeof ph);
  f.append(reinterpret_cast<const char*>(code.data()), code_size);
  f.append(reinterpret_cast<const char*>(syms), sizeof syms);
  f += strtab;
  f += shstr;
  f.resize(sh_off, '\0');
  f.append(reinterpret_cast<const char*>(sh), sizeof sh);
  return f;
}

// Stores 0x5555 to the finisher at 0x100000: exit status 0.
const std::vector<uint32_t> kExitZero{0x001002b7, 0x00005337, 0x55530313, 0x0062a023, 0x0000006f};
// Writes 'x' to the UART data register at 0x10000000 without end.
const std::vector<uint32_t> kPrintForever{0x100002b7, 0x07800313, 0x00628023, 0xffdff06f};

// The readable form of f(a, a<a, a>, a<a<a, a>, a<a, a> >, ...): every
// argument names the one before it twice, so each 10 characters double it;
// this one (some 300 characters) would be gigabytes.
std::string demangler_bomb() {
  const char* digits = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ";
  std::string s = "_Z1f1aS_IS_S_E";
  for (int k = 1; k <= 28; ++k) {
    const std::string prev = std::string("S") + digits[k - 1] + "_";
    s += "S_I" + prev + prev + "E";
  }
  return s;
}

}  // namespace

TEST_CASE("every file option refuses a directory, a FIFO, a device and an oversized file at once",
          "[cli][hostile]") {
  const std::string fifo = tmp("fifo");
  ::unlink(fifo.c_str());
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  // Sparse: a size far past every bound, no disk used.
  const std::string big = tmp("big");
  {
    const int fd = ::open(big.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    REQUIRE(fd >= 0);
    REQUIRE(::ftruncate(fd, off_t{1} << 30) == 0);
    ::close(fd);
  }
  struct Kind {
    std::string path, reason;
  };
  const std::vector<Kind> kinds{{"/tmp", "Is a directory"},
                                {fifo, "not a regular file (a FIFO)"},
                                {"/dev/zero", "not a regular file (a device)"},
                                {big, "larger than"}};
  for (const char* option : {"--board", "--machine", "--cycle-model", "--fpu-model"}) {
    for (const Kind& k : kinds) {
      CAPTURE(option, k.path);
      const Run r = sim({option, k.path, kElf});
      CHECK(r.status == 2);
      CHECK(one_line(r.err));
      CHECK(r.err.find(k.reason) != std::string::npos);
      CHECK(r.out.empty());  // nothing ran
    }
  }
  // The image itself: special files are a usage error (2), a file too large
  // for the memory it loads into a bad image (3), both before reading.
  for (const bool hex : {false, true}) {
    for (const Kind& k : kinds) {
      CAPTURE(hex, k.path);
      const Run r = hex ? sim({"--load-hex", k.path}) : sim({k.path});
      CHECK(r.status == (k.path == big ? 3 : 2));
      CHECK(one_line(r.err));
      CHECK(r.err.find(k.path == big ? "larger than" : k.reason.c_str()) != std::string::npos);
      CHECK(r.seconds < 5);
      CHECK(r.max_rss_kib < 64 * 1024);
    }
  }
  // --uart-in is a stream: a FIFO is allowed (no writer: end of input at
  // once, the open does not block), a directory is not.
  const Run dir = sim({"--uart-in", "/tmp", kElf});
  CHECK(dir.status == 2);
  CHECK(dir.err == "firmware-sim: error: /tmp: Is a directory\n");
  const Run from_fifo = sim({"--uart-in", fifo, kElf});
  CHECK(from_fifo.status == 0);
  // Profiles replace only a regular file or a new name: refused before the
  // run (nothing on the UART), the special file left as it was.
  for (const char* option : {"--profile-out", "--folded-out", "--flame-out"}) {
    for (const std::string& target : {fifo, std::string("/dev/null")}) {
      CAPTURE(option, target);
      const Run r = sim({option, target, kElf});
      CHECK(r.status == 2);
      CHECK(one_line(r.err));
      CHECK(r.err.find("refusing to replace " + target) != std::string::npos);
      CHECK(r.err.find("--write-through") == std::string::npos);  // not an option of firmware-sim
      CHECK(r.out.empty());
    }
  }
  struct stat st {};
  CHECK((::stat(fifo.c_str(), &st) == 0 && S_ISFIFO(st.st_mode)));
  ::unlink(fifo.c_str());
  ::unlink(big.c_str());
}

TEST_CASE("a mangled name whose readable form would take gigabytes is shown as it is", "[cli][hostile]") {
  const std::string bomb = demangler_bomb();
  REQUIRE(bomb.size() > 280);
  REQUIRE(bomb.size() < 320);
  const std::string elf = tmp("bomb.elf"), profile = tmp("bomb.callgrind");
  spit(elf, make_elf(kExitZero, bomb));
  // --profile-out and --stats show every function's name.
  const Run r = sim({"--stats", "--profile-out", profile, elf});
  CHECK(r.status == 0);
  CHECK(r.seconds < 5);
  CHECK(r.max_rss_kib < 256 * 1024);
  CHECK(slurp(profile).find(bomb) != std::string::npos);
  // An ordinary C++ name in the same place is still demangled.
  spit(elf, make_elf(kExitZero, "_ZN5minrt6Tracer4initEv"));
  const Run plain = sim({"--profile-out", profile, elf});
  CHECK(plain.status == 0);
  CHECK(slurp(profile).find("minrt::Tracer::init()") != std::string::npos);
  ::unlink(elf.c_str());
  ::unlink(profile.c_str());
}

TEST_CASE("lost UART output or commit log ends the run with status 7 and a line", "[cli][hostile]") {
  // /dev/full: every write fails with ENOSPC, the short output included
  // (under the UART's 64 KiB buffer: the final flush).
  const Run uart = sim({"--uart-out", "/dev/full", kElf});
  CHECK(uart.status == 7);
  CHECK(one_line(uart.err));
  CHECK(uart.err.find("cannot write the UART output /dev/full: No space left on device") != std::string::npos);
  const Run log = sim({"--commit-log", "/dev/full", kElf});
  CHECK(log.status == 7);
  CHECK(one_line(log.err));
  CHECK(log.err.find("cannot write the commit log /dev/full: No space left on device") != std::string::npos);
  // A reader that went away: EPIPE, not death by SIGPIPE (141), and the run
  // stops instead of going on to the end of a long program.
  int p[2];
  REQUIRE(::pipe(p) == 0);
  ::close(p[0]);
  const std::string looping = tmp("loop.elf");
  spit(looping, make_elf(kPrintForever, "spin"));
  const Run piped = sim({"--uart-out", "/dev/null", "--commit-log", "-", "--no-limit", looping}, p[1]);
  ::close(p[1]);
  CHECK(piped.status == 7);
  CHECK(one_line(piped.err));
  CHECK(piped.err.find("cannot write the commit log (standard output): Broken pipe") != std::string::npos);
  CHECK(piped.seconds < 10);
  ::unlink(looping.c_str());
}

TEST_CASE("a program that prints without end stops at the output limit", "[cli][hostile]") {
  const std::string looping = tmp("print.elf");
  spit(looping, make_elf(kPrintForever, "spin"));
  const std::string out = tmp("uart.out");
  const Run r = sim({"--max-output", "64K", "--uart-out", out, looping});
  CHECK(r.status == 5);
  CHECK(one_line(r.err));
  CHECK(r.err.find("output limit") != std::string::npos);
  CHECK(slurp(out) == std::string(65536, 'x'));
  // The instruction limit stops it too; --no-limit lifts both (checked by
  // the closed-pipe case above, which runs until the write fails).
  const Run counted = sim({"--max-instructions", "100000", "--uart-out", "/dev/null", looping});
  CHECK(counted.status == 5);
  CHECK(counted.err.find("instruction limit exceeded") != std::string::npos);
  CHECK(sim({"--max-output", "0", looping}).status == 2);
  ::unlink(looping.c_str());
  ::unlink(out.c_str());
}

TEST_CASE("a generic UART whose registers run past the top of the address space is refused", "[cli][hostile]") {
  const std::string board = tmp("wrap.board");
  spit(board,
       "name = wrap\nisa = rv32i\nreset = 0x2000\nram_base = 0x0\nram_size = 0x10000\nuart = generic\n"
       "uart_base = 0x20000000\nuart_data = 0xffffffff\nuart_status = 0xfffffffe\nuart_tx_ready = 0x20\n"
       "uart_rx_ready = 0x01\nuart_width = 1\nhalt = loop\n");
  const Run r = sim({"--board", board, kElf});
  CHECK(r.status == 2);
  CHECK(one_line(r.err));
  CHECK(r.err.find("runs past the top of the 32-bit address space") != std::string::npos);
  ::unlink(board.c_str());
}
