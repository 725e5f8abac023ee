#include "bus.hpp"

#include <new>

namespace fwsim {

Bus::Bus(uint32_t ram_size) : ram_(static_cast<uint8_t*>(std::calloc(ram_size, 1))), ram_size_(ram_size) {
  if (!ram_) throw std::bad_alloc();
}

Bus::Result Bus::load(uint32_t addr, unsigned size, uint32_t& value, uint64_t now) {
  if (addr & (size - 1)) return Result::Misaligned;
  if (in_ram(addr, size)) {
    value = 0;
    std::memcpy(&value, ram_ + (addr - kRamBase), size);  // little-endian host
    return Result::Ok;
  }
  if (uart_ && addr - MINRT_UART_BASE < MINRT_UART_SIZE) {
    value = uart_->read(addr - MINRT_UART_BASE, now);
    return uart_->stalled() ? Result::Stop : Result::Ok;
  }
  if (addr - MINRT_FINISHER_BASE < MINRT_FINISHER_SIZE) {
    value = 0;
    return Result::Ok;
  }
  return Result::Fault;
}

Bus::Result Bus::store(uint32_t addr, unsigned size, uint32_t value, uint64_t now) {
  if (addr & (size - 1)) return Result::Misaligned;
  if (in_ram(addr, size)) {
    std::memcpy(ram_ + (addr - kRamBase), &value, size);
    return Result::Ok;
  }
  if (uart_ && addr - MINRT_UART_BASE < MINRT_UART_SIZE) {
    uart_->write(addr - MINRT_UART_BASE, static_cast<uint8_t>(value), now);
    return uart_->io_error() ? Result::Stop : Result::Ok;
  }
  if (addr - MINRT_FINISHER_BASE < MINRT_FINISHER_SIZE) {
    if (addr == MINRT_FINISHER_BASE && finisher_.write(value)) {
      finished_ = true;
      return Result::Stop;
    }
    return Result::Ok;
  }
  return Result::Fault;
}

}  // namespace fwsim
