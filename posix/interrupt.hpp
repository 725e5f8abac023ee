// How a host tool ends on Ctrl-C and the other signals that end a process:
// it removes the temporary file it is writing, stops the child it started,
// and then dies of the same signal, so that the shell reports 128+N (130
// for Ctrl-C) and a script's loop stops too (a tool that caught SIGINT and
// exited 1 would look like an ordinary failure).
//
// A tool with state to put back first (host-send: the serial port's
// settings, the simulator's orderly stop) holds interrupts around that
// work: the signals sent from outside (SIGINT, SIGTERM, SIGHUP, SIGQUIT,
// SIGUSR1, SIGUSR2, SIGALRM, SIGVTALRM, SIGPROF, SIGXCPU) then only set a
// flag that its loops poll (interrupted()); they unwind and call
// die_of_interrupt(). A signal that arrives while nothing is held ends the
// process at once, and so does a fault (SIGSEGV, SIGABRT, ...) even while
// held; either way the handler first puts back the terminal settings
// registered with restore_on_signal().
//
// Everything here is async-signal-safe on the handler's side: fixed
// buffers, unlink and kill only.
#pragma once

#include <sys/types.h>

#include <cstddef>

namespace minrt::host {

// Installs the handler on every catchable signal whose default action ends
// the process and that still has that default (a tool's own handler is
// left be); SIGPIPE only if it is not ignored. Idempotent; the functions
// below call it too.
void install_signal_cleanup();

// The one temporary file a signal removes (posix/output_file.cpp), or none.
void remove_on_signal(const char* path);
void forget_removal();

// A terminal's settings put back by the handler before the process ends of
// a signal: ioctl(fd, request, copy of arg) (host-send's port: TCSETS2 and
// the termios2 found at open). One at a time; arg at most kMaxRestoreBytes.
inline constexpr std::size_t kMaxRestoreBytes = 64;
void restore_on_signal(int fd, unsigned long request, const void* arg, std::size_t size);
void forget_restore();

// A child process a signal stops with SIGTERM on the way out (its own
// parent-death signal covers SIGKILL). Up to kMaxChildren at once.
inline constexpr int kMaxChildren = 8;
void stop_on_signal(pid_t child);
void forget_child(pid_t child);

// While at least one hold is in place, the interrupts above only
// set the flag; releasing the last hold with the flag set dies of the
// signal, like a blocked signal delivered when unblocked.
void hold_interrupts();
void release_interrupts();
class InterruptsHeld {
 public:
  InterruptsHeld() { hold_interrupts(); }
  ~InterruptsHeld() { release_interrupts(); }
  InterruptsHeld(const InterruptsHeld&) = delete;
  InterruptsHeld& operator=(const InterruptsHeld&) = delete;
};

// Whether one of the interrupts has arrived (while held).
bool interrupted();

// Removes the file, stops the children and dies of the signal that
// arrived (SIGINT if none did).
[[noreturn]] void die_of_interrupt();

}  // namespace minrt::host
