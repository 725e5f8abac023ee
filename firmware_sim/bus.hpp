// The physical address space: RAM (fast path, inlined into the interpreter)
// and the memory-mapped devices (slow path). The interpreter only calls into
// this file when an access misses the RAM window or is misaligned.
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
  explicit Bus(uint32_t ram_size) : Bus(MemoryMap{kRamBase, ram_size}) {}
  ~Bus() { std::free(ram_); }
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

  void attach_uart(Uart* uart) { uart_ = uart; }
  Uart* uart() const { return uart_; }
  const Finisher& finisher() const { return finisher_; }

  // Full accesses (RAM and devices); `now` is the simulated cycle count.
  Result load(uint32_t addr, unsigned size, uint32_t& value, uint64_t now);
  Result store(uint32_t addr, unsigned size, uint32_t value, uint64_t now);

  // Reason a device wants the machine stopped (finisher, UART stall).
  bool finished() const { return finished_; }

 private:
  MemoryMap map_;
  uint8_t* ram_;  // calloc: pages the firmware never touches cost nothing
  uint32_t ram_size_;
  Uart* uart_ = nullptr;
  Finisher finisher_;
  bool finished_ = false;
};

}  // namespace fwsim
