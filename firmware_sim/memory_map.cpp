#include "memory_map.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace fwsim {
namespace {

[[noreturn]] void fail(const std::string& why) { throw std::runtime_error(why); }

uint64_t parse_number(const std::string& text, const std::string& what, bool allow_suffix) {
  const std::string t = text;
  if (t.empty() || t[0] == '-' || t[0] == '+' || t[0] == ' ')
    fail(what + " needs a number, got '" + text + "'");
  char* end = nullptr;
  errno = 0;
  const unsigned long long n = std::strtoull(t.c_str(), &end, 0);
  uint64_t mult = 1;
  if (allow_suffix && *end && !end[1]) {
    switch (*end) {
      case 'K': case 'k': mult = 1ull << 10; ++end; break;
      case 'M': case 'm': mult = 1ull << 20; ++end; break;
      case 'G': case 'g': mult = 1ull << 30; ++end; break;
      default: break;
    }
  }
  if (errno || end == t.c_str() || *end || n > (uint64_t{1} << 32) / mult)
    fail(what + " needs a number, got '" + text + "'");
  return n * mult;
}

std::string hex(uint64_t v) {
  char buf[24];
  std::snprintf(buf, sizeof buf, "0x%08llx", static_cast<unsigned long long>(v));
  return buf;
}

std::string trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

}  // namespace

uint32_t parse_address(const std::string& text, const std::string& what) {
  const uint64_t v = parse_number(text, what, false);
  if (v > UINT32_MAX) fail(what + " must fit in 32 bits, got '" + text + "'");
  return static_cast<uint32_t>(v);
}

void parse_ram_spec(const std::string& spec, MemoryMap& map) {
  const size_t colon = spec.find(':');
  if (colon == std::string::npos) fail("--ram needs BASE:SIZE (e.g. 0:4M), got '" + spec + "'");
  map.ram_base = parse_address(spec.substr(0, colon), "RAM base");
  const uint64_t size = parse_number(spec.substr(colon + 1), "RAM size", true);
  if (size == 0 || size > UINT32_MAX) fail("RAM size must be between 64K and 4095M, got '" + spec.substr(colon + 1) + "'");
  map.ram_size = static_cast<uint32_t>(size);
}

void parse_machine_file(const std::string& text, const std::string& origin, MemoryMap& map) {
  std::istringstream in(text);
  std::string line;
  for (unsigned lineno = 1; std::getline(in, line); ++lineno) {
    const std::string where = origin + ":" + std::to_string(lineno) + ": ";
    if (const size_t hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    line = trim(line);
    if (line.empty()) continue;
    const size_t eq = line.find('=');
    if (eq == std::string::npos) fail(where + "expected 'key = value', got '" + line + "'");
    const std::string key = trim(line.substr(0, eq)), value = trim(line.substr(eq + 1));
    try {
      if (key == "ram") parse_ram_spec(value, map);
      else if (key == "ram_base") map.ram_base = parse_address(value, key);
      else if (key == "ram_size") {
        const uint64_t size = parse_number(value, key, true);
        if (size == 0 || size > UINT32_MAX) fail("ram_size out of range: '" + value + "'");
        map.ram_size = static_cast<uint32_t>(size);
      } else if (key == "uart") map.uart_base = parse_address(value, key);
      else if (key == "finisher") map.finisher_base = parse_address(value, key);
      else fail("unknown key '" + key + "' (known: ram, ram_base, ram_size, uart, finisher)");
    } catch (const std::runtime_error& e) {
      fail(where + e.what());
    }
  }
}

uint32_t uart_region_size(const UartLayout& u) {
  switch (u.kind) {
    case UartKind::Ns16550: return kUartSize;
    case UartKind::Litex: return 0x100;   // rxtx .. ev_enable, 32-bit CSRs
    case UartKind::Sifive: return 0x1000;
    case UartKind::Generic: return (u.data > u.status ? u.data : u.status) + u.width;
  }
  return kUartSize;
}

void check_memory_map(const MemoryMap& m) {
  if (m.ram_base % kRamAlign || m.ram_size % kRamAlign)
    fail("RAM base and size must be multiples of 4096 (RAM " + hex(m.ram_base) + ", size " + hex(m.ram_size) + ")");
  if (m.ram_size < 65536) fail("RAM size must be at least 64K, got " + std::to_string(m.ram_size));
  if (m.ram_size > 0x7ffff000u) fail("RAM size must be at most 2047M, got " + std::to_string(m.ram_size));
  // RAM must end below 4 GiB: a2 and the boot block hold its end address.
  if (uint64_t{m.ram_base} + m.ram_size >= (uint64_t{1} << 32))
    fail("RAM " + hex(m.ram_base) + "+" + hex(m.ram_size) + " must end below the top of the 32-bit address space");
  // A generic UART's offsets are the board file's: reckoned in 64 bits, so
  // uart_data = 0xffffffff cannot wrap the region round to a few bytes.
  if (m.uart.kind == UartKind::Generic) {
    const uint64_t span = uint64_t{m.uart.data > m.uart.status ? m.uart.data : m.uart.status} + m.uart.width;
    if (uint64_t{m.uart_base} + span > (uint64_t{1} << 32))
      fail("UART " + hex(m.uart_base) + " with registers at +" + hex(m.uart.data) + " and +" + hex(m.uart.status) +
           " runs past the top of the 32-bit address space");
  }
  const uint32_t uart_size = uart_region_size(m.uart);
  if (m.uart_base % 4 || uint64_t{m.uart_base} + uart_size > (uint64_t{1} << 32))
    fail("UART base " + hex(m.uart_base) + " must be 4-byte aligned and leave room for its registers");
  const bool has_device = m.halt == HaltKind::Finisher || m.halt == HaltKind::Store;
  const uint32_t halt_size = m.halt == HaltKind::Store ? kStoreHaltSize : kFinisherSize;
  if (has_device && (m.finisher_base % 4 || uint64_t{m.finisher_base} + halt_size > (uint64_t{1} << 32)))
    fail("halt device " + hex(m.finisher_base) + " must be 4-byte aligned and leave room for it");
  if (m.rom_size) {
    if (m.rom_base % kRamAlign || m.rom_size % kRamAlign)
      fail("ROM base and size must be multiples of 4096 (ROM " + hex(m.rom_base) + ", size " + hex(m.rom_size) + ")");
    if (uint64_t{m.rom_base} + m.rom_size >= (uint64_t{1} << 32) || m.rom_size > 0x7ffff000u)
      fail("ROM " + hex(m.rom_base) + "+" + hex(m.rom_size) + " must end below the top of the 32-bit address space");
  }
  struct Region {
    const char* name;
    uint64_t begin, end;
  };
  Region r[4] = {{"RAM", m.ram_base, uint64_t{m.ram_base} + m.ram_size},
                 {"UART", m.uart_base, uint64_t{m.uart_base} + uart_size}};
  size_t count = 2;
  if (has_device) r[count++] = {m.halt == HaltKind::Store ? "halt store" : "finisher", m.finisher_base, uint64_t{m.finisher_base} + halt_size};
  if (m.rom_size) r[count++] = {"ROM", m.rom_base, uint64_t{m.rom_base} + m.rom_size};
  for (size_t i = 0; i < count; ++i)
    for (size_t j = i + 1; j < count; ++j)
      if (r[i].begin < r[j].end && r[j].begin < r[i].end)
        fail(std::string(r[i].name) + " " + hex(r[i].begin) + ".." + hex(r[i].end) + " overlaps " + r[j].name +
             " " + hex(r[j].begin) + ".." + hex(r[j].end));
}

std::string describe(const MemoryMap& m) {
  std::string s = "RAM " + hex(m.ram_base) + ".." + hex(uint64_t{m.ram_base} + m.ram_size);
  if (m.rom_size) s += ", ROM " + hex(m.rom_base) + ".." + hex(uint64_t{m.rom_base} + m.rom_size);
  s += ", UART " + hex(m.uart_base);
  switch (m.halt) {
    case HaltKind::Finisher: s += ", finisher " + hex(m.finisher_base); break;
    case HaltKind::Store: s += ", halt store " + hex(m.finisher_base); break;
    case HaltKind::Ecall: s += ", halt by ecall"; break;
    case HaltKind::Loop: s += ", halt by jump-to-self"; break;
  }
  return s;
}

}  // namespace fwsim
