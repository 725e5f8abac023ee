#include "uart.hpp"

#include <poll.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>

#include <minrt/memory_map.h>

namespace fwsim {
namespace {
constexpr uint8_t kLcrDlab = 0x80;
constexpr uint32_t kRegIer = 1, kRegLcr = 3, kRegScr = 7;
// LiteX CSR UART (32-bit CSRs) and SiFive UART register offsets.
constexpr uint32_t kLitexRxtx = 0x00, kLitexTxfull = 0x04, kLitexRxempty = 0x08;
constexpr uint32_t kSifiveTxdata = 0x00, kSifiveRxdata = 0x04, kSifiveTxctrl = 0x08, kSifiveRxctrl = 0x0c,
                   kSifiveDiv = 0x18;
constexpr uint32_t kSifiveFlag = 0x80000000u;  // txdata: full; rxdata: empty
// Empty polls answered at full speed before the host is waited for.
constexpr uint64_t kSpinPolls = 4096;
// The same for --real-board: above the firmware's MINRT_IDLE_POLLS_DEFAULT.
constexpr uint64_t kBoardSpinPolls = 4u << 20;
}  // namespace

bool Uart::fill_input() {
  if (in_pos_ < in_buf_.size()) return true;
  if (eof_) return false;
  // The firmware decides whether to wait by polling LSR. While it polls in
  // vain, ask the host only every 64th time (a syscall each), and once it
  // has waited a while, let that syscall wait up to 100 us for a byte: a
  // spinning simulator would otherwise take the CPU from the program that
  // is about to send (host-send on a loaded 2-core machine), and an idle
  // count would run out before a slow host answers. Data still wakes it at
  // once; simulated time is not affected.
  if (idle_polls_ % 64 != 0) return false;
  pollfd p{cfg_.in_fd, POLLIN, 0};
  // A real board (--real-board) spins longer first, so a firmware's own
  // idle count (an upload cut short by a host that died) runs out in
  // about the time it would on hardware, not after thousands of sleeps
  // whose length depends on the host's load.
  const uint64_t spin = cfg_.real_board ? kBoardSpinPolls : kSpinPolls;
  const timespec wait{0, idle_polls_ >= spin ? 100000 : 0};
  int r = ::ppoll(&p, 1, &wait, nullptr);
  if (r < 0 && errno == EINTR) return false;
  if (r == 0) return false;
  in_buf_.resize(4096);
  ssize_t n = ::read(cfg_.in_fd, in_buf_.data(), in_buf_.size());
  if (n < 0 && (errno == EAGAIN || errno == EINTR)) n = -2;
  // A pty master reports EIO once the host side has closed: that is EOF.
  if (n == 0 || n == -1) eof_ = true;
  in_buf_.resize(n > 0 ? static_cast<size_t>(n) : 0);
  in_pos_ = 0;
  return n > 0;
}

bool Uart::data_ready(uint64_t now) {
  if (!holding_) {
    if (!fill_input()) return false;
    holding_ = true;
    // Back-to-back bytes arrive one frame apart on the wire.
    uint64_t start = now > rx_ready_at_ ? now : rx_ready_at_;
    rx_ready_at_ = start + cfg_.cycles_per_byte;
  }
  return now >= rx_ready_at_;
}

namespace {
long long wall_ns() {
  timespec ts{};
  ::clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<long long>(ts.tv_sec) * 1000000000LL + ts.tv_nsec;
}
}  // namespace

bool Uart::poll_rx(uint64_t now) {
  if (data_ready(now)) return true;
  if (cfg_.real_board && wait_since_ns_ == 0) wait_since_ns_ = wall_ns();
  if (eof_) ++eof_polls_;
  else if (++idle_polls_ == 64) flush();  // the firmware is waiting for input: show what it printed
  return false;
}

int Uart::take_rx(uint64_t now) {
  eof_polls_ = idle_polls_ = 0;
  if (!data_ready(now)) return -1;
  if (wait_since_ns_ != 0) {
    const double waited = static_cast<double>(wall_ns() - wait_since_ns_) / 1e9;
    wait_since_ns_ = 0;
    if (waited >= 1.0) {
      std::fprintf(stderr, "firmware-sim: the board waited %.1f s for the host (%.0f cycles at %llu Hz)\n", waited,
                   waited * static_cast<double>(cfg_.clock_hz), static_cast<unsigned long long>(cfg_.clock_hz));
      std::fflush(stderr);
    }
  }
  holding_ = false;
  ++bytes_in_;
  return in_buf_[in_pos_++];
}

void Uart::send(uint8_t value, uint64_t now) {
  eof_polls_ = idle_polls_ = 0;
  if (bytes_out_ >= cfg_.max_output) {
    // A program that prints without end stops here, not on a full disk.
    output_limited_ = io_error_ = true;
    return;
  }
  out_buf_.push_back(value);
  ++bytes_out_;
  tx_free_at_ = (now > tx_free_at_ ? now : tx_free_at_) + cfg_.cycles_per_byte;
  if (out_buf_.size() >= 65536 || (cfg_.interactive && value == '\n')) flush();
}

uint8_t Uart::read_ns16550(uint32_t offset, uint64_t now) {
  const bool dlab = lcr_ & kLcrDlab;
  switch (offset) {
    case MINRT_UART_REG_DATA: {
      if (dlab) return dll_;
      const int c = take_rx(now);
      return c < 0 ? 0 : static_cast<uint8_t>(c);
    }
    case kRegIer: return dlab ? dlm_ : 0;
    case kRegLcr: return lcr_;
    case kRegScr: return scr_;
    case MINRT_UART_REG_LSR: {
      uint8_t lsr = poll_rx(now) ? MINRT_UART_LSR_DATA_READY : 0;
      if (tx_ready(now)) lsr |= MINRT_UART_LSR_THR_EMPTY | 0x40;  // THRE + TEMT
      return lsr;
    }
    default: return 0;
  }
}

void Uart::write_ns16550(uint32_t offset, uint8_t value, uint64_t now) {
  const bool dlab = lcr_ & kLcrDlab;
  switch (offset) {
    case MINRT_UART_REG_DATA:
      if (dlab) dll_ = value;
      else send(value, now);
      return;
    case kRegIer:
      if (dlab) dlm_ = value;
      return;
    case kRegLcr: lcr_ = value; return;
    case kRegScr: scr_ = value; return;
    default: return;
  }
}

uint32_t Uart::read(uint32_t offset, uint64_t now) {
  const UartLayout& l = cfg_.layout;
  switch (l.kind) {
    case UartKind::Ns16550: return read_ns16550(offset, now);
    case UartKind::Litex:
      switch (offset) {
        case kLitexRxtx: {
          const int c = take_rx(now);
          return c < 0 ? 0 : static_cast<uint32_t>(c);
        }
        case kLitexTxfull: return tx_ready(now) ? 0 : 1;
        case kLitexRxempty: return poll_rx(now) ? 0 : 1;
        default: return 0;
      }
    case UartKind::Sifive:
      switch (offset) {
        case kSifiveTxdata: return tx_ready(now) ? 0 : kSifiveFlag;
        case kSifiveRxdata: {
          if (!poll_rx(now)) return kSifiveFlag;
          return static_cast<uint32_t>(take_rx(now));
        }
        case kSifiveTxctrl: return sifive_txctrl_;
        case kSifiveRxctrl: return sifive_rxctrl_;
        case kSifiveDiv: return sifive_div_;
        default: return 0;
      }
    case UartKind::Generic: {
      const uint32_t idle = l.tx_idle ? l.tx_idle : l.tx_ready;
      const uint32_t written = offset < sizeof generic_regs_ ? generic_regs_[offset / 4] : 0;
      if (!generic_enabled()) {
        // Off: a byte that arrives is lost (the receiver is held empty),
        // the transmitter reads empty and drops what is written.
        if (offset == l.status) {
          if (data_ready(now)) {
            holding_ = false;
            ++in_pos_;
            ++dropped_;
          } else if (eof_) {
            ++eof_polls_;
          }
          return (written & ~(l.tx_ready | l.rx_ready | idle)) | l.tx_ready | idle;
        }
        return offset == l.data ? 0 : written;
      }
      if (offset == l.status) {
        const bool free = tx_ready(now);
        return (written & ~(l.tx_ready | l.rx_ready | idle)) | (free ? l.tx_ready | idle : 0) |
               (poll_rx(now) ? l.rx_ready : 0);
      }
      if (offset == l.data) {
        const int c = take_rx(now);
        return c < 0 ? 0 : static_cast<uint32_t>(c);
      }
      return written;
    }
  }
  return 0;
}

void Uart::write(uint32_t offset, uint32_t value, uint64_t now) {
  const UartLayout& l = cfg_.layout;
  switch (l.kind) {
    case UartKind::Ns16550: write_ns16550(offset, static_cast<uint8_t>(value), now); return;
    case UartKind::Litex:
      if (offset == kLitexRxtx) send(static_cast<uint8_t>(value), now);
      return;
    case UartKind::Sifive:
      switch (offset) {
        case kSifiveTxdata: send(static_cast<uint8_t>(value), now); return;
        case kSifiveTxctrl: sifive_txctrl_ = value; return;
        case kSifiveRxctrl: sifive_rxctrl_ = value; return;
        case kSifiveDiv: sifive_div_ = value; return;
        default: return;
      }
    case UartKind::Generic:
      if (offset != l.data) {
        if (offset < sizeof generic_regs_) generic_regs_[offset / 4] = value;
      } else if (generic_enabled()) {
        send(static_cast<uint8_t>(value), now);
      } else {
        ++dropped_;
      }
      return;
  }
}

bool Uart::generic_enabled() const {
  const UartLayout& l = cfg_.layout;
  if (!l.enable_mask) return true;
  const uint32_t v = l.enable_offset < sizeof generic_regs_ ? generic_regs_[l.enable_offset / 4] : 0;
  return (v & l.enable_mask) == l.enable_mask;
}

void Uart::flush() {
  size_t done = 0;
  while (done < out_buf_.size()) {
    ssize_t n = ::write(cfg_.out_fd, out_buf_.data() + done, out_buf_.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && errno == EAGAIN && cfg_.real_board) {
      // A host that reads takes the bytes within a moment; none does.
      pollfd p{cfg_.out_fd, POLLOUT, 0};
      if (::poll(&p, 1, 200) > 0) continue;
      unread_ += out_buf_.size() - done;
      break;
    }
    if (n <= 0) {
      io_error_ = true;
      if (write_errno_ == 0) write_errno_ = n < 0 ? errno : EIO;
      break;
    }
    done += static_cast<size_t>(n);
  }
  out_buf_.clear();
}

}  // namespace fwsim
