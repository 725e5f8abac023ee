#include "board_file.hpp"

#include <cerrno>
#include <cstdlib>
#include <map>
#include <sstream>
#include <stdexcept>

namespace fwsim {
namespace {

struct BadLine : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

uint32_t number(const std::string& key, const std::string& v) {
  if (v.empty() || v[0] == '-' || v[0] == '+') throw BadLine(key + " needs a number, got '" + v + "'");
  char* end = nullptr;
  errno = 0;
  // Base 0 would read a leading 0 as octal; the format has decimal and 0x only.
  const bool hex = v.size() > 2 && v[0] == '0' && (v[1] == 'x' || v[1] == 'X');
  const unsigned long long n = std::strtoull(v.c_str() + (hex ? 2 : 0), &end, hex ? 16 : 10);
  if (errno || *end || end == v.c_str() + (hex ? 2 : 0) || n > UINT32_MAX)
    throw BadLine(key + " needs a 32-bit number (decimal or 0x hex), got '" + v + "'");
  return static_cast<uint32_t>(n);
}

void parse_halt(const std::string& v, MemoryMap& map) {
  const size_t colon = v.find(':');
  const std::string kind = v.substr(0, colon);
  if (kind == "ecall" && colon == std::string::npos) map.halt = HaltKind::Ecall;
  else if (kind == "loop" && colon == std::string::npos) map.halt = HaltKind::Loop;
  else if ((kind == "finisher" || kind == "store") && colon != std::string::npos) {
    map.halt = kind == "finisher" ? HaltKind::Finisher : HaltKind::Store;
    map.finisher_base = number("halt address", trim(v.substr(colon + 1)));
  } else {
    throw BadLine("halt must be finisher:ADDR, ecall, store:ADDR or loop, got '" + v + "'");
  }
}

// OFFSET:VALUE pairs separated by spaces or commas.
void parse_uart_init(const std::string& v, std::vector<std::pair<uint32_t, uint32_t>>& out) {
  std::string item;
  std::istringstream in(v);
  while (std::getline(in, item, ',')) {
    std::istringstream words(item);
    std::string pair;
    while (words >> pair) {
      const size_t colon = pair.find(':');
      if (colon == std::string::npos) throw BadLine("uart_init needs OFFSET:VALUE pairs, got '" + pair + "'");
      const uint32_t offset = number("uart_init offset", pair.substr(0, colon));
      if (offset >= 0x100) throw BadLine("uart_init offset " + pair.substr(0, colon) + " is not below 0x100");
      out.emplace_back(offset, number("uart_init value", pair.substr(colon + 1)));
    }
  }
  if (out.empty()) throw BadLine("uart_init has no OFFSET:VALUE pair");
}

}  // namespace

Board parse_board_file(const std::string& text, const std::string& origin) {
  Board b;
  b.isa.zifencei = false;  // a board has Zifencei only when its file says so
  std::map<std::string, unsigned> seen;  // key -> line
  std::istringstream in(text);
  std::string line;
  unsigned lineno = 0;
  auto where = [&](unsigned l) { return origin + ":" + std::to_string(l) + ": "; };
  while (std::getline(in, line)) {
    ++lineno;
    if (const size_t hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    line = trim(line);
    if (line.empty()) continue;
    const size_t eq = line.find('=');
    if (eq == std::string::npos) throw std::runtime_error(where(lineno) + "expected 'key = value', got '" + line + "'");
    const std::string key = trim(line.substr(0, eq)), v = trim(line.substr(eq + 1));
    if (seen.count(key))
      throw std::runtime_error(where(lineno) + "'" + key + "' given twice (first on line " + std::to_string(seen[key]) + ")");
    try {
      if (v.empty()) throw BadLine("'" + key + "' has no value");
      MemoryMap& m = b.map;
      if (key == "name") b.name = v;
      else if (key == "mirrors") b.mirrors = v;
      else if (key == "isa") {
        if (!parse_isa(v, b.isa))
          throw BadLine("isa must be one of rv32i, rv32im, rv32imc, rv32imf, rv32imfc, rv32e, rv32em, rv32emc, got '" + v + "'");
      } else if (key == "zicsr") {
        if (v != "yes" && v != "no") throw BadLine("zicsr must be yes or no, got '" + v + "'");
        b.isa.zicsr = v == "yes";
      } else if (key == "zifencei") {
        if (v != "yes" && v != "no") throw BadLine("zifencei must be yes or no, got '" + v + "'");
        b.isa.zifencei = v == "yes";
      } else if (key == "clock_hz") {
        b.clock_hz = number(key, v);
        if (b.clock_hz == 0) throw BadLine("clock_hz must not be 0");
      } else if (key == "after_image") {
        // The firmware's business (serve or halt after an image); checked here too.
        if (v != "serve" && v != "halt") throw BadLine("after_image must be serve or halt, got '" + v + "'");
      } else if (key == "wait_polls") {
        number(key, v);  // the firmware's wait for a host; the simulator only checks it
      } else if (key == "reset") b.reset = number(key, v);
      else if (key == "ram_base") m.ram_base = number(key, v);
      else if (key == "ram_size") m.ram_size = number(key, v);
      else if (key == "rom_base") m.rom_base = number(key, v);
      else if (key == "rom_size") m.rom_size = number(key, v);
      else if (key == "uart") {
        if (v == "ns16550") m.uart.kind = UartKind::Ns16550;
        else if (v == "litex") m.uart.kind = UartKind::Litex;
        else if (v == "sifive") m.uart.kind = UartKind::Sifive;
        else if (v == "generic") m.uart.kind = UartKind::Generic;
        else throw BadLine("uart must be ns16550, litex, sifive or generic, got '" + v + "'");
      } else if (key == "uart_base") m.uart_base = number(key, v);
      else if (key == "uart_divisor") b.uart_divisor = number(key, v);
      else if (key == "uart_data") m.uart.data = number(key, v);
      else if (key == "uart_status") m.uart.status = number(key, v);
      else if (key == "uart_tx_ready") m.uart.tx_ready = number(key, v);
      else if (key == "uart_rx_ready") m.uart.rx_ready = number(key, v);
      else if (key == "uart_width") {
        m.uart.width = number(key, v);
        if (m.uart.width != 1 && m.uart.width != 4) throw BadLine("uart_width must be 1 or 4, got '" + v + "'");
      } else if (key == "uart_tx_idle") {
        m.uart.tx_idle = number(key, v);
      } else if (key == "uart_init") {
        parse_uart_init(v, b.uart_init);
      } else if (key == "uart_enable") {
        const size_t colon = v.find(':');
        if (colon == std::string::npos) throw BadLine("uart_enable needs OFFSET:MASK, got '" + v + "'");
        m.uart.enable_offset = number("uart_enable offset", trim(v.substr(0, colon)));
        m.uart.enable_mask = number("uart_enable mask", trim(v.substr(colon + 1)));
        if (!m.uart.enable_mask) throw BadLine("the uart_enable mask must not be 0");
        if (m.uart.enable_offset >= 0x100) throw BadLine("the uart_enable offset must be below 0x100");
      } else if (key == "halt") parse_halt(v, m);
      else throw BadLine("unknown key '" + key + "'");
    } catch (const BadLine& e) {
      throw std::runtime_error(where(lineno) + e.what());
    }
    seen[key] = lineno;
  }
  const unsigned end = lineno ? lineno : 1;
  for (const char* k : {"name", "isa", "reset", "ram_base", "ram_size", "uart", "uart_base", "halt"})
    if (!seen.count(k)) throw std::runtime_error(where(end) + "missing required key '" + k + "'");
  const bool generic = b.map.uart.kind == UartKind::Generic;
  for (const char* k : {"uart_data", "uart_status", "uart_tx_ready", "uart_rx_ready", "uart_width", "uart_tx_idle",
                        "uart_init", "uart_enable"}) {
    const std::string key = k;
    const bool optional = key == "uart_width" || key == "uart_tx_idle" || key == "uart_init" || key == "uart_enable";
    if (generic && !optional && !seen.count(k))
      throw std::runtime_error(where(end) + "uart = generic needs '" + k + "'");
    if (!generic && seen.count(k))
      throw std::runtime_error(where(seen[k]) + "'" + k + "' applies only to uart = generic");
  }
  if (generic) {
    const UartLayout& u = b.map.uart;
    if (u.data == u.status) throw std::runtime_error(where(seen["uart_status"]) + "uart_data and uart_status must differ");
    if (u.data % u.width || u.status % u.width)
      throw std::runtime_error(where(seen["uart_data"]) + "uart_data and uart_status must be multiples of uart_width");
    if (!u.tx_ready || !u.rx_ready)
      throw std::runtime_error(where(seen[u.tx_ready ? "uart_rx_ready" : "uart_tx_ready"]) + "a status mask must not be 0");
    if (seen.count("uart_tx_idle") && !u.tx_idle)
      throw std::runtime_error(where(seen["uart_tx_idle"]) + "a status mask must not be 0");
    for (const auto& [offset, value] : b.uart_init)
      if (offset % u.width)
        throw std::runtime_error(where(seen["uart_init"]) + "uart_init offsets must be multiples of uart_width");
  }
  if (seen.count("rom_base") != seen.count("rom_size"))
    throw std::runtime_error(where(end) + "rom_base and rom_size go together");
  if (seen.count("rom_size") && b.map.rom_size == 0)
    throw std::runtime_error(where(seen["rom_size"]) + "rom_size must not be 0");
  try {
    check_memory_map(b.map);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(origin + ": " + e.what());
  }
  const uint32_t code_base = b.map.rom_size ? b.map.rom_base : b.map.ram_base;
  const uint32_t code_size = b.map.rom_size ? b.map.rom_size : b.map.ram_size;
  if (b.reset - code_base >= code_size || (b.reset & 3))
    throw std::runtime_error(where(seen["reset"]) + "reset address must be a word in " + (b.map.rom_size ? "ROM" : "RAM"));
  return b;
}

}  // namespace fwsim
