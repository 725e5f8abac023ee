#include "posix/interrupt.hpp"

#include <pthread.h>
#include <signal.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <atomic>
#include <cstring>

namespace minrt::host {

namespace {

// What the handler reads: plain fixed storage, written outside it.
char g_path[4096];
volatile sig_atomic_t g_have_path = 0;
volatile sig_atomic_t g_children[kMaxChildren] = {};
volatile sig_atomic_t g_signal = 0;  // the interrupt that arrived while held, 0: none
// The terminal settings put back on the way out (host-send's port).
volatile sig_atomic_t g_restore_fd = -1;
unsigned long g_restore_request = 0;
unsigned char g_restore_arg[kMaxRestoreBytes];
std::atomic<int> g_holds{0};

// Every signal whose default action ends the process and that a handler
// can catch (SIGKILL and SIGSTOP cannot be).
constexpr int kFatalSignals[] = {SIGINT,  SIGTERM, SIGHUP,    SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM,
                                 SIGPIPE, SIGXCPU, SIGXFSZ,   SIGVTALRM, SIGPROF, SIGABRT, SIGSEGV,
                                 SIGBUS,  SIGILL,  SIGFPE,    SIGSYS,  SIGTRAP};

// The signals sent from outside (a key, kill, a timer): held like Ctrl-C.
// The others (SIGSEGV, SIGABRT, ...) come from the program's own fault and
// cannot wait; the handler still puts the port's settings back.
constexpr int kInterrupts[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM, SIGVTALRM, SIGPROF, SIGXCPU};

bool is_interrupt(int sig) {
  for (int i : kInterrupts)
    if (sig == i) return true;
  return false;
}

void clean_up() {
  if (g_restore_fd >= 0) ::ioctl(g_restore_fd, g_restore_request, g_restore_arg);
  if (g_have_path) ::unlink(g_path);
  for (volatile sig_atomic_t& c : g_children)
    if (c > 0) ::kill(static_cast<pid_t>(c), SIGTERM);
}

// The default action again, then the signal: the process ends of it (the
// signal is blocked inside the handler and delivered when it returns).
void die_of(int sig) {
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  sigemptyset(&dfl.sa_mask);
  ::sigaction(sig, &dfl, nullptr);
  ::raise(sig);
}

void on_signal(int sig) {
  if (is_interrupt(sig) && g_holds.load(std::memory_order_relaxed) > 0) {
    g_signal = sig;
    return;
  }
  clean_up();
  die_of(sig);
}

}  // namespace

void install_signal_cleanup() {
  static std::atomic<bool> installed{false};
  if (installed.exchange(true)) return;
  for (int sig : kFatalSignals) {
    struct sigaction old {};
    ::sigaction(sig, nullptr, &old);
    if ((old.sa_flags & SA_SIGINFO) != 0 || old.sa_handler != SIG_DFL) continue;
    struct sigaction sa {};
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    // Each interrupt blocks the others while the handler runs: two of them
    // cannot clean up at once.
    for (int i : kInterrupts) sigaddset(&sa.sa_mask, i);
    ::sigaction(sig, &sa, nullptr);
  }
}

void remove_on_signal(const char* path) {
  install_signal_cleanup();
  const std::size_t n = std::strlen(path);
  if (n >= sizeof g_path) return;  // longer than any path the system takes
  g_have_path = 0;
  std::memcpy(g_path, path, n + 1);
  g_have_path = 1;
}

void forget_removal() { g_have_path = 0; }

void restore_on_signal(int fd, unsigned long request, const void* arg, std::size_t size) {
  install_signal_cleanup();
  if (size > sizeof g_restore_arg) return;
  g_restore_fd = -1;
  g_restore_request = request;
  std::memcpy(g_restore_arg, arg, size);
  g_restore_fd = fd;
}

void forget_restore() { g_restore_fd = -1; }

void stop_on_signal(pid_t child) {
  install_signal_cleanup();
  for (volatile sig_atomic_t& c : g_children)
    if (c <= 0) {
      c = static_cast<sig_atomic_t>(child);
      return;
    }
}

void forget_child(pid_t child) {
  for (volatile sig_atomic_t& c : g_children)
    if (c == static_cast<sig_atomic_t>(child)) c = 0;
}

void hold_interrupts() {
  install_signal_cleanup();
  g_holds.fetch_add(1);
}

void release_interrupts() {
  if (g_holds.fetch_sub(1) == 1 && g_signal != 0) die_of_interrupt();
}

bool interrupted() { return g_signal != 0; }

void die_of_interrupt() {
  const int sig = g_signal != 0 ? g_signal : SIGINT;
  g_holds.store(0);
  clean_up();
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, sig);
  ::pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
  die_of(sig);
  ::_exit(128 + sig);  // not reached: the signal ends the process
}

}  // namespace minrt::host
