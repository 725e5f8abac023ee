// Where RAM and the devices sit in the simulated address space. The default
// is the board's map from include/minrt/memory_map.h (QEMU virt's layout);
// --ram, --uart, --finisher and --machine FILE change it, like spike's -m
// or QEMU's machines, so programs linked elsewhere (even at 0) run.
#pragma once
#include <cstdint>
#include <string>

#include <minrt/memory_map.h>

namespace fwsim {

// The UART's register interface (board files, docs/firmware_sim.md).
enum class UartKind : uint8_t { Ns16550, Litex, Sifive, Generic };
struct UartLayout {
  UartKind kind = UartKind::Ns16550;
  // Generic kind only: register offsets, status masks, register width.
  uint32_t data = 0, status = 0, tx_ready = 0, rx_ready = 0;
  uint32_t width = 4;
  uint32_t tx_idle = 0;  // "everything sent has left" (0: tx_ready's bits)
  // The UART is off, dropping what is sent and what arrives, until the
  // register at enable_offset has all enable_mask bits set (mask 0: always on).
  uint32_t enable_offset = 0, enable_mask = 0;
};
// Bytes of address space the UART kind decodes.
uint32_t uart_region_size(const UartLayout& u);

// How the firmware stops the machine: the SiFive test finisher at
// finisher_base, ecall with a7 = 93 (status in a0), a status word stored to
// finisher_base, or a jump to itself (status in a0).
enum class HaltKind : uint8_t { Finisher, Ecall, Store, Loop };
inline constexpr uint32_t kEcallExit = 93;  // a7 value of the exit call
inline constexpr uint32_t kStoreHaltSize = 4;

struct MemoryMap {
  uint32_t ram_base = MINRT_RAM_BASE;
  uint32_t ram_size = MINRT_RAM_DEFAULT_SIZE;
  // Separate read-only instruction memory; size 0 = code runs from RAM.
  uint32_t rom_base = 0, rom_size = 0;
  uint32_t uart_base = MINRT_UART_BASE;
  uint32_t finisher_base = MINRT_FINISHER_BASE;  // halt device address
  UartLayout uart;
  HaltKind halt = HaltKind::Finisher;
};

// The default map with RAM of `ram_size` bytes at the default base.
inline MemoryMap map_with_ram(uint32_t ram_size) {
  MemoryMap m;
  m.ram_size = ram_size;
  return m;
}

// Region sizes are the devices' own (memory_map.h), not configurable.
inline constexpr uint32_t kUartSize = MINRT_UART_SIZE;
inline constexpr uint32_t kFinisherSize = MINRT_FINISHER_SIZE;
// RAM base and size granularity: keeps the boot block and sp 16-aligned.
inline constexpr uint32_t kRamAlign = 4096;

// "BASE:SIZE" (SIZE with K/M/G suffix) for --ram. Throws std::runtime_error.
void parse_ram_spec(const std::string& spec, MemoryMap& map);
// A 32-bit address (decimal or 0x hex). Throws std::runtime_error naming `what`.
uint32_t parse_address(const std::string& text, const std::string& what);
// Machine file: `key = value` lines (ram = BASE:SIZE, ram_base, ram_size,
// uart, finisher); '#' comments. Errors as "FILE:LINE: reason".
void parse_machine_file(const std::string& text, const std::string& origin, MemoryMap& map);
// Alignment, RAM within 32 bits, no two regions overlapping. Throws.
void check_memory_map(const MemoryMap& map);
// One line per region, for --stats and error messages.
std::string describe(const MemoryMap& map);

}  // namespace fwsim
