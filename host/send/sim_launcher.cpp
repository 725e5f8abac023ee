#include "sim_launcher.hpp"

#include "posix/interrupt.hpp"
#include "terminal_text.hpp"

#include <fcntl.h>
#include <sys/prctl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>

#ifndef MINRT_FIRMWARE_SIM_DEFAULT
#define MINRT_FIRMWARE_SIM_DEFAULT "firmware-sim"
#endif
#ifndef MINRT_FIRMWARE_ELF_DEFAULT
#define MINRT_FIRMWARE_ELF_DEFAULT "minrt-rv32imf.elf"
#endif

namespace minrt::send {

namespace {
const char kPtyPrefix[] = "uart on ";
// What is kept of the simulator's own output (its messages, shown when it
// fails): a simulator that floods its standard error cannot fill the memory.
constexpr std::size_t kMaxKeptOutput = std::size_t{1} << 20;
// A start-up line longer than this is not the pty line: kept as output.
constexpr std::size_t kMaxLine = 4096;
constexpr std::size_t kMaxShownLine = 512;  // of a line shown to the user

void append_capped(std::string& to, const char* bytes, std::size_t n) {
  if (to.size() < kMaxKeptOutput) to.append(bytes, std::min(n, kMaxKeptOutput - to.size()));
}
long long now_ms() {
  using namespace std::chrono;
  return duration_cast<milliseconds>(steady_clock::now().time_since_epoch()).count();
}

// The folder host-send runs from: in an installed tree (cmake --install)
// firmware-sim sits beside it and the firmware in ../share/minrt/firmware.
std::string own_folder() {
  char buf[4096];
  const ssize_t n = ::readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (n <= 0) return "";
  const std::string self(buf, static_cast<std::size_t>(n));
  const std::size_t slash = self.rfind('/');
  return slash == std::string::npos ? "" : self.substr(0, slash);
}

// The environment's choice, else the installed file when it exists, else the
// build tree's.
std::string pick(const char* env_name, const std::string& installed, const char* built) {
  const char* env = std::getenv(env_name);
  if (env != nullptr && *env != 0) return env;
  if (!installed.empty() && ::access(installed.c_str(), F_OK) == 0) return installed;
  return built;
}
}  // namespace

std::string default_simulator() {
  const std::string dir = own_folder();
  return pick("MINRT_FIRMWARE_SIM", dir.empty() ? "" : dir + "/firmware-sim", MINRT_FIRMWARE_SIM_DEFAULT);
}

std::string default_firmware() {
  const std::string dir = own_folder();
  return pick("MINRT_FIRMWARE_ELF", dir.empty() ? "" : dir + "/../share/minrt/firmware/minrt-rv32imf.elf",
              MINRT_FIRMWARE_ELF_DEFAULT);
}

bool parse_pty_line(const std::string& line, std::string& path) {
  const std::size_t at = line.find(kPtyPrefix);
  if (at == std::string::npos) return false;
  std::string p = line.substr(at + sizeof kPtyPrefix - 1);
  while (!p.empty() && (p.back() == '\n' || p.back() == '\r' || p.back() == ' ')) p.pop_back();
  if (p.empty() || p[0] != '/') return false;
  path = p;
  return true;
}

SimLauncher::~SimLauncher() { stop(0); }

bool SimLauncher::start(const SimConfig& config, std::string& error) {
  if (!config.exact_args.empty()) return spawn(config.exact_args, config.startup_timeout_ms, error);
  if (::access(config.simulator.c_str(), X_OK) != 0) {
    error = "simulator " + config.simulator + " not found or not executable (set MINRT_FIRMWARE_SIM or --sim-binary)";
    return false;
  }
  if (::access(config.firmware.c_str(), R_OK) != 0) {
    error = "firmware " + config.firmware + " not found (build it, or give --sim ELF / MINRT_FIRMWARE_ELF)";
    return false;
  }
  std::vector<std::string> args{config.simulator, "--pty"};
  if (config.baud != 0) {
    args.push_back("--baud");
    args.push_back(std::to_string(config.baud));
  }
  if (!config.ram_size.empty()) {
    args.push_back("--ram-size");
    args.push_back(config.ram_size);
  }
  if (!config.board.empty()) {
    args.push_back("--board");
    args.push_back(config.board);
  }
  args.push_back(config.firmware);
  if (!config.firmware_args.empty()) {
    args.push_back("--");
    for (const auto& a : config.firmware_args) args.push_back(a);
  }
  return spawn(args, config.startup_timeout_ms, error);
}

bool SimLauncher::spawn(std::vector<std::string> args, int startup_timeout_ms, std::string& error) {
  if (::access(args[0].c_str(), X_OK) != 0) {
    error = args[0] + " not found or not executable";
    return false;
  }
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  int pipefd[2];
  if (::pipe2(pipefd, O_CLOEXEC) != 0) {
    error = std::string("pipe: ") + std::strerror(errno);
    return false;
  }
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    error = std::string("fork: ") + std::strerror(errno);
    ::close(pipefd[0]);
    ::close(pipefd[1]);
    return false;
  }
  if (pid == 0) {
    // The simulator must not outlive host-send, even a SIGKILLed one: the
    // kernel signals it when its parent dies, and the check after prctl
    // covers a parent that died before it. Its own process group keeps a
    // terminal's Ctrl-C for host-send, which stops it in order.
    ::setpgid(0, 0);
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(127);
    ::dup2(pipefd[1], 2);
    ::dup2(pipefd[1], 1);
    const int devnull = ::open("/dev/null", O_RDONLY);
    if (devnull >= 0) ::dup2(devnull, 0);
    ::execv(argv[0], argv.data());
    const char msg[] = "host-send: error: cannot run the simulator\n";
    (void)!::write(2, msg, sizeof msg - 1);
    ::_exit(127);
  }
  ::close(pipefd[1]);
  pid_ = pid;
  // A signal that ends host-send stops it too (posix/interrupt.hpp).
  minrt::host::stop_on_signal(pid);
  err_fd_ = pipefd[0];

  // Read its output line by line until the pty line shows up.
  std::string pending;
  const long long deadline = now_ms() + startup_timeout_ms;
  for (;;) {
    std::size_t nl;
    while ((nl = pending.find('\n')) != std::string::npos) {
      const std::string line = pending.substr(0, nl);
      pending.erase(0, nl + 1);
      if (parse_pty_line(line, pty_)) {
        output_ = pending;
        drainer_ = std::thread([this] { drain(); });
        return true;
      }
      append_capped(output_, line.data(), line.size());
      append_capped(output_, "\n", 1);
    }
    if (pending.size() > kMaxLine) {
      append_capped(output_, pending.data(), pending.size());
      pending.clear();
    }
    const long long left = deadline - now_ms();
    if (left <= 0) {
      error = "simulator did not announce its pty within " + std::to_string(startup_timeout_ms / 1000) + " s";
      break;
    }
    // Read only what poll says is there: a simulator that prints nothing
    // must not hold host-send past the deadline in a blocking read.
    pollfd p{err_fd_, POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left, 1000)));
    if (ready <= 0) continue;  // timed out (the deadline is checked above) or EINTR
    char buf[4096];
    const ssize_t n = ::read(err_fd_, buf, sizeof buf);
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (n > 0) {
      pending.append(buf, static_cast<std::size_t>(n));
    } else {
      append_capped(output_, pending.data(), pending.size());
      std::string last = output_;
      while (!last.empty() && last.back() == '\n') last.pop_back();
      if (last.rfind('\n') != std::string::npos) last = last.substr(last.rfind('\n') + 1);
      if (last.size() > kMaxShownLine) last = last.substr(0, kMaxShownLine) + "...";
      error = "simulator exited before opening its pty" + (last.empty() ? std::string() : ": " + terminal_safe(last));
      break;
    }
  }
  stop(1000);
  return false;
}

void SimLauncher::drain() {
  char buf[4096];
  for (;;) {
    const ssize_t n = ::read(err_fd_, buf, sizeof buf);
    if (n > 0) {
      std::lock_guard<std::mutex> lock(mu_);
      append_capped(output_, buf, static_cast<std::size_t>(n));
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    return;
  }
}

std::string SimLauncher::output() {
  std::lock_guard<std::mutex> lock(mu_);
  // Lines kept, every other byte escaped and long lines cut: it goes to
  // the user's terminal.
  std::string shown;
  std::size_t from = 0;
  while (from < output_.size()) {
    const std::size_t nl = std::min(output_.find('\n', from), output_.size());
    shown += terminal_safe(output_.substr(from, std::min(nl - from, kMaxShownLine)));
    if (nl - from > kMaxShownLine) shown += "...";
    if (nl < output_.size()) shown += '\n';
    from = nl + 1;
  }
  return shown;
}

int SimLauncher::stop(int timeout_ms) {
  if (pid_ > 0) {
    const long long deadline = now_ms() + timeout_ms;
    int st = 0;
    pid_t r = 0;
    for (;;) {
      r = ::waitpid(pid_, &st, WNOHANG);
      if (r != 0 || now_ms() >= deadline) break;
      ::usleep(10000);
    }
    if (r == 0) {
      ::kill(pid_, SIGTERM);
      for (int i = 0; i < 100 && (r = ::waitpid(pid_, &st, WNOHANG)) == 0; ++i) ::usleep(10000);
      if (r == 0) {
        ::kill(pid_, SIGKILL);
        ::waitpid(pid_, &st, 0);
      }
      status_ = -1;
    } else if (r > 0) {
      status_ = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    }
    minrt::host::forget_child(pid_);
    pid_ = -1;
  }
  if (drainer_.joinable()) drainer_.join();
  if (err_fd_ >= 0) {
    ::close(err_fd_);
    err_fd_ = -1;
  }
  return status_;
}

}  // namespace minrt::send
