// A serial port opened for exclusive use: O_NOCTTY, flock(LOCK_EX|LOCK_NB)
// plus TIOCEXCL, raw 8N1 at any rate through termios2/BOTHER, chosen flow
// control. The settings found at open are put back when the port closes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace minrt::send {

enum class Flow { kNone, kRtsCts, kXonXoff };

struct PortSettings {
  std::uint32_t baud = 115200;
  Flow flow = Flow::kNone;
};

// Thrown by SerialPort::open with a one-line message.
struct PortError {
  std::string message;
};

// "pid 1234 (picocom)" for every other process with `device` open, or "".
std::string describe_holders(const std::string& device);

class SerialPort {
 public:
  SerialPort() = default;
  ~SerialPort();
  SerialPort(const SerialPort&) = delete;
  SerialPort& operator=(const SerialPort&) = delete;

  // Opens and configures; throws PortError.
  void open(const std::string& device, const PortSettings& settings);
  // Restores the original settings, releases the lock and closes.
  void close();

  bool is_open() const { return fd_ >= 0; }
  int fd() const { return fd_; }
  const std::string& device() const { return device_; }
  // The rate the driver reports after configuration.
  std::uint32_t applied_baud() const { return applied_baud_; }
  // Empty, or a warning when the applied rate is off by more than 2%.
  const std::string& baud_warning() const { return baud_warning_; }

  // Writes everything; false on error or when `deadline_ms` (from now)
  // passes first (-1: no limit), or with EINTR once an interrupt is noted
  // (posix/interrupt.hpp: the caller holds interrupts while the port is open).
  bool write_all(const void* data, std::size_t size, int deadline_ms = -1);
  // Waits up to timeout_ms (-1: forever) for bytes. Returns the count read,
  // 0 on timeout, -1 on error/hang-up (errno kept) or interrupt (EINTR).
  long read_some(void* data, std::size_t size, int timeout_ms);
  // Waits until the output has been transmitted.
  void drain();
  // Discards pending input.
  void flush_input();

 private:
  int fd_ = -1;
  std::string device_;
  bool saved_valid_ = false;
  unsigned char saved_[64] = {};  // struct termios2 as found at open
  std::uint32_t applied_baud_ = 0;
  std::string baud_warning_;
};

}  // namespace minrt::send
