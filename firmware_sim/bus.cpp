#include "bus.hpp"

#include <new>

namespace fwsim {

Bus::Bus(const MemoryMap& map)
    : map_(map), ram_(static_cast<uint8_t*>(std::calloc(map.ram_size, 1))), ram_size_(map.ram_size),
      uart_size_(uart_region_size(map.uart)) {
  if (!ram_) throw std::bad_alloc();
  if (map.rom_size) {
    rom_ = static_cast<uint8_t*>(std::calloc(map.rom_size, 1));
    if (!rom_) throw std::bad_alloc();
  }
}

Bus::Result Bus::load(uint32_t addr, unsigned size, uint32_t& value, uint64_t now) {
  if (addr & (size - 1)) return Result::Misaligned;
  if (uint8_t* p = host_at(addr, size)) {
    value = 0;
    std::memcpy(&value, p, size);  // little-endian host
    return Result::Ok;
  }
  if (uart_ && addr - map_.uart_base < uart_size_) {
    value = uart_->read(addr - map_.uart_base, now);
    if (size < 4) value &= (1u << (8 * size)) - 1;
    return uart_->stalled() ? Result::Stop : Result::Ok;
  }
  if (map_.halt == HaltKind::Finisher && addr - map_.finisher_base < kFinisherSize) {
    value = 0;
    return Result::Ok;
  }
  if (map_.halt == HaltKind::Store && addr - map_.finisher_base < kStoreHaltSize) {
    value = 0;
    return Result::Ok;
  }
  return Result::Fault;
}

Bus::Result Bus::store(uint32_t addr, unsigned size, uint32_t value, uint64_t now) {
  if (addr & (size - 1)) return Result::Misaligned;
  if (in_ram(addr, size)) {
    std::memcpy(ram_at(addr), &value, size);
    return Result::Ok;
  }
  if (uart_ && addr - map_.uart_base < uart_size_) {
    uart_->write(addr - map_.uart_base, value, now);
    return uart_->io_error() ? Result::Stop : Result::Ok;
  }
  if (map_.halt == HaltKind::Finisher && addr - map_.finisher_base < kFinisherSize) {
    if (addr == map_.finisher_base && finisher_.write(value)) {
      finished_ = true;
      halt_code_ = finisher_.code();
      return Result::Stop;
    }
    return Result::Ok;
  }
  if (map_.halt == HaltKind::Store && addr - map_.finisher_base < kStoreHaltSize) {
    finished_ = true;
    halt_code_ = static_cast<int>(value);
    return Result::Stop;
  }
  return Result::Fault;  // includes stores to ROM
}

}  // namespace fwsim
