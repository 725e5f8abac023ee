#include "bus.hpp"

#include <new>

namespace fwsim {

Bus::Bus(const MemoryMap& map)
    : map_(map), ram_(static_cast<uint8_t*>(std::calloc(map.ram_size, 1))), ram_size_(map.ram_size) {
  if (!ram_) throw std::bad_alloc();
}

Bus::Result Bus::load(uint32_t addr, unsigned size, uint32_t& value, uint64_t now) {
  if (addr & (size - 1)) return Result::Misaligned;
  if (in_ram(addr, size)) {
    value = 0;
    std::memcpy(&value, ram_at(addr), size);  // little-endian host
    return Result::Ok;
  }
  if (uart_ && addr - map_.uart_base < kUartSize) {
    value = uart_->read(addr - map_.uart_base, now);
    return uart_->stalled() ? Result::Stop : Result::Ok;
  }
  if (addr - map_.finisher_base < kFinisherSize) {
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
  if (uart_ && addr - map_.uart_base < kUartSize) {
    uart_->write(addr - map_.uart_base, static_cast<uint8_t>(value), now);
    return uart_->io_error() ? Result::Stop : Result::Ok;
  }
  if (addr - map_.finisher_base < kFinisherSize) {
    if (addr == map_.finisher_base && finisher_.write(value)) {
      finished_ = true;
      return Result::Stop;
    }
    return Result::Ok;
  }
  return Result::Fault;
}

}  // namespace fwsim
