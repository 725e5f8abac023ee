// The physical address space: RAM (fast path, inlined into the interpreter),
// the optional ROM (instruction memory, read-only to the firmware) and the
// memory-mapped devices (slow path). The interpreter only calls into this
// file when an access misses the RAM window or is misaligned. Code runs from
// the "code memory": the ROM when the board has one, RAM otherwise.
#pragma once
#include <cstdint>
#include <cstring>
#include <cstdlib>

#include <minrt/memory_map.h>

#include "finisher.hpp"
#include "memory_map.hpp"
#include "uart.hpp"

namespace fwsim {

// The default RAM base (the board's); a run may move RAM (memory_map.hpp).
inline constexpr uint32_t kRamBase = MINRT_RAM_BASE;

class Bus {
 public:
  enum class Result : uint8_t { Ok, Fault, Misaligned, Stop };

  explicit Bus(const MemoryMap& map);
  explicit Bus(uint32_t ram_size) : Bus(map_with_ram(ram_size)) {}
  ~Bus() {
    std::free(ram_);
    std::free(rom_);
  }
  Bus(const Bus&) = delete;
  Bus& operator=(const Bus&) = delete;

  uint8_t* ram() { return ram_; }
  const uint8_t* ram() const { return ram_; }
  uint32_t ram_size() const { return ram_size_; }
  uint32_t ram_base() const { return map_.ram_base; }
  const MemoryMap& map() const { return map_; }
  // Unsigned wrap-around makes addresses below the base fail too.
  bool in_ram(uint32_t addr, uint32_t len) const {
    return addr - map_.ram_base <= ram_size_ - len && len <= ram_size_;
  }
  // Host pointer to RAM at a simulated address the caller checked with in_ram.
  uint8_t* ram_at(uint32_t addr) { return ram_ + (addr - map_.ram_base); }

  // Where instructions are fetched from (ROM, or RAM without one).
  uint8_t* code() { return rom_ ? rom_ : ram_; }
  uint32_t code_base() const { return rom_ ? map_.rom_base : map_.ram_base; }
  uint32_t code_size() const { return rom_ ? map_.rom_size : ram_size_; }
  bool in_code(uint32_t addr, uint32_t len) const {
    return addr - code_base() <= code_size() - len && len <= code_size();
  }
  uint8_t* code_at(uint32_t addr) { return code() + (addr - code_base()); }
  // Host pointer to `len` bytes of RAM or ROM at `addr`, or null: for the
  // loader and the debugger, which may write the ROM.
  uint8_t* host_at(uint32_t addr, uint32_t len) {
    if (in_ram(addr, len)) return ram_at(addr);
    if (rom_ && addr - map_.rom_base <= map_.rom_size - len && len <= map_.rom_size) return rom_ + (addr - map_.rom_base);
    return nullptr;
  }

  void attach_uart(Uart* uart) { uart_ = uart; }
  Uart* uart() const { return uart_; }
  const Finisher& finisher() const { return finisher_; }

  // Full accesses (RAM and devices); `now` is the simulated cycle count.
  Result load(uint32_t addr, unsigned size, uint32_t& value, uint64_t now);
  Result store(uint32_t addr, unsigned size, uint32_t value, uint64_t now);

  // Reason a device wants the machine stopped (finisher, UART stall).
  bool finished() const { return finished_; }
  // Exit status the halt device was given.
  int exit_code() const { return halt_code_; }

 private:
  MemoryMap map_;
  uint8_t* ram_;  // calloc: pages the firmware never touches cost nothing
  uint32_t ram_size_;
  uint8_t* rom_ = nullptr;
  uint32_t uart_size_;
  Uart* uart_ = nullptr;
  Finisher finisher_;
  bool finished_ = false;
  int halt_code_ = 0;
};

}  // namespace fwsim
